"""Supplied realtime GI (Enlighten) lightmaps (issue 34; importers/unity/dynamic_lightmaps.py): a
Unity material's ``dynamic_lightmap`` is ``unity_DynamicLightmap``, its ``scale_offset``
``unity_DynamicLightmapST``, TEXCOORD2 the realtime lightmap UVs (the mesh's lightmap UVs, as
Unity falls back to them without a Mesh.uv3), and ``DecodeRealtimeLightmap`` decodes its texels as
Unity does for its RGB9E5 output (pow((x a) rgb, y) with (x, y) = (1, 1), alpha 1: the texel's RGB).
Checked per pixel against float64 expectations on the plane and camera of
test_supplied_lightmaps.py (its ``expected`` reads the block each pixel centre meets), in both
languages; and the two GIDebug shaders that read the realtime lightmap's UVs.
"""

from __future__ import annotations

import sys
import textwrap
from pathlib import Path

import numpy as np
import pytest

from pbrlab.checking import unity_corpus as corpus
from pbrlab.foundation import images
from pbrlab.foundation.errors import PbrlabError
from pbrlab.importers.loader import parse_scene
from pbrlab.render.renderer import render_scene

sys.path.insert(0, str(Path(__file__).resolve().parent))
from unity_inputs import pixel_rays  # noqa: E402
from test_supplied_lightmaps import BLOCK, CAMERA, N, SIZE, expected, _shader as baked_shader  # noqa: E402

pytestmark = pytest.mark.filterwarnings("ignore::pbrlab.importers.unity.UnityShaderNote")

GIDEBUG = (Path(__file__).resolve().parents[3] / "corpus" / "unity" / "builtin-2019.4" / "DefaultResourcesExtra"
           / "GIDebug")
SCALE_OFFSET = (0.8, 0.7, 0.1, 0.2)   # unity_DynamicLightmapST
BAKED_SCALE_OFFSET = (0.5, 0.4, 0.3, 0.05)  # unity_LightmapST where a shader reads both (a different chart)
LOWEST, HIGHEST = 0.05, 4.0           # the texels' range (the bound's range of values)
# Relative slack of DecodeRealtimeLightmap's pow((1 * a) * rgb, 1) on float32 texels, from GLSL's
# precision rules (GLSL 4.60 4.7.1): pow is exp2(y log2 v); for v in [0.05, 4] |log2 v| <= 4.33,
# log2 within 3 ulp there (2^-21 absolute inside [0.5, 2]): 3 x 2^-21 = 1.4e-6 absolute in the
# exponent, 1.0e-6 relative after exp2 (ln 2 x); exp2's own 3 + 2|x| ulp (11.7 ulp, 7.0e-7); the two
# products one rounding each (1.2e-7): 1.8e-6 in all, slack 3e-6 (as the baked lightmap's test).
# The texels themselves are float32 read unfiltered within a block (an exact read).
BOUND = 3e-6


DECODE = "return float4(DecodeRealtimeLightmap(UNITY_SAMPLE_TEX2D(unity_DynamicLightmap, i.lm)), 1);"


def _shader(tmp_path, body=DECODE, pragmas="", name="dyn",
            uv="o.lm = v.texcoord2.xy * unity_DynamicLightmapST.xy + unity_DynamicLightmapST.zw;"):
    """The baked test's pass (test_supplied_lightmaps._shader) with the realtime lightmap's UVs."""
    return baked_shader(tmp_path, body, pragmas, name, uv)


def _blocks(tmp_path, name="realtime.exr", seed=23):
    """(file, texels per block: RGBA, alpha 1, N/BLOCK x N/BLOCK, row 0 the image's top): float RGB."""
    rng = np.random.default_rng(seed)
    blocks = N // BLOCK
    texels = rng.uniform(LOWEST, HIGHEST, (blocks, blocks, 4)).astype(np.float32)
    texels[..., 3] = 1.0
    path = tmp_path / name
    images.write_exr(path, np.repeat(np.repeat(texels[..., :3], BLOCK, 0), BLOCK, 1))
    return path, texels.astype(np.float64)


def _render(tmp_path, shader, language, dynamic=None, properties=None, lightmap=None, keywords=None):
    data = corpus.scene_for(shader)
    data["camera"] = CAMERA
    data["objects"] = [{"mesh": {"primitive": "plane", "size": SIZE}, "material": "m"}]
    material = data["materials"]["m"]
    material.pop("dynamic_lightmap", None)
    material.pop("lightmap", None)
    for key, value in (("dynamic_lightmap", dynamic), ("properties", properties), ("lightmap", lightmap),
                       ("keywords", keywords)):
        if value is not None:
            material[key] = value
    return render_scene(parse_scene(data, "t", tmp_path), language=language).linear.astype(np.float64)


