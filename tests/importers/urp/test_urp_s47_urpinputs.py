"""URP stand-ins split as URP 12's and 14's files are (issue 34, session 47, s47-urpinputs).

* Which file brings which: URP's Shadows.hlsl, Input.hlsl and SurfaceInput.hlsl bring Core.hlsl
  (and SurfaceData.hlsl), not the lights; RealtimeLights.hlsl brings Input.hlsl, Shadows.hlsl and
  AmbientOcclusion.hlsl, not the BRDF; Lighting.hlsl brings them all (URP 12/14's #include lines,
  read for their names). A program that includes only one of the smaller files may use the names
  of the larger ones for its own.
* SurfaceData.hlsl guarded by Unity's own name, so a project's copy of it and the stand-in are one
  file to the preprocessor.
* URP's additional lights as Input.hlsl declares them for the uniform-array path
  (_AdditionalLightsPosition, _AdditionalLightsColor, _AdditionalLightsAttenuation,
  _AdditionalLightsSpotDir), and RealtimeLights.hlsl's GetAdditionalPerObjectLight (int and uint
  index), GetPerObjectLightIndex and GetAdditionalLightsCount with URP's DistanceAttenuation and
  AngleAttenuation, checked against float64 with the scene's point light.

Each renders in both languages from minimal shaders of our own (in the tests' text), with a control.
"""

from __future__ import annotations

import numpy as np
import pytest

from pbrlab.foundation.errors import ShaderCompileError
from test_urp_library_round2 import LANGUAGES, render_constant
from test_urp_names_round44 import _SHADER as NAMES44_SHADER

EPS = 2.0 ** -24
LIBRARY = "Packages/com.unity.render-pipelines.universal/ShaderLibrary"


def _render(tmp_path, language, body, includes, globals_="", lights=None):
    text = NAMES44_SHADER % {"body": body, "includes": includes, "globals": globals_, "properties": ""}
    return render_constant(tmp_path, text, language, environment=False, lights=lights)


def _include(*names):
    return "\n".join(f'#include "{LIBRARY}/{name}.hlsl"' for name in names)


# --- a program's own struct Light beside the files that do not declare URP's ----------------------
OWN_LIGHT = "struct Light { float3 c; };"
OWN_LIGHT_BODY = "Light l; l.c = float3(0.25, 0.5, 0.75); return float4(l.c, 1.0);"


@pytest.mark.parametrize("language", LANGUAGES)
@pytest.mark.parametrize("library_file", ["Shadows", "Input", "SurfaceInput"])
def test_a_program_may_define_light_beside_shadows_input_or_surface_input(tmp_path, language, library_file):
    """URP's Shadows.hlsl, Input.hlsl and SurfaceInput.hlsl bring Core.hlsl, not RealtimeLights.hlsl
    (where URP declares struct Light): a program that includes only one of them and declares its
    own Light (a shader of bioumaiquan's did, beside Shadows.hlsl) compiles and draws its own value,
    (0.25, 0.5, 0.75) exactly (each a float32 constant, written to a float target). Control:
    before the split pbrlab's Shadows.hlsl and Input.hlsl brought all of Lighting.hlsl, a
    'Light' : redefinition; and through Lighting.hlsl, which does bring URP's Light, it is still
    refused (the test below), as Unity's compiler refuses it."""
    pixels, _ = _render(tmp_path, language, OWN_LIGHT_BODY, _include(library_file), OWN_LIGHT)
    assert (pixels[:, :3] == [0.25, 0.5, 0.75]).all(), pixels[0]


