"""Unity names issue 34 found missing (the "unity-names" round): UnityCG.cginc's packing helpers
(EncodeDepthNormal and its parts, UnpackHeightmap, SAMPLE_RAW_DEPTH_TEXTURE,
UnityObjectToClipPosODS: harness/pbrlab/importers/unity/cginc/UnityCGPacking.cginc) against
float64 transcriptions written from the documented encodings, and the front end's forms of Cg
that glslang and GLSL did not take (cg_spellings.py), globals only one of Unity's engine
subsystems sets (engine_inputs.py) and a SubShader whose every pass is skipped.

Readback: the corpus scene (pbrlab.checking.unity_corpus.scene_for: a UV sphere, rgba32f target),
its ``linear`` image, whose colour is what the fragment returned (a pass's alpha is the target's
coverage, so each check reads three channels at a time), on the pixels the sphere covers whole.
"""

from __future__ import annotations

import textwrap
from pathlib import Path

import numpy as np
import pytest

from pbrlab.checking import unity_corpus as corpus
from pbrlab.foundation.errors import PbrlabError
from pbrlab.importers.loader import parse_scene
from pbrlab.importers.unity import cg_spellings, engine_inputs
from pbrlab.render.renderer import render_scene

LANGUAGES = ("glsl", "hlsl")
ROOT = Path(__file__).resolve().parents[3] / "corpus" / "unity" / "builtin-2019.4" / "DefaultResourcesExtra"

PASS = """
Shader "t/{name}" {{
    Properties {{
{properties}
    }}
    SubShader {{ Pass {{
        CGPROGRAM
        #pragma vertex vert
        #pragma fragment frag
        #include "UnityCG.cginc"
{globals}
        struct v2f {{ float4 pos : SV_POSITION; float2 uv : TEXCOORD0; }};
        v2f vert(appdata_base v) {{ v2f o; o.pos = UnityObjectToClipPos(v.vertex); o.uv = v.texcoord.xy; return o; }}
        float4 frag(v2f i) : SV_Target {{
{body}
        }}
        ENDCG
    }} }}
}}
"""


def _shader(tmp_path, name, body, properties="", globals_=""):
    path = tmp_path / f"{name}.shader"
    path.write_text(textwrap.dedent(PASS.format(name=name, properties=properties, globals=globals_, body=body)))
    return path


def _render(tmp_path, shader, language, properties=None):
    data = corpus.scene_for(shader)
    if properties:
        data["materials"]["m"]["properties"] = properties
    return render_scene(parse_scene(data, "t", tmp_path), language=language).linear


def _covered(image):
    """The pixels the sphere covers whole (edge pixels mix the background in)."""
    covered = image[..., 3] == 1.0
    assert covered.mean() > 0.3
    return covered


# --- float64 transcriptions of the documented encodings (Unity manual, "Camera's depth texture":
# _CameraDepthNormalsTexture holds the view-space normal and the [0, 1] linear depth in 8-bit
# pairs; the normal by a stereographic projection, scaled by 1.7777)
STEREO_SCALE = 1.7777


def encode_normal(n):
    """Stereographic projection from (0, 0, -1) onto z = 0, scaled into [0, 1]."""
    p = n[..., :2] / (1.0 + n[..., 2:3])
    return p / STEREO_SCALE * 0.5 + 0.5


def decode_normal(enc):
    """The inverse projection: P = the point on the plane, n = (2P, 1 - |P|^2) / (1 + |P|^2)."""
    p = (enc * 2.0 - 1.0) * STEREO_SCALE
    q = np.sum(p * p, axis=-1, keepdims=True)
    return np.concatenate([2.0 * p, 1.0 - q], axis=-1) / (1.0 + q)


def encode_float_rg(v):
    """v in [0, 1) as (high, low) bytes-to-be: low = frac(255 v), high = frac(v) - low / 255."""
    low = np.mod(255.0 * v, 1.0)
    return np.stack([np.mod(v, 1.0) - low / 255.0, low], axis=-1)


def decode_float_rg(enc):
    return enc[..., 0] + enc[..., 1] / 255.0


