"""URP and Core RP names real URP shaders read that pbrlab refused (issue 34, session 45c): Core's
DebugMipmapStreamingMacros.hlsl (Unity 6), whose macros declare the mipmap-streaming debug
constants inside a material's UnityPerMaterial. Rendered in both languages from a minimal shader
of our own, compared with the float64 value of Unity's documented meaning, with a control.
"""

from __future__ import annotations

import numpy as np
import pytest

from test_urp_library_round2 import LANGUAGES, render_constant
from test_urp_names_round44 import _SHADER as NAMES44_SHADER

EPS = 2.0 ** -24

MIPMAP_GLOBALS = """
#include "Packages/com.unity.render-pipelines.core/ShaderLibrary/DebugMipmapStreamingMacros.hlsl"
CBUFFER_START(UnityPerMaterial)
    UNITY_TEXTURE_STREAMING_DEBUG_VARS
    float4 _Tint;
    UNITY_TEXTURE_STREAMING_DEBUG_VARS_FOR_TEX(_Splat0)
    float _Gain;
CBUFFER_END
"""


@pytest.mark.parametrize("language", LANGUAGES)
def test_mipmap_streaming_debug_vars_keep_the_material_constants(tmp_path, language):
    """The macros declare float4 members (the debug texture's and _Splat0's mip and stream
    information) between a material's own constants; those still read their property values
    (_Tint (0.2, 0.4, 0.6), _Gain 0.5) and the debug constants, which nothing sets without
    Unity's rendering debugger, read 0. Expected: tint * gain + the debug values' sum (0).
    Bound: two float32 roundings of values below 1, 2 * 2^-24. Control: the tint without the
    gain, which the bound rejects."""
    text = NAMES44_SHADER % {
        "properties": '_Tint ("t", Color) = (0.2, 0.4, 0.6, 1) _Gain ("g", Float) = 0.5',
        "includes": "", "globals": MIPMAP_GLOBALS,
        "body": "float d = dot(_Splat0_MipInfo + _Splat0_StreamInfo + unity_MipmapStreaming_DebugTex_MipInfo"
                " + unity_MipmapStreaming_DebugTex_StreamInfo + unity_MipmapStreaming_DebugTex_ST"
                " + unity_MipmapStreaming_DebugTex_TexelSize, float4(1, 1, 1, 1));"
                " return float4(_Tint.rgb * _Gain + d, 1.0);"}
    pixels, _ = render_constant(tmp_path, text, language, environment=False)
    tint = np.array([0.2, 0.4, 0.6])
    expected = tint * 0.5
    bound = 2 * EPS
    assert (np.abs(pixels[:, :3] - expected) <= bound).all(), (pixels[0, :3], expected)
    assert (np.abs(tint - expected) > 100 * bound).all()


@pytest.mark.parametrize("language", LANGUAGES)
def test_output_sh4_is_the_ambient_probe_at_the_normal(tmp_path, language):
    """URP's five-argument OUTPUT_SH4 (Unity 6.1: position, normal, view direction, the SH
    output, the probe occlusion output) with no probe volumes writes the ambient probe's SH at the
    normal (URP's SampleProbeSHVertex without APV) and leaves the occlusion argument unread: here a
    member no struct has, as the terrain shaders pass o.probeOcclusion without declaring it.
    Normal +y: the float64 SH9 irradiance along +y over pi (unity_AmbientSky's value, the same
    lookup), within AMBIENT_BOUND. Control: the SH along -y (unity_AmbientGround), which differs by
    far more than the bound."""
    from test_urp_library_round2 import AMBIENT_BOUND, AMBIENT_INCLUDE, _expected_ambient
    text = NAMES44_SHADER % {
        "properties": "", "includes": AMBIENT_INCLUDE, "globals": "struct ShOut { float3 sh; };",
        "body": "ShOut o; o.sh = float3(0, 0, 0); float3 p = float3(0.3, 0.2, 0.1);"
                " OUTPUT_SH4(p, float3(0, 1, 0), GetWorldSpaceNormalizeViewDir(p), o.sh, o.probeOcclusion);"
                " return float4(o.sh, 1.0);"}
    pixels, scene = render_constant(tmp_path, text, language)
    expected = _expected_ambient(scene, "unity_AmbientSky")
    err = np.abs(pixels[:, :3] - expected).max(axis=1)
    assert (err > AMBIENT_BOUND).mean() == 0.0, (err.max(), pixels[0], expected)
    assert np.abs(_expected_ambient(scene, "unity_AmbientGround") - expected).max() > 100 * AMBIENT_BOUND


