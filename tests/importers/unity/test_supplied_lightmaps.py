"""Supplied baked lightmaps (issue 34; importers/unity/lightmaps.py): a Unity material's
``lightmap`` is ``unity_Lightmap``, its ``scale_offset`` ``unity_LightmapST``, and ``DecodeLightmap``
decodes its texels as Unity does in linear colour space (Unity manual, "Lightmaps: Technical
information"). Checked per pixel against a float64 decode of the texel each pixel reads, on a
plane seen by the corpus camera of test_glslprogram.py, in both languages, for each encoding.

The expectation is independent of the harness: each pixel centre's ray meets the plane y = 0 at
(x, z), whose UV (the plane primitive's only UV set: TEXCOORD0 and TEXCOORD1) is
(x / size + 1/2, 1/2 - z / size); the lightmap coordinate is uv * scale + offset. The lightmap is
made of 8 x 8-texel blocks of one texel value each, and only pixels whose coordinate lies 2 texels
or more inside a block, seen at under 1.5 texels per pixel, are compared: there bilinear and
trilinear filtering (mip levels 0 and 1, whose blocks are 8 and 4 texels) read that one value
whatever their weights, so the expectation is the decode of the block's texel alone.
"""

from __future__ import annotations

import textwrap
from pathlib import Path

import numpy as np
import pytest

from pbrlab.checking import unity_corpus as corpus
from pbrlab.foundation import images
from pbrlab.foundation.errors import PbrlabError
from pbrlab.importers.loader import parse_scene
from pbrlab.maths.reference.color import srgb_to_linear
from pbrlab.render.renderer import render_scene

from unity_inputs import pixel_rays

pytestmark = pytest.mark.filterwarnings("ignore::pbrlab.importers.unity.UnityShaderNote")

CAMERA = {"position": [0.0, 1.3, 1.5], "target": [0.0, 0.0, 0.0], "fov_y_deg": 40, "size": [64, 64]}
SIZE = 1.6
SCALE_OFFSET = (0.8, 0.7, 0.1, 0.2)
N, BLOCK = 32, 8
INSIDE_TEXELS = 2.0       # a compared coordinate lies this far inside its block (texels of level 0)
MOST_TEXELS_PER_PIXEL = 1.5
# Unity's manual ("Lightmaps: Technical information"), linear colour space: RGBM spans 5^2.2, M
# taken to the power 2.2; dLDR is times 2^2.2; both stored in gamma space (sampled as sRGB).
RGBM_RANGE, GAMMA, DLDR_SCALE = 5.0 ** 2.2, 2.2, 2.0 ** 2.2
# The texel each pixel reads: an sRGB-sampled channel is the texture unit's decode of its byte b,
# which need not be the formula's value exactly; Direct3D 10's rule (which llvmpipe's polynomial
# decode keeps, Mesa gallivm lp_bld_format_srgb.c) is that it re-encodes to within half a step of
# b, so it lies in [decode((b - 1/2) / 255), decode((b + 1/2) / 255)] (measured on llvmpipe: up to
# 0.43 % off the formula at b = 34). The expectation is that interval through Unity's decode.
# Relative slack beside it, from GLSL's precision rules (GLSL 4.60 4.7.1) for the RGBM decode
# x * pow(a, 2.2) * rgb, the worst of the three encodings: pow is exp2(2.2 log2 a); log2 within
# 2^-21 absolute for a in [0.5, 2] and 3 ulp outside (a >= 0.2: |log2 a| <= 2.33, 3 ulp = 7.2e-7),
# times 2.2: 1.6e-6 in the exponent, 1.1e-6 relative after exp2 (ln 2 x); exp2's own 3 + 2|x| ulp
# (|x| <= 5.1: 13 ulp, 7.7e-7); three products, one rounding each (1.8e-7): 2.1e-6, slack 3e-6.
# A full-HDR texel is a float32 read as it is (its interval a point).
BOUND = 3e-6