# Per pixel inputs the shader makes from the sphere's UVs: a depth in [0, 0.5] (u / 2: exact, so no
# folding of constants by a compiler moves it) and a unit normal facing the camera (z >= 0.6 / |.|),
# read back exactly (float32 target) in modes 0 and 1.
DEPTH_NORMAL_BODY = """\
            float d = i.uv.x * 0.5;
            float3 n = normalize(float3(i.uv.x * 2.0 - 1.0, i.uv.y * 2.0 - 1.0, 0.6));
            float4 enc = EncodeDepthNormal(d, n);
            float dd; float3 dn;
            DecodeDepthNormal(enc, dd, dn);
            if (_Mode < 0.5) return float4(d, n.x, n.y, 1);
            if (_Mode < 1.5) return float4(n.z, enc.x, enc.y, 1);
            if (_Mode < 2.5) return float4(enc.z, enc.w, dd, 1);
            return float4(dn, 1);"""
# Bounds (float32 arithmetic on the read-back float32 inputs; derivations):
# - enc.xy: n.xy / (1 + n.z), / 1.7777, * 0.5, + 0.5: four roundings of values below 1 plus
#   the float32 constant 1.7777 (relative 3e-8): below 4 * 2^-24 + 3e-8 ~ 3e-7; 1e-6.
# - enc.w = frac(255 d): the product 255 d < 255 rounds by up to half an ulp of 128..255, 2^-17
#   = 7.6e-6; frac is exact. enc.z = frac(d) - enc.w / 255 carries that / 255 (3e-8) plus a
#   rounding: 1e-5 bounds enc.w, 1e-6 enc.z.
# - decoded depth enc.z + enc.w / 255 against d: exact up to the two roundings, 1e-6.
# - decoded normal against n: the inverse projection of a point carrying 1e-6 from the encode,
#   amplified by |dn/dP| <= 2 * 1.7777 * 2 (the scale and the map's largest stretch on this
#   range, |P| <= 1): 1.5e-5; 2e-5.
BOUNDS = {"enc_xy": 1e-6, "enc_z": 1e-6, "enc_w": 1e-5, "depth": 1e-6, "normal": 2e-5}


@pytest.mark.parametrize("language", LANGUAGES)
def test_encode_and_decode_depth_normal_are_unitys_encoding(tmp_path, language):
    """EncodeDepthNormal = (stereographic normal, EncodeFloatRG(depth)) per pixel against the
    float64 transcription; DecodeDepthNormal gives the depth and the normal back. Controls: an
    unscaled projection (kScale 1) and a one-byte depth (no low byte) fail the same bounds."""
    shader = _shader(tmp_path, "depth_normal", DEPTH_NORMAL_BODY, '        _Mode ("Mode", Float) = 0',
                     "        float _Mode;")
    images = [_render(tmp_path, shader, language, {"_Mode": float(mode)}) for mode in range(4)]
    covered = _covered(images[0])
    m0, m1, m2, m3 = (im[covered][:, :3].astype(np.float64) for im in images)
    d, n = m0[:, 0], np.column_stack([m0[:, 1], m0[:, 2], m1[:, 0]])
    enc_xy, enc_zw = encode_normal(n), encode_float_rg(d)
    assert np.ptp(d) > 0.4 and np.ptp(n[:, 0]) > 0.5  # many inputs, not one
    assert np.max(np.abs(m1[:, 1:3] - enc_xy)) <= BOUNDS["enc_xy"]
    assert np.max(np.abs(m2[:, 0] - enc_zw[:, 0])) <= BOUNDS["enc_z"]
    assert np.max(np.abs(m2[:, 1] - enc_zw[:, 1])) <= BOUNDS["enc_w"]
    assert np.max(np.abs(m2[:, 2] - d)) <= BOUNDS["depth"]
    assert np.max(np.abs(m3 - n)) <= BOUNDS["normal"]
    unit = n / np.linalg.norm(n, axis=-1, keepdims=True)  # float32's normalize is unit to ~1e-7
    assert np.max(np.abs(decode_normal(encode_normal(unit)) - unit)) < 1e-12  # the transcriptions invert each other
    assert np.max(np.abs(decode_float_rg(enc_zw) - d)) < 1e-12
    # controls
    unscaled = n[:, :2] / (1.0 + n[:, 2:3]) * 0.5 + 0.5
    assert np.max(np.abs(m1[:, 1:3] - unscaled)) > 100 * BOUNDS["enc_xy"]
    assert np.max(np.abs(m2[:, 2] - np.floor(d * 255.0) / 255.0)) > 100 * BOUNDS["depth"]


HEIGHT_BODY = """\
            float h = UnpackHeightmap(_Texel);
            float4 packed = PackHeightmap(h * _Scale + _Offset);
            return float4(h, packed.x, packed.y + packed.z + packed.w, 1);"""