@pytest.mark.parametrize("language", LANGUAGES)
def test_linear_eye_depth_of_a_vector_reads_its_first_component(tmp_path, language):
    """Core's LinearEyeDepth(depth, _ZBufferParams) and Linear01Depth given a depth texture's whole
    sample (a float4, or a float2): FXC truncates the vector to its first component (warning X3206)
    to match the (float, float4) form. With GL's _ZBufferParams (x = 1 - far/near, y = far/near,
    z = x / far, w = y / far): 1 / (z d + w) and 1 / (x d + y) of d = 0.5. Bound: the parameters are
    float32 (two roundings each), the product, sum and divide round once each, and the sum cancels
    at most a factor 3 at d = 0.5 (|z d| + |w| < 3 |z d + w|): 3 * 8 * 2^-24 relative. Control:
    the sample's second component (0.9) read instead."""
    body = ("return float4(LinearEyeDepth(float4(0.5, 0.9, 0.1, 0.3), _ZBufferParams) * 0.1,"
            " Linear01Depth(float2(0.5, 0.9), _ZBufferParams), LinearEyeDepth(float2(0.5, 0.9), _ZBufferParams) * 0.1, 1.0);")
    text = NAMES44_SHADER % {"properties": "", "includes": "", "globals": "", "body": body}
    pixels, scene = render_constant(tmp_path, text, language, environment=False)
    from pbrlab.render.renderer import scene_frame
    frame = scene_frame(scene)
    near, far = float(frame.near), float(frame.far)
    x, y = 1.0 - far / near, far / near

    def eye(d):
        return 1.0 / (x / far * d + y / far)

    def linear01(d):
        return 1.0 / (x * d + y)

    expected = np.array([eye(0.5) * 0.1, linear01(0.5), eye(0.5) * 0.1])
    bound = 3 * 8 * EPS * expected
    assert (np.abs(pixels[:, :3] - expected) <= bound).all(), (pixels[0, :3], expected)
    assert (np.abs(np.array([eye(0.9) * 0.1, linear01(0.9)]) - expected[:2]) > 100 * bound[:2]).all()


@pytest.mark.parametrize("language", LANGUAGES)
def test_main_light_with_a_scalar_shadow_mask(tmp_path, language):
    """GetMainLight(shadowCoord, positionWS, 1): the int literal for URP's half4 shadowMask, which
    FXC splats (scalar-to-vector promotion). The light is the scene's first directional light:
    colour its radiance (0.25, 0.5, 1), direction towards it (0, 0, 1) (the light travels along
    -z), exact in float32 (0.5 d + 0.5 rounds nothing). Control: the light with no light in the
    scene, black."""
    from test_urp_library_round2 import AMBIENT_INCLUDE
    sun = {"type": "directional", "direction": [0.0, 0.0, -1.0], "color": [0.25, 0.5, 1.0], "intensity": 1.0}
    text = NAMES44_SHADER % {
        "properties": "", "includes": AMBIENT_INCLUDE, "globals": "",
        "body": "Light l = GetMainLight(float4(0, 0, 0, 1), float3(0.1, 0.2, 0.3), 1);"
                " return float4(l.color * (l.direction.z * 0.5 + 0.5), 1.0);"}
    pixels, _ = render_constant(tmp_path, text, language, environment=False, lights=[sun])
    assert (pixels[:, :3] == np.array([0.25, 0.5, 1.0])).all(), pixels[0]
    dark, _ = render_constant(tmp_path, text, language, environment=False)
    assert np.abs(dark[:, :3]).max() == 0.0


@pytest.mark.parametrize("language", LANGUAGES)
def test_normal_reconstruction_raw_depth_is_ray_sphere_depth(tmp_path, language):
    """URP's NormalReconstruction.hlsl GetRawDepth(uv): the camera depth texture's raw depth at
    the screen position, so LinearEyeDepth / Linear01Depth of it are the float64 ray-sphere hit's
    eye depth and eye depth / far (test_urp_scene_textures' check and bound, the same texture and
    float32 chain). Control (in the check): the neighbouring pixel's depth fails it."""
    from test_urp_scene_textures import _URP_PASS, _scene, check_sphere_depths
    text = _URP_PASS % {
        "name": "urp normal reconstruction depth",
        "include": '#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/NormalReconstruction.hlsl"',
        "body": """float raw = GetRawDepth(GetNormalizedScreenSpaceUV(IN.positionCS));
                return float4(Linear01Depth(raw, _ZBufferParams), LinearEyeDepth(raw, _ZBufferParams),
                              LinearEyeDepth(raw, _ZBufferParams), 1.0);"""}
    check_sphere_depths(_scene(text, tmp_path), language)