def over_bound(image, expectation, compared, bound=BOUND) -> float:
    """The fraction of compared pixels with a channel outside [low (1 - bound), high (1 + bound)]."""
    low, high = expectation
    rgb = image[..., :3]
    outside = ((rgb < low * (1 - bound)) | (rgb > high * (1 + bound))).any(-1)
    return float(outside[compared].mean())


def _dynamic(path, scale_offset=SCALE_OFFSET):
    return {"path": str(path), "scale_offset": list(scale_offset)}


@pytest.mark.parametrize("language", ["glsl", "hlsl"])
def test_a_supplied_realtime_lightmap_decodes_per_pixel_as_unity(tmp_path, language):
    path, texels = _blocks(tmp_path)
    image = _render(tmp_path, _shader(tmp_path), language, _dynamic(path))
    expectation, compared = expected(image.shape[:2], texels, "full_hdr", SCALE_OFFSET)
    assert compared.mean() > 0.05  # pixels enough to compare: every block's centre is seen
    assert over_bound(image, expectation, compared) == 0.0


def test_controls_fail(tmp_path):
    """The float64 expectation without unity_DynamicLightmapST, or with a wrong decode (y = 2.2:
    pow(rgb, 2.2), a gamma-to-linear read of an encoded texture), fails on the same image."""
    path, texels = _blocks(tmp_path)
    image = _render(tmp_path, _shader(tmp_path), "glsl", _dynamic(path))
    expectation, compared = expected(image.shape[:2], texels, "full_hdr", (1, 1, 0, 0))
    assert over_bound(image, expectation, compared) > 0.3
    wrong = texels.copy()
    wrong[..., :3] **= 2.2
    expectation, compared = expected(image.shape[:2], wrong, "full_hdr", SCALE_OFFSET)
    assert over_bound(image, expectation, compared) > 0.3


@pytest.mark.parametrize("language", ["glsl", "hlsl"])
def test_a_realtime_lightmap_read_without_one_is_refused_at_its_line(tmp_path, language):
    with pytest.raises(PbrlabError, match=r"dyn\.shader:13: uses unity_DynamicLightmapST, part of realtime GI "
                                          r"lightmaps: the object's realtime \(Enlighten\) lightmap, which the "
                                          r"material does not supply"):
        _render(tmp_path, _shader(tmp_path), language)


def test_a_realtime_lightmap_must_be_an_hdr_image(tmp_path):
    png = tmp_path / "realtime.png"
    images.write_png(png, np.zeros((4, 4, 4), np.uint8))
    with pytest.raises(PbrlabError, match=r"realtime\.png: a realtime GI lightmap is an HDR image"):
        _render(tmp_path, _shader(tmp_path), "glsl", _dynamic(png))


def test_dynamiclightmap_on_is_set_where_a_pass_declares_it_and_texcoord2_is_0_without_one(tmp_path):
    """multi_compile_fwdbase declares DYNAMICLIGHTMAP_ON: with a realtime lightmap its branch draws
    the decode (as the first test's image); without one the other branch, which shows TEXCOORD2
    itself: 0 (no mesh here has a Mesh.uv3), so black where the plane is drawn."""
    path, texels = _blocks(tmp_path)
    body = "#ifdef DYNAMICLIGHTMAP_ON\n " + DECODE + "\n#else\n return float4(i.lm, 0, 1);\n#endif"
    uv = ("o.lm = v.texcoord2.xy;\n#ifdef DYNAMICLIGHTMAP_ON\n o.lm = v.texcoord2.xy * unity_DynamicLightmapST.xy "
          "+ unity_DynamicLightmapST.zw;\n#endif")
    shader = _shader(tmp_path, body, "#pragma multi_compile_fwdbase", name="fwdbase", uv=uv)
    lit = _render(tmp_path, shader, "glsl", _dynamic(path))
    expectation, compared = expected(lit.shape[:2], texels, "full_hdr", SCALE_OFFSET)
    assert over_bound(lit, expectation, compared) == 0.0
    plain = _render(tmp_path, shader, "glsl")
    covered = plain[..., 3] > 0
    assert covered.mean() > 0.3 and np.array_equal(plain[covered][:, :3], np.zeros((int(covered.sum()), 3)))