def _shader(tmp_path, body="return float4(DecodeLightmap(UNITY_SAMPLE_TEX2D(unity_Lightmap, i.lm)), 1);",
            pragmas="", name="lm", lightmap_uv="o.lm = v.texcoord1.xy * unity_LightmapST.xy + unity_LightmapST.zw;"):
    text = f"""
    Shader "t/{name}" {{
        SubShader {{ Pass {{
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            {pragmas}
            #include "UnityCG.cginc"
            struct v2f {{ float4 pos : SV_POSITION; float2 lm : TEXCOORD0; }};
            v2f vert (appdata_full v) {{
                v2f o;
                o.pos = UnityObjectToClipPos(v.vertex);
                {lightmap_uv}
                return o;
            }}
            float4 frag (v2f i) : SV_Target {{
                {body}
            }}
            ENDCG
        }} }}
    }}
    """
    path = tmp_path / f"{name}.shader"
    path.write_text(textwrap.dedent(text))
    return path


def _lightmap(tmp_path, encoding):
    """(file, texels per block: RGBA as stored, N/BLOCK x N/BLOCK, row 0 the image's top)."""
    rng = np.random.default_rng(11)
    blocks = N // BLOCK
    if encoding == "full_hdr":
        texels = rng.uniform(0.0, 4.0, (blocks, blocks, 4)).astype(np.float32)
        texels[..., 3] = 1.0
        path = tmp_path / "lightmap.exr"
        images.write_exr(path, np.repeat(np.repeat(texels[..., :3], BLOCK, 0), BLOCK, 1))
        return path, texels.astype(np.float64)
    texels = rng.integers(0, 256, (blocks, blocks, 4)).astype(np.uint8)
    texels[..., 3] = rng.integers(51, 256, (blocks, blocks))  # M >= 0.2 (the bound's range of a)
    path = tmp_path / f"lightmap_{encoding}.png"
    images.write_png(path, np.repeat(np.repeat(texels, BLOCK, 0), BLOCK, 1))
    return path, texels.astype(np.float64) / 255.0


def decoded(texels, encoding, gamma_space=False):
    """(low, high): Unity's DecodeLightmap of the stored texels, float64, over the interval of
    values the texture unit may read for each byte (BOUND's comment); linear space, or with
    ``gamma_space`` the control: decoded as gamma space would (5 a rgb, 2 rgb; no sRGB read)."""
    if encoding == "full_hdr":
        return texels[..., :3], texels[..., :3]
    rgb, a = texels[..., :3], texels[..., 3:]
    if gamma_space:
        value = 5.0 * a * rgb if encoding == "rgbm" else 2.0 * rgb
        return value, value
    scale = RGBM_RANGE * a ** GAMMA if encoding == "rgbm" else DLDR_SCALE
    half_step = 0.5 / 255.0
    low = srgb_to_linear(np.clip(rgb - half_step, 0.0, 1.0))
    high = srgb_to_linear(np.clip(rgb + half_step, 0.0, 1.0))
    return scale * low, scale * high


def _uv(size, offset=(0.0, 0.0)):
    eye, d = pixel_rays(CAMERA, size, offset)
    hit = eye + d * (-eye[1] / d[..., 1])[..., None]
    return np.stack([hit[..., 0] / SIZE + 0.5, 0.5 - hit[..., 2] / SIZE], -1)


def expected(size, texels, encoding, scale_offset=SCALE_OFFSET, gamma_space=False):
    """((low, high) per pixel, compared): the decode of the block each pixel centre reads."""
    uv = _uv(size)
    inside = ((uv >= 0) & (uv <= 1)).all(-1)
    st = np.array(scale_offset)
    texel = (uv * st[:2] + st[2:]) * N  # level-0 texel coordinates, v up (GL rows bottom-up)
    within = texel % BLOCK
    deep = ((within >= INSIDE_TEXELS) & (within <= BLOCK - INSIDE_TEXELS)).all(-1)
    gradients = [np.abs((_uv(size, d) - uv) * st[:2] * N).max(-1) for d in ((1, 0), (0, 1), (-1, 0), (0, -1))]
    fine = np.max(gradients, axis=0) <= MOST_TEXELS_PER_PIXEL
    blocks = N // BLOCK
    column = np.clip(np.floor(texel[..., 0] / BLOCK), 0, blocks - 1).astype(int)
    row_up = np.clip(np.floor(texel[..., 1] / BLOCK), 0, blocks - 1).astype(int)
    low, high = (d[blocks - 1 - row_up, column] for d in decoded(texels, encoding, gamma_space))  # rows top-down
    return (low, high), inside & deep & fine


