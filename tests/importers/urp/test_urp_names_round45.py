"""URP and Core RP names real URP shaders read that pbrlab refused (issue 34, session 45): Core's
GetCurrentViewPosition, Blit.hlsl's _BlitTexture_TexelSize, URP's _GlossyEnvironmentCubeMap,
UnityGBuffer.hlsl, Core's octahedral and R8G8 packing, URP 12's FullscreenVert (Varyings.uv)
and Shader Graph's cube texture object and UnityTexture2D parameter. Each is rendered in both
languages from a minimal shader of our own and compared with its float64 value from Unity's
documented meaning (or, for the sky cube, with the probe it is documented to be), with a control
(the value another reading gives) that the bound rejects.
"""

from __future__ import annotations

import numpy as np
import pytest

from pbrlab.render.renderer import scene_frame
from test_urp_fullscreen_pass import SIZE, _linear, _scene  # pytest puts this folder on sys.path
from test_urp_library_round2 import LANGUAGES, render_constant
from test_urp_names_round44 import _SHADER as NAMES44_SHADER

EPS = 2.0 ** -24


def _render(tmp_path, language, body, includes="", environment=False, properties=""):
    text = NAMES44_SHADER % {"body": body, "includes": includes, "globals": "", "properties": properties}
    return render_constant(tmp_path, text, language, environment=environment)


# --- GetCurrentViewPosition -----------------------------------------------------------------------
@pytest.mark.parametrize("language", LANGUAGES)
def test_current_view_position_is_the_camera_position(tmp_path, language):
    """Core's GetCurrentViewPosition (and GetPrimaryCameraPosition): the world position of the
    camera drawing the pass, the view matrix's inverse's translation. Bound: the position is
    float32 (2^-24 relative) and the output's offsets and scale round once each: 3 * 2^-24 * |p|.
    Control: the view matrix's own translation (the world origin in view space), (0, 0, -3.2)."""
    pixels, scene = _render(tmp_path, language, "float3 p = GetCurrentViewPosition(); float3 q = GetPrimaryCameraPosition();"
                            " return float4(p.x + 0.5, q.y + 0.25, p.z * 0.125, 1.0);")
    view = np.asarray(scene_frame(scene).view, np.float64)
    camera = np.linalg.inv(view)[:3, 3]
    expected = np.array([camera[0] + 0.5, camera[1] + 0.25, camera[2] * 0.125])
    bound = 3 * EPS * (np.abs(camera).max() + 1.0)
    assert (np.abs(pixels[:, :3] - expected) <= bound).all(), (pixels[0, :3], expected)
    origin_in_view = view[:3, 3]
    assert abs(origin_in_view[2] * 0.125 - expected[2]) > 100 * bound


# --- Core's packing -------------------------------------------------------------------------------
def _oct_encode(n: np.ndarray) -> np.ndarray:
    """Cigolle et al. 2014's octahedral map (float64): p = n / |n|_1, the lower hemisphere folded."""
    p = n / max(np.abs(n).sum(), 1e-6)
    fold = np.clip(-p[2], 0.0, 1.0)
    return p[:2] + np.where(p[:2] >= 0.0, fold, -fold)


def _oct_decode(f: np.ndarray) -> np.ndarray:
    n = np.array([f[0], f[1], 1.0 - abs(f[0]) - abs(f[1])])
    fold = max(-n[2], 0.0)
    n[:2] += np.where(n[:2] >= 0.0, -fold, fold)
    return n / np.linalg.norm(n)


LOWER = np.array([0.3, -0.5, -0.8]) / np.linalg.norm([0.3, -0.5, -0.8])  # a lower-hemisphere normal
UPPER = np.array([-0.6, 0.2, 0.7]) / np.linalg.norm([-0.6, 0.2, 0.7])
# float32: the normal's components (2^-24 relative), |n|_1's two sums and the division, the fold's
# sum and the output's x 0.5 + 0.5: under 8 roundings of values below 2, 16 * 2^-24; the decode
# adds its normalize (a dot of 3, a rsqrt, a product): 32 * 2^-24 for a round trip.
PACK_BOUND = 16 * EPS
ROUND_TRIP_BOUND = 32 * EPS