def test_a_surface_shader_with_a_realtime_lightmap_is_refused(tmp_path):
    path, _ = _blocks(tmp_path)
    surface = tmp_path / "surf.shader"
    surface.write_text(textwrap.dedent("""
        Shader "t/surf" { SubShader { CGPROGRAM
        #pragma surface surf Lambert
        struct Input { float2 uv_MainTex; };
        void surf (Input IN, inout SurfaceOutput o) { o.Albedo = 0.5; }
        ENDCG } }
    """))
    with pytest.raises(PbrlabError, match="a surface shader with a realtime GI lightmap"):
        _render(tmp_path, surface, "glsl", _dynamic(path))


# GIDebug/TextureUV (_StaticUV1 = 0, no Property: its default branch): _MainTex at TEXCOORD2 x
# unity_DynamicLightmapST, shown as it is (_Decode_HDR.x = 0: no decode; _ConvertToLinearSpace 0;
# exp2(_Exposure = 0) = 1). With _MainTex the float block image (read linear) the expectation is
# the block each pixel centre's realtime lightmap coordinate meets: exact up to float32 reads
# (the products uv * s + o are the only arithmetic: 1e-6 relative slack is 8 ulp of it).
TEXTURE_UV_BOUND = 1e-6


@pytest.mark.parametrize("language", ["glsl", "hlsl"])
def test_gidebug_texture_uv_shows_its_texture_at_the_realtime_lightmap_uvs(tmp_path, language):
    path, texels = _blocks(tmp_path)
    shader = GIDEBUG / "TextureUV.shader"
    baked = {"path": str(path), "encoding": "full_hdr", "scale_offset": list(BAKED_SCALE_OFFSET)}
    properties = {"_MainTex": {"path": str(path), "srgb": False}}
    image = _render(tmp_path, shader, language, _dynamic(path), properties, baked)
    expectation, compared = expected(image.shape[:2], texels, "full_hdr", SCALE_OFFSET)
    assert compared.mean() > 0.05
    assert over_bound(image, expectation, compared, TEXTURE_UV_BOUND) == 0.0
    if language == "glsl":  # the control: the baked lightmap's chart (the _StaticUV1 branch) fails
        expectation, compared = expected(image.shape[:2], texels, "full_hdr", BAKED_SCALE_OFFSET)
        assert over_bound(image, expectation, compared, TEXTURE_UV_BOUND) > 0.3


def _layout_coverage(size, scale_offset):
    """(inside, certain): whether each pixel centre's ray meets the plane z = 0 inside the rectangle
    [o, o + s] (the plane primitive's UV square [0, 1]^2 placed at uv * s + o, z = 0, by
    UV1sAsPositions), and whether its four neighbours' centres agree (the pixel is off the edge)."""
    def inside(offset=(0.0, 0.0)):
        eye, d = pixel_rays(CAMERA, size, offset)
        hit = eye + d * (-eye[2] / d[..., 2])[..., None]
        s, o = np.array(scale_offset[:2]), np.array(scale_offset[2:])
        return ((hit[..., :2] >= o) & (hit[..., :2] <= o + s)).all(-1)
    centre = inside()
    certain = np.all([inside(d) == centre for d in ((1, 0), (0, 1), (-1, 0), (0, -1))], axis=0)
    return centre, certain


@pytest.mark.parametrize("language", ["glsl", "hlsl"])
def test_gidebug_uv1s_as_positions_draws_the_realtime_uv_layout(tmp_path, language):
    """UV1sAsPositions draws each vertex at (TEXCOORD2 x s + o, 0) in object space (ZTest Always,
    Cull Off), in _Color (white by its Property): the plane's UV square is the rectangle [o, o + s]
    of the plane z = 0. Every pixel off the rectangle's edge is white inside it and empty outside."""
    path, _ = _blocks(tmp_path)
    shader = GIDEBUG / "UV1sAsPositions.shader"
    baked = {"path": str(path), "encoding": "full_hdr", "scale_offset": list(BAKED_SCALE_OFFSET)}
    image = _render(tmp_path, shader, language, _dynamic(path), lightmap=baked)
    inside, certain = _layout_coverage(image.shape[:2], SCALE_OFFSET)
    assert (inside & certain).mean() > 0.1 and (~inside & certain).mean() > 0.1
    drawn = image[..., 3] > 0
    assert np.array_equal(drawn[certain], inside[certain])
    assert np.array_equal(image[inside & certain][:, :3], np.ones((int((inside & certain).sum()), 3)))
    if language == "glsl":  # the control: the baked lightmap's chart (the _StaticUV1 branch) fails
        other, sure = _layout_coverage(image.shape[:2], BAKED_SCALE_OFFSET)
        assert not np.array_equal(drawn[sure & certain], other[sure & certain])