@pytest.mark.parametrize("language", LANGUAGES)
def test_realtime_lights_brings_light_but_not_the_brdf(tmp_path, language):
    """RealtimeLights.hlsl declares URP's Light (so a program's own Light beside it is refused, as in
    Unity) and brings Shadows.hlsl (MainLightRealtimeShadow), not BRDF.hlsl: a program's own
    struct BRDFData compiles beside it. The pixel: the program's BRDFData member 0.5 plus the
    unshadowed main light's shadow 1 times 0.25, (0.75, 0.5, 0.25), exact in float32. Control:
    through Lighting.hlsl (which brings BRDF.hlsl) the same BRDFData is a redefinition."""
    own_brdf = "struct BRDFData { float3 mine; };"
    body = ("BRDFData b; b.mine = float3(0.5, 0.5, 0.0); Light l = GetMainLight();"
            " float s = MainLightRealtimeShadow(float4(0.0, 0.0, 0.0, 0.0));"
            " return float4(b.mine + float3(0.25, 0.0, 0.25) * s + l.color * 0.0, 1.0);")
    pixels, _ = _render(tmp_path, language, body, _include("RealtimeLights"), own_brdf)
    assert (pixels[:, :3] == [0.75, 0.5, 0.25]).all(), pixels[0]
    with pytest.raises(ShaderCompileError):
        _render(tmp_path, language, OWN_LIGHT_BODY, _include("RealtimeLights"), OWN_LIGHT)
    with pytest.raises(ShaderCompileError):
        _render(tmp_path, language, body, _include("Lighting"), own_brdf)


# --- a project's own SurfaceData.hlsl under Unity's guard ---------------------------------------------
PROJECT_SURFACE_DATA = """#ifndef UNIVERSAL_SURFACE_DATA_INCLUDED
#define UNIVERSAL_SURFACE_DATA_INCLUDED
struct SurfaceData {
    half3 albedo; half3 specular; half metallic; half smoothness; half3 normalTS; half3 emission;
    half occlusion; half alpha; half clearCoatMask; half clearCoatSmoothness;
};
#endif
"""


@pytest.mark.parametrize("language", LANGUAGES)
@pytest.mark.parametrize("order", ["copy first", "lighting first"])
def test_a_projects_surface_data_copy_and_the_stand_in_are_one_file(tmp_path, language, order):
    """A project's ShaderLibrary/SurfaceData.hlsl under URP's guard (UNIVERSAL_SURFACE_DATA_INCLUDED),
    included before or after Lighting.hlsl (which brings the package's SurfaceData.hlsl): in Unity
    the guard makes them one file, the first one read defining the struct. The pixel is the
    program's albedo (0.25, 0.5, 0.75), exact. Control: the stand-in guarded by pbrlab's name only
    (before this change) defined SurfaceData a second time after the copy: 'SurfaceData' :
    redefinition (HLSL), and the program does not compile."""
    (tmp_path / "ShaderLibrary").mkdir()
    (tmp_path / "ShaderLibrary" / "SurfaceData.hlsl").write_text(PROJECT_SURFACE_DATA)
    copy = '#include "ShaderLibrary/SurfaceData.hlsl"'
    includes = "\n".join([copy, _include("Lighting")] if order == "copy first" else [_include("Lighting"), copy])
    body = "SurfaceData s = (SurfaceData)0; s.albedo = float3(0.25, 0.5, 0.75); return float4(s.albedo, 1.0);"
    pixels, _ = _render(tmp_path, language, body, includes)
    assert (pixels[:, :3] == [0.25, 0.5, 0.75]).all(), pixels[0]