@pytest.mark.parametrize("language", LANGUAGES)
def test_oct_quad_encode_of_a_lower_and_an_upper_normal(tmp_path, language):
    """PackNormalOctQuadEncode of a lower- and an upper-hemisphere normal against the float64
    map, shown as f * 0.5 + 0.5. Control: the lower normal's unfolded projection p.xy, which the
    fold moves by over 0.3."""
    lower = ", ".join(f"{x:.9f}" for x in LOWER)
    upper = ", ".join(f"{x:.9f}" for x in UPPER)
    pixels, _ = _render(tmp_path, language, f"float2 a = PackNormalOctQuadEncode(float3({lower}));"
                        f" float2 b = PackNormalOctQuadEncode(float3({upper}));"
                        " return float4(a * 0.5 + 0.5, b.x * 0.5 + 0.5, 1.0);")
    a, b = _oct_encode(LOWER), _oct_encode(UPPER)
    expected = np.array([a[0] * 0.5 + 0.5, a[1] * 0.5 + 0.5, b[0] * 0.5 + 0.5])
    assert (np.abs(pixels[:, :3] - expected) <= PACK_BOUND).all(), (pixels[0, :3], expected)
    unfolded = LOWER[:2] / np.abs(LOWER).sum() * 0.5 + 0.5
    assert np.abs(unfolded - expected[:2]).max() > 0.1


@pytest.mark.parametrize("language", LANGUAGES)
def test_oct_quad_decode_returns_the_normal(tmp_path, language):
    """UnpackNormalOctQuadEncode(PackNormalOctQuadEncode(n)) is n (the float64 decode of the
    float64 encode is n to 1e-15), shown as n * 0.5 + 0.5. Control: the decode without the
    unfold (the folded point's direction), far from n."""
    lower = ", ".join(f"{x:.9f}" for x in LOWER)
    pixels, _ = _render(tmp_path, language, f"float3 n = UnpackNormalOctQuadEncode(PackNormalOctQuadEncode(float3({lower})));"
                        " return float4(n * 0.5 + 0.5, 1.0);")
    expected = _oct_decode(_oct_encode(LOWER)) * 0.5 + 0.5
    assert np.abs(expected - (LOWER * 0.5 + 0.5)).max() < 1e-12
    assert (np.abs(pixels[:, :3] - expected) <= ROUND_TRIP_BOUND).all(), (pixels[0, :3], expected)
    f = _oct_encode(LOWER)
    not_unfolded = np.array([f[0], f[1], 1.0 - abs(f[0]) - abs(f[1])])
    not_unfolded = not_unfolded / np.linalg.norm(not_unfolded) * 0.5 + 0.5
    assert np.abs(not_unfolded - expected).max() > 0.1