def _render(tmp_path, shader, language, lightmap=None, keywords=None):
    data = corpus.scene_for(shader)
    data["camera"] = CAMERA
    data["objects"] = [{"mesh": {"primitive": "plane", "size": SIZE}, "material": "m"}]
    data["materials"]["m"].pop("lightmap", None)
    if lightmap is not None:
        data["materials"]["m"]["lightmap"] = lightmap
    if keywords:
        data["materials"]["m"]["keywords"] = keywords
    return render_scene(parse_scene(data, "t", tmp_path), language=language).linear.astype(np.float64)


def over_bound(image, expectation, compared) -> float:
    """The fraction of compared pixels with a channel outside [low (1 - BOUND), high (1 + BOUND)]."""
    low, high = expectation
    rgb = image[..., :3]
    outside = ((rgb < low * (1 - BOUND)) | (rgb > high * (1 + BOUND))).any(-1)
    return float(outside[compared].mean())


@pytest.mark.parametrize("encoding", ["rgbm", "dldr", "full_hdr"])
@pytest.mark.parametrize("language", ["glsl", "hlsl"])
def test_a_supplied_lightmap_decodes_per_pixel_as_unity(tmp_path, language, encoding):
    path, texels = _lightmap(tmp_path, encoding)
    lightmap = {"path": str(path), "encoding": encoding, "scale_offset": list(SCALE_OFFSET)}
    image = _render(tmp_path, _shader(tmp_path), language, lightmap)
    expectation, compared = expected(image.shape[:2], texels, encoding)
    assert compared.mean() > 0.05  # pixels enough to compare: every block's centre is seen
    assert over_bound(image, expectation, compared) == 0.0


@pytest.mark.parametrize("encoding", ["rgbm", "dldr"])
def test_controls_fail(tmp_path, encoding):
    """The float64 expectation without unity_LightmapST, or decoded as gamma space would (no sRGB
    sampling, 5 a rgb / 2 rgb), fails on the same image."""
    path, texels = _lightmap(tmp_path, encoding)
    lightmap = {"path": str(path), "encoding": encoding, "scale_offset": list(SCALE_OFFSET)}
    image = _render(tmp_path, _shader(tmp_path), "glsl", lightmap)
    expectation, compared = expected(image.shape[:2], texels, encoding, scale_offset=(1, 1, 0, 0))
    assert over_bound(image, expectation, compared) > 0.0  # measured: 49 % of the compared pixels
    expectation, compared = expected(image.shape[:2], texels, encoding, gamma_space=True)
    assert over_bound(image, expectation, compared) > 0.0


@pytest.mark.parametrize("language", ["glsl", "hlsl"])
def test_a_lightmap_read_without_one_is_refused_at_its_line(tmp_path, language):
    shader = _shader(tmp_path)
    with pytest.raises(PbrlabError, match=r"lm\.shader:13: uses unity_LightmapST, part of baked lightmaps: the "
                                          r"object's lightmap, which the material does not supply"):
        _render(tmp_path, shader, language)