PROJECT_REALTIME_LIGHTS = """#ifndef UNIVERSAL_REALTIME_LIGHTS_INCLUDED
#define UNIVERSAL_REALTIME_LIGHTS_INCLUDED
#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Input.hlsl"
struct Light { half3 direction; half3 color; half distanceAttenuation; half shadowAttenuation; uint layerMask; };
Light GetMainLight() { Light l = (Light)0; return l; }
#endif
"""


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_projects_copy_of_realtime_lights_reads_the_stand_in(tmp_path, language):
    """A project's copy of URP's ShaderLibrary/RealtimeLights.hlsl (under URP's guard,
    UNIVERSAL_REALTIME_LIGHTS_INCLUDED) is read as pbrlab's stand-in, as copies of Lighting.hlsl
    and Shadows.hlsl are (vendored_library.GUARDS): its declarations of what Unity's engine sets
    would otherwise stand beside the stand-ins'. The program includes the copy, then Lighting.hlsl,
    and draws GetAdditionalLightsCount() (the stand-in's; the copy has none) over 4 with no light:
    0, and its own 0.5 in G, exactly. Control: read as written, the copy declares Light before
    Lighting.hlsl's RealtimeLights.hlsl does (its guard is pbrlab's), a redefinition."""
    (tmp_path / "ShaderLibrary").mkdir()
    (tmp_path / "ShaderLibrary" / "RealtimeLights.hlsl").write_text(PROJECT_REALTIME_LIGHTS)
    includes = '#include "ShaderLibrary/RealtimeLights.hlsl"\n' + _include("Lighting")
    body = "return float4(float(GetAdditionalLightsCount()) * 0.25, 0.5, GetMainLight().color.r, 1.0);"
    pixels, _ = _render(tmp_path, language, body, includes)
    assert (pixels[:, :3] == [0.0, 0.5, 0.0]).all(), pixels[0]
    from pbrlab.importers.unity.vendored_library import GUARDS
    assert GUARDS["ShaderLibrary/RealtimeLights.hlsl"] == "UNIVERSAL_REALTIME_LIGHTS_INCLUDED"


# --- URP's additional lights ----------------------------------------------------------------------
POINT = {"type": "point", "position": [1.5, 2.0, 1.0], "color": [1.0, 0.5, 0.25], "intensity": 2.0, "range": 4.0}
SUN = {"type": "directional", "direction": [0.0, -1.0, 0.0], "color": [1.0, 1.0, 1.0], "intensity": 1.0}
SHADED = np.array([0.3, 0.2, 0.1])  # the world position the program lights (a constant: every pixel alike)
SHADED_HLSL = "float3(0.3, 0.2, 0.1)"


def _urp_point_attenuation(position, light, nice=True) -> float:
    """URP 12 RealtimeLights.hlsl DistanceAttenuation (SHADER_HINT_NICE_QUALITY, URP's on desktop):
    1 / d^2 times saturate(1 - (d^2 / range^2)^2)^2, with _AdditionalLightsAttenuation.x = 1 /
    range^2 (URP 12 UniversalRenderPipelineCore, GetLightAttenuationAndSpotDirection); times
    AngleAttenuation, 1 for a point light (z 0, w 1). ``nice=False``: the mobile branch, the linear
    fade from 0.8 of the range, saturate(d^2 x + y) with x = 1 / (fade^2 - range^2), y = -range^2
    x (the control)."""
    d2 = float(np.sum((np.asarray(light["position"], float) - position) ** 2))
    r2 = light["range"] ** 2
    if nice:
        smooth = max(0.0, min(1.0, 1.0 - (d2 / r2) ** 2)) ** 2
    else:
        fade = 0.8 * 0.8 * r2 - r2
        smooth = max(0.0, min(1.0, d2 / fade - r2 / fade))
    return smooth / d2