@pytest.mark.parametrize("language", LANGUAGES)
def test_unpack_heightmap_reads_the_red_channel_and_pack_writes_it(tmp_path, language):
    """UnpackHeightmap(t) = t.r on APIs with 16-bit red textures (desktop GL, D3D11: the
    harness's), PackHeightmap(h) = (h, 0, 0, 0); float32 exact up to one multiply-add (2 ulp of
    values below 1: 2.4e-7). Control: the two-byte path of GLES ((r + 256 g) / 257) differs."""
    texel = (0.3, 0.7, 0.2, 1.0)
    shader = _shader(tmp_path, "heightmap", HEIGHT_BODY,
                     '        _Texel ("T", Vector) = (0, 0, 0, 0)\n        _Scale ("S", Float) = 1\n'
                     '        _Offset ("O", Float) = 0', "        float4 _Texel; float _Scale; float _Offset;")
    image = _render(tmp_path, shader, language, {"_Texel": list(texel), "_Scale": 0.5, "_Offset": 0.125})
    got = image[_covered(image)][:, :3]
    r = np.float32(texel[0])
    want = np.array([r, r * 0.5 + 0.125, 0.0])
    assert np.max(np.abs(got - want)) <= 2.4e-7
    two_byte = (texel[0] + 256.0 * texel[1]) / 257.0
    assert abs(two_byte - float(r)) > 0.3


@pytest.mark.parametrize("language", LANGUAGES)
def test_sample_raw_depth_texture_returns_every_channel(tmp_path, language):
    """SAMPLE_RAW_DEPTH_TEXTURE(t, uv) is the whole texel (SAMPLE_DEPTH_TEXTURE keeps red):
    Internal-BlitCopyDepth on a one-colour texture draws that colour, (r, g, b) of an 8-bit PNG
    decoded to float (exact: k / 255 in float32, 3e-8). Control: red alone in every channel."""
    from pbrlab.foundation.images import write_png
    png = tmp_path / "texel.png"
    write_png(png, np.broadcast_to(np.array([40, 120, 200, 255], np.uint8), (4, 4, 4)).copy())
    data = corpus.scene_for(ROOT / "Internal-BlitCopyDepth.shader")
    data["materials"]["m"]["properties"] = {"_MainTex": {"path": str(png), "srgb": False}}  # data: k / 255
    image = render_scene(parse_scene(data, "t", tmp_path), language=language).linear
    got = image[_covered(image)][:, :3]
    target = np.array([40, 120, 200]) / 255.0
    assert np.max(np.abs(got - target)) <= 1e-6
    assert np.max(np.abs(got - target[0])) > 0.1  # red alone would fail


@pytest.mark.parametrize("language", LANGUAGES)
def test_object_to_clip_pos_ods_is_the_mono_clip_position(tmp_path, language):
    """UnityObjectToClipPosODS without STEREO_CUBEMAP_RENDER_ON is the object position through
    M then VP: the image equals UnityObjectToClipPos's (exactly: the same two products in the
    same order). Internal-ODSWorldTexture draws the world position: at covered pixels |rgb| is
    the sphere's radius 1 up to the mesh's chords (UV sphere, within 1 - cos(pi / 16) = 0.019 of
    it) and interpolation."""
    body = "            return float4(i.uv, 0.5, 1);"
    plain = _shader(tmp_path, "plain", body)
    ods_text = plain.read_text().replace("o.pos = UnityObjectToClipPos(v.vertex);",
                                         "o.pos = UnityObjectToClipPosODS(v.vertex.xyz);")
    ods = tmp_path / "ods.shader"
    ods.write_text(ods_text.replace('"t/plain"', '"t/ods"'))
    a, b = _render(tmp_path, plain, language), _render(tmp_path, ods, language)
    assert np.array_equal(a, b)
    world = render_scene(parse_scene(corpus.scene_for(ROOT / "Internal-ODSWorldTexture.shader"), "t", tmp_path),
                         language=language).linear
    radius = np.linalg.norm(world[_covered(world)][:, :3], axis=-1)
    assert np.all(np.abs(radius - 1.0) <= 0.02)