@pytest.mark.parametrize("language", LANGUAGES)
def test_r8g8_packing_holds_sixteen_bits(tmp_path, language):
    """PackFloatToR8G8(f): i = round(65535 f), (i mod 256, i div 256) / 255; UnpackFloatFromR8G8
    gives i / 65535 back. f = 0.3: i = 19661, bytes 205 and 76. Bound: one division each, 2^-24
    relative (the bytes and i are exact integers in float32). Control: f stored in one 8-bit
    channel, round(255 f) / 255, 2e-3 away."""
    pixels, _ = _render(tmp_path, language, "float2 p = PackFloatToR8G8(0.3);"
                        " return float4(p, UnpackFloatFromR8G8(p), 1.0);")
    i = int(np.floor(0.3 * 65535 + 0.5))
    expected = np.array([(i % 256) / 255.0, (i // 256) / 255.0, i / 65535.0])
    assert (i, i % 256, i // 256) == (19661, 205, 76)
    assert (np.abs(pixels[:, :3] - expected) <= 2 * EPS).all(), (pixels[0, :3], expected)
    assert abs(round(255 * 0.3) / 255.0 - expected[2]) > 1000 * EPS


# --- UnityGBuffer.hlsl ------------------------------------------------------------------------------
GBUFFER = '#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/UnityGBuffer.hlsl"'


@pytest.mark.parametrize("language", LANGUAGES)
def test_gbuffer_material_flags_pack_into_a_byte(tmp_path, language):
    """UnityGBuffer.hlsl in a forward pass: the material flags (receive-shadows-off 1, specular
    setup 8) packed as flags / 255, a pair (highlights-off 2, subtractive 4) packed and unpacked
    back to 6, and the Simple Lit lighting mode, 2. Bound: one division, 2^-24 relative.
    Control: the flags' sum read as a bit index (2^9 / 255 is not a channel value)."""
    pixels, _ = _render(tmp_path, language,
                        "float a = PackMaterialFlags(kMaterialFlagReceiveShadowsOff | kMaterialFlagSpecularSetup);"
                        " uint b = UnpackMaterialFlags(PackMaterialFlags(kMaterialFlagSpecularHighlightsOff"
                        " | kMaterialFlagSubtractiveMixedLighting));"
                        " return float4(a, float(b) / 16.0, kLightingSimpleLit * 0.25, 1.0);", includes=GBUFFER)
    expected = np.array([9.0 / 255.0, 6.0 / 16.0, 0.5])
    assert (np.abs(pixels[:, :3] - expected) <= 2 * EPS).all(), (pixels[0, :3], expected)
    assert abs(2.0 ** 9 / 255.0 - expected[0]) > 1.0


# --- _MainLightOcclusionProbes ---------------------------------------------------------------------
LIGHTING = '#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Lighting.hlsl"'


@pytest.mark.parametrize("language", LANGUAGES)
def test_main_light_occlusion_probes_mask_no_channel(tmp_path, language):
    """URP's _MainLightOcclusionProbes, the main light's one-hot channel of the baked shadow mask:
    no channel for a realtime light (0, 0, 0, 0), passed to MainLightShadow, which is 1 without
    shadow maps. Exact constants. Control: a light baked into the shadow mask's red channel,
    (1, 0, 0, 0)."""
    pixels, _ = _render(tmp_path, language, "float4 m = _MainLightOcclusionProbes;"
                        " float s = MainLightShadow(float4(0.0, 0.0, 0.0, 0.0), float3(0.0, 0.0, 0.0),"
                        " float4(1.0, 1.0, 1.0, 1.0), _MainLightOcclusionProbes);"
                        " return float4(m.x + m.y + 0.25, m.z + m.w + 0.5, s * 0.75, 1.0);", includes=LIGHTING)
    expected = np.array([0.25, 0.5, 0.75], np.float32)
    assert np.all(pixels[:, :3] == expected), pixels[0, :3]
    assert abs((1.0 + 0.25) - expected[0]) > 0.5


# --- _GlossyEnvironmentCubeMap ----------------------------------------------------------------------
def _sky_read(cube: str, sampler: str, hdr: str) -> str:
    return (f"float3 a = SAMPLE_TEXTURECUBE_LOD({cube}, {sampler}, float3(0.3, 0.8, 0.5), 1.0).rgb;"
            f" float3 b = SAMPLE_TEXTURECUBE({cube}, {sampler}, float3(-0.7, -0.2, 0.4)).rgb;"
            f" return float4(a.r + b.g, a.g * {hdr}.x, b.b + {hdr}.y + {hdr}.z, 1.0);")


@pytest.mark.parametrize("language", LANGUAGES)
def test_glossy_environment_cube_map_is_the_sky_probe(tmp_path, language):
    """URP's _GlossyEnvironmentCubeMap is the sky's reflection probe, unity_SpecCube0's texture
    (test_urp_names_round44 and the library tests check that against float64), with its decode
    _GlossyEnvironmentCubeMap_HDR unity_SpecCube0_HDR's: the same reads of both, at a mip and at
    mip 0 in two directions, give the same bits. Control: the environment is read (the two
    directions differ, the result is not black)."""
    sky, _ = _render(tmp_path, language, _sky_read("_GlossyEnvironmentCubeMap", "sampler_GlossyEnvironmentCubeMap",
                                                   "_GlossyEnvironmentCubeMap_HDR"), environment=True)
    probe, _ = _render(tmp_path, language, _sky_read("unity_SpecCube0", "samplerunity_SpecCube0", "unity_SpecCube0_HDR"),
                       environment=True)
    assert np.array_equal(sky[:, :3], probe[:, :3])
    other, _ = _render(tmp_path, language, "return float4(SAMPLE_TEXTURECUBE(_GlossyEnvironmentCubeMap,"
                       " sampler_GlossyEnvironmentCubeMap, float3(0.3, 0.8, 0.5)).rgb, 1.0);", environment=True)
    lower, _ = _render(tmp_path, language, "return float4(SAMPLE_TEXTURECUBE(_GlossyEnvironmentCubeMap,"
                       " sampler_GlossyEnvironmentCubeMap, float3(-0.7, -0.2, 0.4)).rgb, 1.0);", environment=True)
    assert other[:, :3].max() > 0.01 and np.abs(other[:, :3] - lower[:, :3]).max() > 0.01


# --- full-screen passes: _BlitTexture_TexelSize and URP 12's FullscreenVert --------------------------
TEXEL_SIZE_SHADER = """
Shader "t/blit texel size" {
    SubShader {
        Tags { "RenderPipeline" = "UniversalPipeline" }
        Pass {
            ZTest Always ZWrite Off Cull Off
            HLSLPROGRAM
            #pragma vertex Vert
            #pragma fragment Frag
            #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
            #include "Packages/com.unity.render-pipelines.core/Runtime/Utilities/Blit.hlsl"
            %(declaration)s
            float4 Frag(Varyings input) : SV_Target {
                float4 t = _BlitTexture_TexelSize;
                return float4(t.x * 16.0, t.y * 16.0, (t.z + t.w) / 256.0, 1.0);
            }
            ENDHLSL
        }
    }
}
"""


@pytest.mark.parametrize("declared", [False, True], ids=["from_blit_hlsl", "declared_by_the_shader"])
@pytest.mark.parametrize("language", LANGUAGES)
def test_blit_texture_texel_size_is_the_source_s(tmp_path, language, declared):
    """_BlitTexture_TexelSize (Blit.hlsl's since Unity 6, or the shader's own declaration, which
    the stand-in then leaves alone) is the camera colour's (1 / w, 1 / h, w, h), here 64 x 48.
    Bound: one division and one product of exact values: 2 * 2^-24. Control: the size
    transposed (48 x 64) moves the first two channels by 1/12."""
    text = TEXEL_SIZE_SHADER % {"declaration": "float4 _BlitTexture_TexelSize;" if declared else ""}
    image = _linear(_scene(tmp_path, text), language)
    w, h = SIZE
    expected = np.array([16.0 / w, 16.0 / h, (w + h) / 256.0])
    assert (np.abs(image[..., :3] - expected) <= 2 * EPS).all(), (image[0, 0, :3], expected)
    transposed = np.array([16.0 / h, 16.0 / w])
    assert np.abs(transposed - expected[:2]).min() > 0.05


URP12_SHADER = """
Shader "t/urp12 fullscreen" {
    SubShader {
        Tags { "RenderPipeline" = "UniversalPipeline" }
        HLSLINCLUDE
        #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
        #include "Packages/com.unity.render-pipelines.universal/Shaders/PostProcessing/Common.hlsl"
        half4 Frag(Varyings input) : SV_Target {
            return half4(UnityStereoTransformScreenSpaceTex(input.%(member)s), 0.5, 1.0);
        }
        ENDHLSL
        Pass {
            ZTest Always ZWrite Off Cull Off
            HLSLPROGRAM
            #pragma vertex %(vertex)s
            #pragma fragment Frag
            ENDHLSL
        }
    }
}
"""


@pytest.mark.parametrize("layout", ["urp12", "urp13"])
@pytest.mark.parametrize("language", LANGUAGES)
def test_post_processing_common_s_full_screen_vertex_of_each_urp(tmp_path, language, layout):
    """PostProcessing/Common.hlsl's full-screen vertex function: URP 12's FullscreenVert
    (Utils/Fullscreen.hlsl, Varyings.uv) in a shader that names it, URP 13 on's Vert (Blit.hlsl,
    Varyings.texcoord) in one that does not; each interpolates to the pixel centre's viewport
    position ((x + 0.5) / 64, (y + 0.5) / 48), y up (GL). Bound: the float32 interpolation of
    corner values up to 2, 2^-20, and the half output (rgba32f target: a half's 11 bits of
    values below 1, 2^-11 relative). Control: the coordinate from the top (1 - v)."""
    vertex, member = ("FullscreenVert", "uv") if layout == "urp12" else ("Vert", "texcoord")
    image = _linear(_scene(tmp_path, URP12_SHADER % {"vertex": vertex, "member": member}), language)
    h, w = image.shape[:2]
    x = (np.arange(w) + 0.5) / w
    y = (np.arange(h)[::-1] + 0.5) / h
    want = np.stack(np.broadcast_arrays(x[None, :], y[:, None], np.full((h, w), 0.5)), axis=-1)
    bound = 2.0 ** -20 + 2.0 ** -11 * want
    err = np.abs(image[..., :3] - want)
    assert (err <= bound).all(), err.max()
    top_down = np.abs(image[..., 1] - (1.0 - want[..., 1])) > bound[..., 1]
    assert top_down.mean() > 0.95


# --- Shader Graph texture objects ---------------------------------------------------------------------
# The generated code's forms: a cube texture object built from a Cubemap property and read
# through its members; a sub-graph function that takes a UnityTexture2D, copies it and reads its
# members, called with a local built from a 2D property.
GRAPH_OBJECTS = """
            #include "Packages/com.unity.render-pipelines.core/ShaderLibrary/Texture.hlsl"
            TEXTURECUBE(_Sky); SAMPLER(sampler_Sky);
            TEXTURE2D(_Tint); SAMPLER(sampler_Tint); float4 _Tint_TexelSize; float4 _Tint_ST;
            void SG_Tinted_0123(UnityTexture2D Texture2D_ab, float2 UV_cd, out float4 Out_1) {
                UnityTexture2D _Property_ef_Out_0 = Texture2D_ab;
                Out_1 = SAMPLE_TEXTURE2D(_Property_ef_Out_0.tex, _Property_ef_Out_0.samplerstate,
                    _Property_ef_Out_0.GetTransformedUV(UV_cd)) * (_Property_ef_Out_0.texelSize.z * 0.25);
            }
"""
GRAPH_BODY = ("UnityTextureCube c = UnityBuildTextureCubeStruct(_Sky);"
              " float4 s = SAMPLE_TEXTURECUBE_LOD(c.tex, c.samplerstate, float3(0.3, 0.8, 0.5), 0.0);"
              " UnityTexture2D t = UnityBuildTexture2DStruct(_Tint); float4 o;"
              " SG_Tinted_0123(t, IN.uv, o);"
              " return float4(s.rgb * 0.5, 1.0) + float4(o.rgb * 0.125, 0.0);")
# The same cube read directly (the property's texture: an unset Cube property binds the scene's
# environment, program.py), and the texture parameter's read as its value, 0.125 * 0.25.
DIRECT_BODY = ("float4 s = SAMPLE_TEXTURECUBE_LOD(_Sky, sampler_Sky, float3(0.3, 0.8, 0.5), 0.0);"
               " return float4(s.rgb * 0.5, 1.0) + float4(0.03125, 0.03125, 0.03125, 0.0);")
GRAPH_PROPERTIES = '_Sky ("Sky", Cube) = "" {} _Tint ("Tint", 2D) = "white" {}'


@pytest.mark.parametrize("language", LANGUAGES)
def test_shader_graph_cube_object_and_texture_parameter(tmp_path, language):
    """Shader Graph's UnityTextureCube (UnityBuildTextureCubeStruct: the cube and its sampler)
    reads what the property binds, the same bits as the cube read directly; a sub-graph's
    UnityTexture2D parameter (its texture, sampler, texel size and tiling, read through a copy)
    reads the unset 2D property's white texture, 1 x 1 (texel size z = 1, tiling 1, offset 0):
    0.125 * 0.25, exact binary fractions, added to the same cube term in both, so the renders
    agree to the bit. Control: the cube term is not black (the cube is read, not a zero that
    a missing binding would give both)."""
    pixels, _ = _render(tmp_path, language, GRAPH_BODY, includes=GRAPH_OBJECTS, properties=GRAPH_PROPERTIES,
                        environment=True)
    direct, _ = _render(tmp_path, language, DIRECT_BODY, includes=GRAPH_OBJECTS, properties=GRAPH_PROPERTIES,
                        environment=True)
    assert np.array_equal(pixels[:, :3], direct[:, :3])
    assert (direct[:, :3] - 0.03125).min() > 0.005  # the cube's term