@pytest.mark.parametrize("language", LANGUAGES)
def test_additional_per_object_light_is_urps_attenuation_of_the_point_light(tmp_path, language):
    """GetAdditionalPerObjectLight(0, p) with the scene's point light (the only additional light: the
    sun is the main light) at p = (0.3, 0.2, 0.1): R its distanceAttenuation (the float64 formula,
    _urp_point_attenuation, 0.142), G its direction's x mapped to [0, 1] (float64 normalize of the
    light's position minus p), B the same light through a uint index
    (GetAdditionalPerObjectLight(GetPerObjectLightIndex(k), p), k a uint) times 0.5. Bound: each
    value passes a dot of 3, a reciprocal or an inversesqrt (at most 2.5 ulp each, GLSL 4.50
    section 4.7.1), a square, a saturate and two products: 32 ulps of values below 1 (32 * 2^-24)
    covers them with the float32 roundings of the inputs. Control: the mobile branch's linear fade
    (URP's DistanceAttenuation without SHADER_HINT_NICE_QUALITY) differs by far more than the bound;
    before this change there was no uint overload (a uint index does not convert to int in GLSL)."""
    body = (f"float3 p = {SHADED_HLSL}; Light a = GetAdditionalPerObjectLight(0, p);"
            " uint k = 0u; Light b = GetAdditionalPerObjectLight(GetPerObjectLightIndex(k), p);"
            " Light c = GetAdditionalPerObjectLight(k, p);"
            " return float4(a.distanceAttenuation, a.direction.x * 0.5 + 0.5,"
            " b.distanceAttenuation * 0.25 + c.distanceAttenuation * 0.25, 1.0);")
    pixels, _ = _render(tmp_path, language, body, _include("RealtimeLights"), lights=[SUN, POINT])
    attenuation = _urp_point_attenuation(SHADED, POINT)
    to_light = np.asarray(POINT["position"]) - SHADED
    direction_x = to_light[0] / np.linalg.norm(to_light)
    expected = np.array([attenuation, direction_x * 0.5 + 0.5, attenuation * 0.5])
    bound = 32 * EPS
    assert (np.abs(pixels[:, :3] - expected) <= bound).all(), (pixels[0, :3], expected)
    assert abs(_urp_point_attenuation(SHADED, POINT, nice=False) - attenuation) > 100 * bound


@pytest.mark.parametrize("language", LANGUAGES)
def test_additional_light_arrays_hold_urps_values_of_the_scene_lights(tmp_path, language):
    """The arrays as URP's Input.hlsl declares them, filled from the scene (through RealtimeLights.hlsl,
    which brings Input.hlsl and declares GetAdditionalLightsCount): the point light's
    _AdditionalLightsPosition[0] = (1.5, 2, 1, 1), _AdditionalLightsColor[0] = colour x intensity
    (2, 1, 0.5), _AdditionalLightsAttenuation[0] = (1 / 16, 1 / 0.36, 0, 1),
    _AdditionalLightsSpotDir[0].w 0; GetAdditionalLightsCount() and _AdditionalLightsCount.x 1.
    The pixel: R position.x / 2 + attenuation.x = 0.8125; G colour.g / 4 + attenuation.w / 4 +
    spotDir.w = 0.5; B count / 4 + _AdditionalLightsCount.x / 8 + attenuation.y * 0.09 / 2 +
    attenuation.z = 0.375 + 0.125 = 0.5. Bound: 1 / 0.36 and 1 / 16 rounded (2.5 ulp each) and
    four sums: 16 ulps. Control: without a light the count is 0 (B 0.125 short of the expected,
    the light's own third term gone too), which the bound rejects."""
    body = ("float4 pos = _AdditionalLightsPosition[0]; float4 col = _AdditionalLightsColor[0];"
            " float4 att = _AdditionalLightsAttenuation[0]; float4 dir = _AdditionalLightsSpotDir[0];"
            " return float4(pos.x * 0.5 + att.x, col.g * 0.25 + att.w * 0.25 + dir.w,"
            " float(GetAdditionalLightsCount()) * 0.25 + _AdditionalLightsCount.x * 0.125"
            " + att.y * 0.09 * 0.5 + att.z, 1.0);")
    expected = np.array([0.75 + 1.0 / 16.0, 0.25 + 0.25, 0.25 + 0.125 + (1.0 / 0.36) * 0.045])
    bound = 16 * EPS
    pixels, _ = _render(tmp_path, language, body, _include("RealtimeLights"), lights=[SUN, POINT])
    assert (np.abs(pixels[:, :3] - expected) <= bound).all(), (pixels[0, :3], expected)
    dark, _ = _render(tmp_path, language, body, _include("RealtimeLights"), lights=[SUN])
    assert (np.abs(dark[:, 2] - expected[2]) > 100 * bound).all(), dark[0]