ENGINE_FED = """\
            return mul(_StereoPreviousVP[0], float4(i.uv, 0, 1));"""


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_global_only_the_engine_sets_is_refused_by_name(tmp_path, language):
    """A pass reading _StereoPreviousVP (stereo motion vectors: the previous frame's matrices
    per eye; the mono ones are filled from the scene, test_engine_set_inputs.py) is refused at
    its line, naming it; declaring it without reading it (the control) renders."""
    reads = _shader(tmp_path, "reads", ENGINE_FED, globals_="        float4x4 _StereoPreviousVP[2];")
    with pytest.raises(PbrlabError) as caught:
        _render(tmp_path, reads, language)
    message = str(caught.value)
    assert "reads.shader:" in message and "uses _StereoPreviousVP, part of motion vectors" in message
    assert "\n" not in message.split("reads.shader", 1)[1].split("pbrlab does not provide it")[0]
    declares = _shader(tmp_path, "declares", "            return float4(i.uv, 0, 1);",
                       globals_="        float4x4 _StereoPreviousVP[2];")
    assert _covered(_render(tmp_path, declares, language)).any()


def test_engine_input_read_skips_declarations_and_inactive_text():
    assert engine_inputs.engine_input_read("float4x4 _PreviousVP;\nuniform float4 _TerrainTreeLightColors[4];") is None
    assert engine_inputs.engine_input_read("float4x4 _PreviousVP;\nx = mul(_PreviousVP, p);")[0] == "_PreviousVP"


SWITCH_BODY = """\
            float4 c = float4(0, 0, 0, 1);
            switch (_Selector)
            {
            case 0: c.r = 1; break;
            case 1: c.g = 1; break;
            case 2: c.b = 1; break;
            default: c.rgb = 0.5; break;
            }
            return c;"""


@pytest.mark.parametrize("language", LANGUAGES)
@pytest.mark.parametrize("selector, want", [(1.7, (0, 1, 0)), (-0.5, (1, 0, 0)), (2.0, (0, 0, 1)), (7.0, (0.5,) * 3)])
def test_switch_on_a_float_truncates_as_hlsl(tmp_path, language, selector, want):
    """``switch`` on a float selects the case of the selector truncated toward zero (HLSL's
    float-to-int): 1.7 -> 1, -0.5 -> 0 (rounding would give 2 and -1: the controls' cases)."""
    shader = _shader(tmp_path, "switch", SWITCH_BODY, '        _Selector ("S", Float) = 0', "        float _Selector;")
    image = _render(tmp_path, shader, language, {"_Selector": selector})
    got = image[_covered(image)][:, :3]
    assert np.all(got == np.array(want, np.float32))


def test_cg_spellings_keep_lines_and_offsets():
    text = ("const static int n = 8;\nfloat a[n];\nswitch (x.z) {\n}\n#pragma instancing_options procedural:setup\n"
            "void setup()\n{\n    unity_ObjectToWorld = _M;\n}\n")
    out = cg_spellings.respelled(text)
    assert out.splitlines()[0] == "static const int n = 8;"
    assert "switch (int(x.z))" in out
    assert out.count("\n") == text.count("\n")
    assert "unity_ObjectToWorld" not in out and "void setup()\n{\n" in out
    assert cg_spellings.respelled("switch (int(k)) {}") == "switch (int(k)) {}"


def test_a_subshader_whose_passes_are_all_skipped_names_each_skip():
    """Terrain-Utilities: its two passes are the editor's picking and selection passes."""
    outcome = corpus.run_shader(ROOT / "TerrainShaders" / "Splats" / "Terrain-Utilities.shader", "glsl")
    assert outcome.status == "refused"
    first = outcome.message.splitlines()[0]
    assert "nothing here draws (every pass skipped: Pass 'Picking' (LightMode Picking) skipped: an editor pass; " \
           "Pass 'Selection' (LightMode SceneSelectionPass) skipped: an editor pass)" in first


CAMERA_BODY = """\
            float3 world = mul(unity_ObjectToWorld, float4(i.uv.x * 2 - 1, i.uv.y * 2 - 1, 0.25, 1)).xyz;
            float3 camera = mul(unity_WorldToCamera, float4(world, 1)).xyz;
            float3 view = UnityWorldToViewPos(world);
            float3 back = mul(unity_CameraToWorld, float4(camera, 1)).xyz;
            if (_Mode < 0.5) return float4(camera - view * float3(1, 1, -1), 1);
            if (_Mode < 1.5) return float4(back - world, 1);
            return float4(camera - view, 1);"""