def test_lightmap_on_is_set_where_a_pass_declares_it(tmp_path):
    """multi_compile_fwdbase declares LIGHTMAP_ON: with a lightmap its branch draws the decode
    (as the first test's image), without one the other branch (magenta, and nothing reads the
    lightmap, so nothing is refused)."""
    path, texels = _lightmap(tmp_path, "rgbm")
    lightmap = {"path": str(path), "encoding": "rgbm", "scale_offset": list(SCALE_OFFSET)}
    body = ("#ifdef LIGHTMAP_ON\n return float4(DecodeLightmap(UNITY_SAMPLE_TEX2D(unity_Lightmap, i.lm)), 1);\n"
            "#else\n return float4(1, 0, 1, 1);\n#endif")
    uv = ("o.lm = 0;\n#ifdef LIGHTMAP_ON\n o.lm = v.texcoord1.xy * unity_LightmapST.xy + unity_LightmapST.zw;\n"
          "#endif")
    shader = _shader(tmp_path, body, "#pragma multi_compile_fwdbase", name="fwdbase", lightmap_uv=uv)
    lit = _render(tmp_path, shader, "glsl", lightmap)
    expectation, compared = expected(lit.shape[:2], texels, "rgbm")
    assert over_bound(lit, expectation, compared) == 0.0
    plain = _render(tmp_path, shader, "glsl")
    covered = plain[..., 3] > 0
    assert covered.mean() > 0.3 and np.array_equal(plain[covered][:, :3], np.broadcast_to([1.0, 0.0, 1.0],
                                                                                         (int(covered.sum()), 3)))


def test_a_lightmapped_object_draws_the_vertexlm_pass(tmp_path):
    """Unity's Mobile/Unlit (Supports Lightmap) draws its VertexLM program for a lightmapped object
    (texture x DecodeLightmap of the lightmap at TEXCOORD1 x unity_LightmapST; its texture white)
    instead of its Vertex pass (the texture alone: white): the first test's expectation holds."""
    unlit = (Path(__file__).resolve().parents[3] / "corpus" / "unity" / "builtin-2019.4" / "DefaultResourcesExtra"
             / "Mobile" / "Mobile-Lightmap-Unlit.shader")
    path, texels = _lightmap(tmp_path, "rgbm")
    lightmap = {"path": str(path), "encoding": "rgbm", "scale_offset": list(SCALE_OFFSET)}
    image = _render(tmp_path, unlit, "hlsl", lightmap)
    expectation, compared = expected(image.shape[:2], texels, "rgbm")
    assert over_bound(image, expectation, compared) == 0.0
    unlit_white = _render(tmp_path, unlit, "hlsl")
    covered = unlit_white[..., 3] > 0
    assert np.allclose(unlit_white[covered][:, :3], 1.0)  # the control: the Vertex pass, no lightmap


def test_a_surface_shader_with_a_lightmap_is_refused(tmp_path):
    path, _ = _lightmap(tmp_path, "rgbm")
    surface = tmp_path / "surf.shader"
    surface.write_text(textwrap.dedent("""
        Shader "t/surf" { SubShader { CGPROGRAM
        #pragma surface surf Lambert
        struct Input { float2 uv_MainTex; };
        void surf (Input IN, inout SurfaceOutput o) { o.Albedo = 0.5; }
        ENDCG } }
    """))
    with pytest.raises(PbrlabError, match="a surface shader with a lightmap: pbrlab's surface programs do not draw"):
        _render(tmp_path, surface, "glsl", {"path": str(path)})


def test_a_surface_program_reading_the_lightmap_without_one_is_refused(tmp_path):
    """A surface program's own read of unity_LightmapST (a vertex: function) is refused at its
    line too: with no lightmap it would read zeros."""
    surface = tmp_path / "surflm.shader"
    surface.write_text(textwrap.dedent("""
        Shader "t/surflm" { SubShader { CGPROGRAM
        #pragma surface surf Lambert vertex:vert
        struct Input { float2 lm; };
        void vert (inout appdata_full v, out Input o) {
            UNITY_INITIALIZE_OUTPUT(Input, o); o.lm = v.texcoord1.xy * unity_LightmapST.xy; }
        void surf (Input IN, inout SurfaceOutput o) { o.Albedo = float3(IN.lm, 0); }
        ENDCG } }
    """))
    with pytest.raises(PbrlabError, match=r"surflm\.shader:6: uses unity_LightmapST, part of baked lightmaps"):
        _render(tmp_path, surface, "glsl")