def test_additional_light_arrays_are_filled_only_where_read():
    """Every URP program includes Input.hlsl's arrays (through Core.hlsl); the entry points fill
    them (4 x 32 entries, each stage) only where the program reads one past its declaration.
    Control: a program reading _AdditionalLightsColor has it (and only it) filled."""
    from pbrlab.importers.unity.engine_inputs import fill_declared, fill_statements
    included = ("static float4 _AdditionalLightsPosition[32];\nstatic float4 _AdditionalLightsColor[32];\n"
                "float4 pbrlab_urp_additional_light_color(int index) { return float4(0.0, 0.0, 0.0, 0.0); }\n")
    quiet = "float4 frag() : SV_Target { return float4(1.0, 1.0, 1.0, 1.0); }"
    _, filled = fill_declared(quiet, quiet, included)
    assert filled == () and fill_statements(filled, "glsl") == ""
    reads = "float4 frag() : SV_Target { return _AdditionalLightsColor[0]; }"
    _, filled = fill_declared(reads, reads, included)
    assert filled == ("_AdditionalLightsColor",)
    assert "_AdditionalLightsColor[pbrlab_l] = pbrlab_urp_additional_light_color(pbrlab_l);" in fill_statements(filled, "glsl")


# --- Blit.hlsl's Vert beside a program's own GLES branch that reads positionOS --------------------
# X-PostProcessing's layout (a URP 14 port): Core.hlsl and Blit.hlsl included, #pragma vertex Vert
# (Blit.hlsl's), and a vertex function of its own over Blit's Attributes that reads v.positionOS
# and v.uv under SHADER_API_GLES (the members Core RP 14's Blit.hlsl declares on GLES only).
BLIT_VERT_SHADER = """
Shader "t/blit vert beside a gles branch" {
    SubShader {
        Tags { "RenderPipeline" = "UniversalPipeline" }
        ZTest Always ZWrite Off Cull Off
        HLSLINCLUDE
        #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
        #include "Packages/com.unity.render-pipelines.core/Runtime/Utilities/Blit.hlsl"
        struct VaryingsRay { float4 positionCS : SV_POSITION; float2 texcoord : TEXCOORD0; };
        VaryingsRay VertRay(Attributes v) {
            VaryingsRay o;
        #if SHADER_API_GLES
            o.positionCS = v.positionOS;
            o.texcoord = v.uv;
        #else
            o.positionCS = GetFullScreenTriangleVertexPosition(v.vertexID);
            o.texcoord = GetFullScreenTriangleTexCoord(v.vertexID);
        #endif
            return o;
        }
        ENDHLSL
        Pass {
            HLSLPROGRAM
            #pragma vertex Vert
            #pragma fragment Frag
            float4 Frag(Varyings input) : SV_Target { return float4(input.texcoord, 0.5, 1.0); }
            ENDHLSL
        }
    }
}
"""