DECAL_SHADER = """
Shader "t/decal" {
    SubShader {
        Tags { "RenderPipeline" = "UniversalPipeline" }
        Pass {
            Name "DBufferProjector"
            Tags { "LightMode" = "%(mode)s" }
            HLSLPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
            struct Attributes { float4 positionOS : POSITION; };
            float4 vert(Attributes IN) : SV_POSITION { return TransformObjectToHClip(IN.positionOS.xyz); }
            float4 frag() : SV_Target { return float4(0.25, 0.5, 0.75, 1.0); }
            ENDHLSL
        }
    }
}
"""


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_urp_decal_pass_is_refused_naming_the_decal_feature(tmp_path, language):
    """A shader whose passes are URP decal passes (LightMode DBufferProjector, drawn only by URP's
    Decal renderer feature) is refused naming that, not read as a custom Render Objects pass.
    Control: the same pass tagged UniversalForward draws its colour (0.25, 0.5, 0.75), exact."""
    from pbrlab.foundation.errors import PbrlabError
    with pytest.raises(PbrlabError, match=r"t\.shader:\d+: nothing here draws .*LightMode DBufferProjector.*"
                                          r"URP decal pass, drawn only by URP's Decal renderer feature"):
        render_constant(tmp_path, DECAL_SHADER % {"mode": "DBufferProjector"}, language, environment=False)
    pixels, _ = render_constant(tmp_path, DECAL_SHADER % {"mode": "UniversalForward"}, language, environment=False)
    assert (pixels[:, :3] == np.array([0.25, 0.5, 0.75])).all()


@pytest.mark.parametrize("language", LANGUAGES)
@pytest.mark.parametrize("default, value", [("white", 1.0), ("black", 0.0)])
def test_texture_object_declared_in_an_included_file_is_sampled(tmp_path, language, default, value):
    """A Texture2D and SamplerState declared in the project's own include file and sampled by the
    program with the object's method (_MainTex.Sample(sampler_MainTex, uv)): the GLSL port spells
    the lookup as it does the file's own. The texture's default, 'white' (1, 1, 1) or 'black' (0, 0,
    0), times 0.5: 0.5 or 0, exact in float32. Control: the two defaults give different pixels (a
    lookup that read no texture would give one value)."""
    (tmp_path / "objects.hlsl").write_text("Texture2D _MainTex;\nSamplerState sampler_MainTex;\n")
    text = NAMES44_SHADER % {
        "properties": f'_MainTex ("t", 2D) = "{default}" {{}}', "includes": '#include "objects.hlsl"', "globals": "",
        "body": "half4 c = _MainTex.Sample(sampler_MainTex, IN.uv) * 0.5; return float4(c.rgb, 1.0);"}
    pixels, _ = render_constant(tmp_path, text, language, environment=False)
    assert (pixels[:, :3] == 0.5 * value).all(), pixels[0]


@pytest.mark.parametrize("language", LANGUAGES)
def test_core_2d_sprite_inputs_are_an_unflipped_white_sprite(tmp_path, language):
    """URP's Core2D.hlsl (with SurfaceData2D.hlsl and Debugging2D.hlsl, which the 2D passes include
    beside it): a mesh drawn as a SpriteRenderer with no flip, white colour and no bones draws
    its sprite: unity_SpriteColor (1, 1, 1, 1), unity_SpriteProps (flip 1, 1; bone offset -1);
    UnityFlipSprite(p, flip) scales p.xy by flip. Pixel: (0.25 colour.r, 0.5 flip.x, -0.75 offset)
    plus the flipped point's x + 0.2 and y - 0.3 (both 0 for flip (-1, 1) of (0.2, 0.3, 0.4)):
    (0.25, 0.5, 0.75); bound: two float32 roundings, 2 * 2^-24. Control: a flip of (1, 1)
    leaves x 0.2, which moves red by 0.4."""
    body = ("float3 f = UnityFlipSprite(float3(0.2, 0.3, 0.4), float2(-1.0, 1.0));"
            " return float4(0.25 * unity_SpriteColor.r + (f.x + 0.2), unity_SpriteProps.x * 0.5 + (f.y - 0.3),"
            " -unity_SpriteProps.z * 0.75, unity_SpriteColor.a);")
    includes = "\n".join(f'#include "Packages/com.unity.render-pipelines.universal/{p}"' for p in (
        "Shaders/2D/Include/Core2D.hlsl", "Shaders/2D/Include/SurfaceData2D.hlsl", "ShaderLibrary/Debug/Debugging2D.hlsl"))
    text = NAMES44_SHADER % {"properties": "", "includes": includes, "globals": "", "body": body}
    pixels, _ = render_constant(tmp_path, text, language, environment=False)
    assert (np.abs(pixels[:, :3] - np.array([0.25, 0.5, 0.75])) <= 2 * EPS).all(), pixels[0]
    control, _ = render_constant(tmp_path, text.replace("float2(-1.0, 1.0)", "float2(1.0, 1.0)"), language,
                                 environment=False)
    assert (np.abs(control[:, 0] - 0.65) <= 2 * EPS).all(), control[0]