@pytest.mark.parametrize("language", LANGUAGES)
def test_world_to_camera_is_the_camera_transforms_frame(tmp_path, language):
    """unity_WorldToCamera is the camera transform's world-to-local matrix, +z forward: the
    view position with z negated (the view matrix looks down -z); unity_CameraToWorld takes it
    back. Points within 4 of the origin, seen from 3.2: two float32 matrix products each of
    terms up to ~8, 2 * 4 * 8 * 2^-24 = 3.8e-6; bound 5e-6. Control: the view position itself
    (z not negated) is off by twice the eye depth (> 1)."""
    shader = _shader(tmp_path, "camera", CAMERA_BODY, '        _Mode ("Mode", Float) = 0', "        float _Mode;")
    to_camera = _render(tmp_path, shader, language, {"_Mode": 0.0})
    back = _render(tmp_path, shader, language, {"_Mode": 1.0})
    covered = _covered(to_camera)
    assert np.max(np.abs(to_camera[covered][:, :3])) <= 5e-6
    assert np.max(np.abs(back[covered][:, :3])) <= 5e-6
    unflipped = _render(tmp_path, shader, language, {"_Mode": 2.0})
    assert np.min(np.abs(unflipped[covered][:, 2])) > 1.0


ARRAY = """
Shader "t/array" {
    Properties { _Layers ("Layers", 2DArray) = "red" {} }
    SubShader { Pass {
        CGPROGRAM
        #pragma vertex vert
        #pragma fragment frag
        #include "UnityCG.cginc"
        UNITY_DECLARE_TEX2DARRAY(_Layers);
        struct v2f { float4 pos : SV_POSITION; float2 uv : TEXCOORD0; };
        v2f vert(appdata_base v) { v2f o; o.pos = UnityObjectToClipPos(v.vertex); o.uv = v.texcoord.xy; return o; }
        float4 frag(v2f i) : SV_Target {
            float3 c = UNITY_SAMPLE_TEX2DARRAY(_Layers, float3(i.uv, 3)) * 0.5;
            return float4(c + UNITY_SAMPLE_TEX2DARRAY_LOD(_Layers, float3(i.uv, 0), 0).rgb * 0.25, 1);
        }
        ENDCG
    } }
}
"""


@pytest.mark.parametrize("language", LANGUAGES)
@pytest.mark.parametrize("default, want", [(None, (0.75, 0.0, 0.0)), ("gray", (0.375, 0.375, 0.375))])
def test_a_texture_array_property_is_one_layer_of_its_texel(tmp_path, language, default, want):
    """UNITY_DECLARE_TEX2DARRAY / UNITY_SAMPLE_TEX2DARRAY(_LOD): a one-layer array of the
    property's texel, every layer index clamped to it; the float4 truncated to float3 as HLSL
    does (the port's type pass knows the sample's type). Exact: 0.5 and 0.25 of 1 and 0.5. The
    material's default name changes it (the control: red against gray)."""
    shader = tmp_path / "array.shader"
    shader.write_text(ARRAY)
    image = _render(tmp_path, shader, language, {"_Layers": default} if default else None)
    assert np.all(image[_covered(image)][:, :3] == np.array(want, np.float32))


def test_a_texture_array_from_an_image_file_is_refused_by_name(tmp_path):
    from pbrlab.foundation.images import write_png
    write_png(tmp_path / "layer.png", np.full((2, 2, 4), 255, np.uint8))
    shader = tmp_path / "array.shader"
    shader.write_text(ARRAY)
    with pytest.raises(PbrlabError, match=r"_Layers is sampled as a texture array .* layer\.png"):
        _render(tmp_path, shader, "glsl", {"_Layers": {"path": "layer.png"}})


def test_a_surface_program_reading_an_engine_set_global_is_refused_by_name(tmp_path):
    """The same rule for a surface program (its Input and lighting are generated): the tree
    imposter's lights, at the line that reads them."""
    shader = tmp_path / "imposter.shader"
    shader.write_text(textwrap.dedent("""\
        Shader "t/imposter" {
            SubShader {
                CGPROGRAM
                #pragma surface surf Lambert
                float3 _TerrainTreeLightDirections[4];
                struct Input { float2 uv_MainTex; };
                void surf (Input IN, inout SurfaceOutput o) {
                    o.Albedo = _TerrainTreeLightDirections[0];
                }
                ENDCG
            }
        }
        """))
    with pytest.raises(PbrlabError, match=r"imposter\.shader:8: uses _TerrainTreeLightDirections, part of the lights"):
        _render(tmp_path, shader, "glsl")