@pytest.mark.parametrize("language", LANGUAGES)
def test_blit_vert_is_defined_beside_a_gles_branch_reading_position_os(tmp_path, language):
    """The program above draws full-screen through Blit.hlsl's Vert: each pixel shows its viewport
    position ((x + 0.5) / w, (y + 0.5) / h), y up (GL; as test_urp_fullscreen_pass). Bound: the
    float32 interpolation of corner values up to 2, a few ulp of 2: 2^-20. Control: before this
    change the v.positionOS read (in a branch pbrlab never draws, SHADER_API_GLES being undefined)
    was taken for URP 10's mesh-drawn layout (user_definitions: PBRLAB_USER_READS_Attributes_positionOS),
    which leaves Blit.hlsl's names out: '#pragma vertex Vert: no function Vert(...) is defined'
    (7 hidden-sample shaders of X-PostProcessing ports); the text_defines check below is that
    decision itself, and it still holds for a program that does not include Blit.hlsl."""
    from test_urp_fullscreen_pass import _linear, _scene
    from pbrlab.importers.unity.user_definitions import text_defines
    image = _linear(_scene(tmp_path, BLIT_VERT_SHADER), language)
    h, w = image.shape[:2]
    x = (np.arange(w) + 0.5) / w
    y = (np.arange(h)[::-1] + 0.5) / h
    want = np.stack(np.broadcast_arrays(x[None, :], y[:, None], np.full((h, w), 0.5)), axis=-1)
    assert (np.abs(image[..., :3] - want) <= 2.0 ** -20).all()
    program = BLIT_VERT_SHADER.split("HLSLINCLUDE")[1].split("ENDHLSL")[0]
    assert "PBRLAB_USER_READS_Attributes_positionOS" not in text_defines(program, tmp_path)
    urp10 = program.replace('#include "Packages/com.unity.render-pipelines.core/Runtime/Utilities/Blit.hlsl"', "")
    assert "PBRLAB_USER_READS_Attributes_positionOS" in text_defines(urp10, tmp_path)


# --- the 2D renderer's SpriteMaskShared.hlsl and URP 12's DebuggingFullscreen.hlsl -------------------
SPRITE_MASK_SHADER = """
Shader "t/sprite mask" {
    Properties { _MainTex ("Mask", 2D) = "white" {} _Cutoff ("Cutoff", Float) = %(cutoff)s }
    SubShader {
        Tags { "RenderPipeline" = "UniversalPipeline" }
        Pass {
            HLSLPROGRAM
            #pragma vertex MaskRenderingVertex
            #pragma fragment frag
            #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
            #include "Packages/com.unity.render-pipelines.universal/Shaders/2D/Include/SpriteMaskShared.hlsl"
            float4 frag(Varyings input) : SV_Target {
                return MaskRenderingFragment(input) + float4(input.uv * 0.5, 0.25, 1.0);
            }
            ENDHLSL
        }
    }
}
"""


@pytest.mark.parametrize("language", LANGUAGES)
def test_sprite_mask_pass_keeps_texels_at_or_above_the_cutoff(tmp_path, language):
    """SpriteMaskShared.hlsl's MaskRenderingVertex (the mesh's position to clip space, its uv passed
    on) and MaskRenderingFragment (clip(alpha - _Cutoff), then 0): with the white mask (alpha 1) and
    _Cutoff 0.5 nothing is discarded and the pixel is the program's own (uv / 2, 0.25, 1) plus 0:
    B 0.25 and A 1 exactly, R and G a texture coordinate of the sphere over 2, in [0, 0.5].
    Control: _Cutoff 2 (above every texel's alpha) discards every pixel, so nothing covers the
    sphere (render_constant's coverage assertion); before this change the include was refused."""
    pixels, _ = render_constant(tmp_path, SPRITE_MASK_SHADER % {"cutoff": "0.5"}, language, environment=False)
    assert (pixels[:, 2] == 0.25).all() and (pixels[:, 3] == 1.0).all(), pixels[0]
    assert ((pixels[:, :2] >= 0.0) & (pixels[:, :2] <= 0.5)).all()
    with pytest.raises(AssertionError):
        render_constant(tmp_path, SPRITE_MASK_SHADER % {"cutoff": "2.0"}, language, environment=False)


@pytest.mark.parametrize("language", LANGUAGES)
def test_debugging_fullscreen_declares_nothing_with_debug_display_off(tmp_path, language):
    """URP 12's Debug/DebuggingFullscreen.hlsl declares its overrides (CanDebugOverrideOutputColor)
    under DEBUG_DISPLAY only, which pbrlab never defines: a program's call under #if
    defined(DEBUG_DISPLAY) is not compiled, and the program's own colour (0.25, 0.5, 0.75) is drawn,
    exactly. A program's own function of that name compiles beside it (the stand-in declares none).
    Control: before this change the include was refused as a file pbrlab lacks; the program's own
    CanDebugOverrideOutputColor would be a redefinition were the stand-in to declare one."""
    own = "bool CanDebugOverrideOutputColor(float4 c, float2 uv, inout float4 d) { d = c; return false; }"
    body = ("float4 c = float4(0.25, 0.5, 0.75, 1.0);\n#if defined(DEBUG_DISPLAY)\n"
            " float4 d; if (CanDebugOverrideOutputColor(c, IN.uv, d)) return d;\n#endif\n"
            " float4 e = c; CanDebugOverrideOutputColor(c, IN.uv, e); return e;")
    pixels, _ = _render(tmp_path, language, body, '#include "%s/Debug/DebuggingFullscreen.hlsl"' % LIBRARY, own)
    assert (pixels[:, :3] == [0.25, 0.5, 0.75]).all(), pixels[0]


# --- URP 12's terrain inputs -----------------------------------------------------------------------
TERRAIN_PROPERTIES = ('_Control ("Control", 2D) = "red" {} _Splat0 ("Layer 0", 2D) = "white" {}'
                      ' _Splat1 ("Layer 1", 2D) = "black" {} _Metallic0 ("Metallic 0", Float) = 0.25')
TERRAIN_INPUT = '#include "Packages/com.unity.render-pipelines.universal/Shaders/Terrain/TerrainLitInput.hlsl"'
TERRAIN_BODY = ("float4 control = SAMPLE_TEXTURE2D(_Control, sampler_Control, IN.uv);"
                " float4 c = control.r * SAMPLE_TEXTURE2D(_Splat0, sampler_Splat0, IN.uv)"
                " + control.g * SAMPLE_TEXTURE2D(_Splat1, sampler_Splat0, IN.uv);"
                " float4 p = float4(1.0, 2.0, 3.0, 1.0); float3 n = float3(0.0, 1.0, 0.0); TerrainInstancing(p, n);"
                " return float4(c.rgb * 0.5 + _Metallic0, (p.y - 2.0) + (n.y - 1.0) + 1.0);")


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_custom_terrain_shader_reads_urp_12s_terrain_inputs(tmp_path, language):
    """A terrain shader of its own over TerrainLitInput.hlsl: _Control's texel weighs layer 0
    (_Splat0) and layer 1 (_Splat1, read with layer 0's sampler as URP's shaders do), _Metallic0 a
    per-layer scalar; TerrainInstancing leaves a vertex unchanged without instancing (URP 12). With
    the material's defaults ("red" control: weight 1 on layer 0, white layer 0, black layer 1,
    metallic 0.25) the pixel is 1 * 0.5 + 0.25 = 0.75 in each channel, alpha 1: exact (texels of 0
    and 255, sums of binary fractions). Control: URP's own passes (TerrainLitPasses.hlsl) are
    refused naming them; before this change TerrainLitInput.hlsl itself was a missing include."""
    pixels, _ = render_constant(
        tmp_path, NAMES44_SHADER % {"properties": TERRAIN_PROPERTIES, "includes": TERRAIN_INPUT, "globals": "",
                                    "body": TERRAIN_BODY}, language, environment=False)
    assert (pixels == [0.75, 0.75, 0.75, 1.0]).all(), pixels[0]
    passes = TERRAIN_INPUT.replace("TerrainLitInput", "TerrainLitPasses")
    with pytest.raises(Exception, match=r"URP's Terrain Lit passes \(TerrainLitPasses\.hlsl: SplatmapVert, "
                                        r"SplatmapFragment, SplatmapMix and the terrain's shadow and depth passes\)"
                                        r" are not provided by pbrlab's stand-in"):
        render_constant(tmp_path, NAMES44_SHADER % {"properties": TERRAIN_PROPERTIES, "includes": passes,
                                                    "globals": "", "body": TERRAIN_BODY}, language, environment=False)
