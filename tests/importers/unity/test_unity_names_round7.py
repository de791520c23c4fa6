"""Built-in pipeline names and constructs a seen sample found missing (session 44): Unity's
UNITY_SPECCUBE_LOD_STEPS, DotClamped, UNITY_VPOS_TYPE, the fog-factor and legacy depth macros,
EncodeViewNormalStereo's float2, unity_CameraWorldClipPlanes, the deferred library's falloff
texture, a v2f position written POSITION0, include guards spelled ``#if !defined(X)`` or with
``__``, a for-loop variable used after its loop, the Standard add pass's own vertex output, and
the refusals of shaders whose passes all draw outside the camera's colour. Each against a
float64 value (or Unity's documented result), with a control.

Each pass is drawn on the corpus scene's sphere into its rgba32f target; a check reads the
colour at every pixel the sphere covers whole (alpha 1), where the fragment's value shows.
"""

from __future__ import annotations

import math
import textwrap

import numpy as np
import pytest

from corpus_sphere import covered_pixels, render_on_corpus_sphere
from pbrlab.foundation.errors import PbrlabError
from pbrlab.gpu.shaders import Source
from pbrlab.importers.unity import parse
from pbrlab.importers.unity.loop_scope import loop_variables_in_enclosing_scope
from pbrlab.importers.unity.source_text import UnityShaderError

LANGUAGES = ("hlsl", "glsl")  # HLSL as written, then the GLSL port

# A value the fragment computes from float32 inputs of magnitude <= 4 in a handful of
# operations: each rounding is within 2^-24 relative, so 16 of them stay under 2^-20 absolute.
FLOAT32_FEW_OPS = 2.0 ** -20

PASS = """
Shader "t/{name}" {{
    SubShader {{ Pass {{
        Tags {{ "LightMode" = "{light_mode}" }}
        CGPROGRAM
        #pragma vertex vert
        #pragma fragment frag
        #include "UnityCG.cginc"
{includes}
        struct v2f {{ float4 pos : SV_POSITION; float2 uv : TEXCOORD0; }};
        v2f vert(appdata_base v) {{
            v2f o; o.pos = UnityObjectToClipPos(v.vertex); o.uv = v.texcoord.xy;
            return o;
        }}
        float4 frag(v2f i{fragment_params}) : SV_Target {{
{body}
        }}
        ENDCG
    }} }}
}}
"""


def _shader(tmp_path, name, body, *, includes="", fragment_params="", light_mode="Always", text=None):
    path = tmp_path / f"{name}.shader"
    path.write_text(text if text is not None else textwrap.dedent(PASS.format(
        name=name, includes=includes, fragment_params=fragment_params, light_mode=light_mode, body=body)))
    return path


def _colour(image):
    """The rgb of every pixel the sphere covers, float64."""
    return image[covered_pixels(image)][:, :3].astype(np.float64)


def _assert_colour(image, expected, bound=FLOAT32_FEW_OPS):
    got = _colour(image)
    assert np.max(np.abs(got - np.asarray(expected, np.float64))) <= bound, (got.min(0), got.max(0), expected)


# -- UnityStandardConfig / UnityStandardBRDF ------------------------------------------------------

@pytest.mark.parametrize("language", LANGUAGES)
def test_speccube_lod_steps_is_unitys_six(tmp_path, language):
    """UnityStandardConfig.cginc: UNITY_SPECCUBE_LOD_STEPS 6 (a probe's roughest mip), reached
    through UnityStandardBRDF.cginc as Unity's include chain does. Control: without that include
    the name is undeclared (a refusal naming it)."""
    body = "            return float4(UNITY_SPECCUBE_LOD_STEPS / 8.0, 0, 0, 1);"
    image = render_on_corpus_sphere(tmp_path, _shader(tmp_path, "steps", body, includes='#include "UnityStandardBRDF.cginc"'), language)
    _assert_colour(image, [6.0 / 8.0, 0.0, 0.0], 0.0)
    with pytest.raises(PbrlabError, match="UNITY_SPECCUBE_LOD_STEPS"):
        render_on_corpus_sphere(tmp_path, _shader(tmp_path, "no_steps", body), language)


@pytest.mark.parametrize("language", LANGUAGES)
def test_dot_clamped_through_unity_pbs_lighting(tmp_path, language):
    """UnityStandardBRDF.cginc's DotClamped(a, b) = max(0, a . b), which UnityPBSLighting.cginc
    includes: 0.96 for two unit vectors 16 degrees apart. Control: opposed vectors give 0, not the
    dot product's -0.96."""
    a, b = np.array([0.6, 0.8, 0.0]), np.array([0.8, 0.6, 0.0])
    body = ("            return float4(DotClamped(float3(0.6, 0.8, 0), float3(0.8, 0.6, 0)),\n"
            "                          DotClamped(float3(0.6, 0.8, 0), float3(-0.8, -0.6, 0)), 0, 1);")
    image = render_on_corpus_sphere(tmp_path, _shader(tmp_path, "dot", body, includes='#include "UnityPBSLighting.cginc"'), language)
    _assert_colour(image, [max(0.0, a @ b), max(0.0, a @ -b), 0.0])
    assert a @ -b < -0.9  # the control's unclamped value


# -- HLSLSupport / UnityCG ----------------------------------------------------------------------

@pytest.mark.parametrize("language", LANGUAGES)
def test_vpos_type_gives_the_pixel_position(tmp_path, language):
    """HLSLSupport.cginc's UNITY_VPOS_TYPE (float4) on a VPOS fragment input: x is the pixel
    centre's window position, column + 0.5. Control: the red channel differs from column to
    column (a constant would not)."""
    body = "            return float4(screenPos.x / 64.0, 0, 0, 1);"
    image = render_on_corpus_sphere(tmp_path, _shader(tmp_path, "vpos", body, fragment_params=", UNITY_VPOS_TYPE screenPos : VPOS"),
                    language)
    covered = covered_pixels(image)
    columns = np.broadcast_to(np.arange(image.shape[1], dtype=np.float64), covered.shape)
    expected = (columns[covered] + 0.5) / 64.0
    assert np.max(np.abs(image[covered][:, 0] - expected)) <= FLOAT32_FEW_OPS
    assert np.ptp(image[covered][:, 0]) > 0.3


@pytest.mark.parametrize("language", LANGUAGES)
def test_fog_factor_is_unitys_no_fog_value(tmp_path, language):
    """UnityCG.cginc's UNITY_CALC_FOG_FACTOR_RAW / UNITY_CALC_FOG_FACTOR declare unityFogFactor,
    0.0 in the variant without FOG_LINEAR/EXP/EXP2 (the harness draws no fog): a program's own
    lerp(unity_FogColor, colour, unityFogFactor) shows unity_FogColor, (0.5, 0.5, 0.5) (Unity's
    default RenderSettings.fogColor). Control: the same lerp at factor 1 shows the colour."""
    for macro in ("UNITY_CALC_FOG_FACTOR_RAW", "UNITY_CALC_FOG_FACTOR"):
        body = (f"            {macro}(10.0);\n"
                "            return lerp(unity_FogColor, float4(1, 0.25, 0, 1), unityFogFactor);")
        _assert_colour(render_on_corpus_sphere(tmp_path, _shader(tmp_path, macro.lower(), body), language), [0.5, 0.5, 0.5], 0.0)
    body = "            float unityFogFactor = 1.0;\n            return lerp(unity_FogColor, float4(1, 0.25, 0, 1), unityFogFactor);"
    _assert_colour(render_on_corpus_sphere(tmp_path, _shader(tmp_path, "fog_one", body), language), [1.0, 0.25, 0.0], 0.0)


@pytest.mark.parametrize("language", LANGUAGES)
def test_legacy_depth_macros_are_unitys(tmp_path, language):
    """UnityCG.cginc's UNITY_TRANSFER_DEPTH(o) is nothing and UNITY_OUTPUT_DEPTH(i) is
    ``return 0``: the fragment returns 0 (black; the image's alpha is the harness's coverage). Control: the same shader
    without the macro returns its colour over the same pixels."""
    v2f = "struct v2f { float4 pos : SV_POSITION; float2 depth : TEXCOORD0; };"
    text = textwrap.dedent(f"""
        Shader "t/depth" {{ SubShader {{ Pass {{
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "UnityCG.cginc"
            {v2f}
            v2f vert(appdata_base v) {{
                v2f o; o.pos = UnityObjectToClipPos(v.vertex); o.depth = 0;
                UNITY_TRANSFER_DEPTH(o.depth);
                return o;
            }}
            half4 frag(v2f i) : SV_Target {{
                UNITY_OUTPUT_DEPTH(i.depth);
                return half4(0.25, 0.5, 0.75, 1);
            }}
            ENDCG
        }} }} }}
        """)
    control = render_on_corpus_sphere(tmp_path, _shader(tmp_path, "no_depth", "", text=text.replace("UNITY_OUTPUT_DEPTH(i.depth);", "")),
                      language)
    covered = covered_pixels(control)
    assert np.array_equal(control[covered][:, :3], np.broadcast_to([0.25, 0.5, 0.75], (covered.sum(), 3)))
    image = render_on_corpus_sphere(tmp_path, _shader(tmp_path, "depth", "", text=text), language)
    assert np.array_equal(image[covered][:, :3], np.zeros((covered.sum(), 3)))


@pytest.mark.parametrize("language", LANGUAGES)
def test_encode_view_normal_stereo_is_a_float2(tmp_path, language):
    """UnityCG.cginc's EncodeViewNormalStereo(n) returns a float2: n.xy / (n.z + 1) / 1.7777,
    mapped to [0, 1]; ``float4(EncodeViewNormalStereo(n), 0, 0)`` compiles as in Unity.
    Control: a second normal gives its own encoding (the value follows n)."""
    for name, n in (("a", (0.3, 0.4, 0.5)), ("b", (-0.6, 0.2, 0.7))):
        v = np.asarray(n, np.float64) / np.linalg.norm(n)
        expected = v[:2] / (v[2] + 1.0) / 1.7777 * 0.5 + 0.5
        body = f"            return float4(EncodeViewNormalStereo(normalize(float3{n})), 0, 1);"
        _assert_colour(render_on_corpus_sphere(tmp_path, _shader(tmp_path, f"enc_{name}", body), language), [*expected, 0.0])


@pytest.mark.parametrize("language", LANGUAGES)
def test_camera_world_clip_planes_are_the_frustums(tmp_path, language):
    """UnityShaderVariables.cginc's unity_CameraWorldClipPlanes: left, right, bottom, top, near,
    far, each a unit inward normal and an offset. For the corpus camera (at (0, 0, 3.2) looking at
    the origin, vertical field of view 40 degrees, square image) the left plane holds the eye and
    the left edge: its normal is (1, 0, -t) / |(1, 0, -t)| with t = tan(20 degrees), and its offset
    -n . eye; the near plane's normal is the view direction (0, 0, -1). Written from the camera's
    definition, not from the matrix the harness extracts them from. Control: the right plane's x
    is the left plane's negated."""
    t = math.tan(math.radians(20.0))
    left = np.array([1.0, 0.0, -t]) / math.hypot(1.0, t)
    eye = np.array([0.0, 0.0, 3.2])
    body = ("            float4 l = unity_CameraWorldClipPlanes[0];\n"
            "            float4 r = unity_CameraWorldClipPlanes[1];\n"
            "            float4 n = unity_CameraWorldClipPlanes[4];\n"
            "            return float4(l.x * 0.5 + 0.5 + n.z * 0.25, l.w / 4.0, r.x * 0.5 + 0.5, 1);")
    image = render_on_corpus_sphere(tmp_path, _shader(tmp_path, "planes", body), language)
    _assert_colour(image, [left[0] * 0.5 + 0.5 - 0.25, -(left @ eye) / 4.0, -left[0] * 0.5 + 0.5])


@pytest.mark.parametrize("language", LANGUAGES)
def test_deferred_library_declares_the_falloff_texture(tmp_path, language):
    """UnityDeferredLibrary.cginc declares _LightTextureB0 (a light pass may sample it itself,
    ``.UNITY_ATTEN_CHANNEL``); pbrlab's is white, the falloff being in the light's colour (as
    AutoLight.cginc's stand-in). Control: without that include it is undeclared."""
    body = "            return float4(tex2D(_LightTextureB0, float2(0.5, 0.5)).UNITY_ATTEN_CHANNEL * 0.5, 0, 0, 1);"
    image = render_on_corpus_sphere(tmp_path, _shader(tmp_path, "b0", body, includes='#include "UnityDeferredLibrary.cginc"'), language)
    _assert_colour(image, [0.5, 0.0, 0.0], 0.0)
    with pytest.raises(PbrlabError, match="_LightTextureB0"):
        render_on_corpus_sphere(tmp_path, _shader(tmp_path, "no_b0", body), language)


# -- semantics, includes, scopes ----------------------------------------------------------------

POSITION0 = """
Shader "t/position0" {{ SubShader {{ Pass {{
    CGPROGRAM
    #pragma vertex vert
    #pragma fragment frag
    #include "UnityCG.cginc"
    struct v2f {{ float4 vertex : {position}; float4 extra : POSITION1; }};
    v2f vert(appdata_base v) {{
        v2f o; o.vertex = UnityObjectToClipPos(v.vertex); o.extra = float4(0.125, 0.375, 0.625, 1);
        return o;
    }}
    float4 frag(v2f i) : SV_Target {{ return i.extra; }}
    ENDCG
}} }} }}
"""


@pytest.mark.parametrize("language", LANGUAGES)
def test_position0_in_a_v2f_is_the_clip_position(tmp_path, language):
    """HLSL: a semantic without an index is index 0, so ``POSITION0`` is POSITION, the clip-space
    position FXC takes from a vertex output; ``POSITION1`` beside it an interpolator whose value
    reaches the fragment. Control: with no index-0 position (POSITION2 instead) the pass is still
    refused for writing no SV_POSITION."""
    image = render_on_corpus_sphere(tmp_path, _shader(tmp_path, "pos0", "", text=POSITION0.format(position="POSITION0")), language)
    _assert_colour(image, [0.125, 0.375, 0.625], 0.0)
    with pytest.raises(PbrlabError, match="writes no SV_POSITION"):
        render_on_corpus_sphere(tmp_path, _shader(tmp_path, "pos2", "", text=POSITION0.format(position="POSITION2")), language)


@pytest.mark.parametrize("language", LANGUAGES)
@pytest.mark.parametrize("guard", ["#if !defined (MY_INC)", "#if !defined(MY_INC)", "#ifndef MY_INC"])
def test_a_guarded_file_that_includes_itself(tmp_path, language, guard):
    """A file inside its own guard that includes itself (hyunxiGit's incDeferLight.cginc): the
    second inclusion is empty once the guard's macro is defined, so both compilers read the file
    once. Control: the same file without its guard is refused as an include cycle, naming it."""
    inc = tmp_path / "mine.cginc"
    inc.write_text(f"{guard}\n#define MY_INC\n#include \"mine.cginc\"\n"
                   "float4 MyColour() { return float4(0.625, 0.125, 0.25, 1); }\n#endif\n")
    body = "            return MyColour();"
    image = render_on_corpus_sphere(tmp_path, _shader(tmp_path, "guarded", body, includes='#include "mine.cginc"'), language)
    _assert_colour(image, [0.625, 0.125, 0.25], 0.0)
    inc.write_text("#include \"mine.cginc\"\nfloat4 MyColour() { return float4(0.625, 0.125, 0.25, 1); }\n")
    with pytest.raises(PbrlabError, match=r"mine\.cginc:1: include cycle"):
        render_on_corpus_sphere(tmp_path, _shader(tmp_path, "unguarded", body, includes='#include "mine.cginc"'), language)


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_guard_macro_with_a_double_underscore(tmp_path, language):
    """``#ifndef __COMMON__`` / ``#define __COMMON__`` (Unity's PostProcessing includes): FXC takes
    the name; GLSL reserves identifiers with ``__`` and the port renames them, in the guard's test
    as in its #define, so a file included twice declares its names once (Mesa's preprocessor
    warning on the name stays a warning). Control: the same file without its guard, included
    twice, is refused for the redeclaration."""
    inc = tmp_path / "common.cginc"
    inc.write_text("#ifndef __COMMON__\n#define __COMMON__\nfloat4 _Tint;\n"
                   "float4 Shade() { return float4(0.375, 0.75, 0.125, 1); }\n#endif\n")
    body = "            return Shade();"
    twice = '#include "common.cginc"\n#include "common.cginc"'
    _assert_colour(render_on_corpus_sphere(tmp_path, _shader(tmp_path, "twice", body, includes=twice), language), [0.375, 0.75, 0.125], 0.0)
    inc.write_text("float4 _Tint;\nfloat4 Shade() { return float4(0.375, 0.75, 0.125, 1); }\n")
    with pytest.raises(PbrlabError, match=r"common\.cginc:[12]"):
        render_on_corpus_sphere(tmp_path, _shader(tmp_path, "twice_unguarded", body, includes=twice), language)


def test_mesa_preprocessor_warnings_are_warnings():
    """Mesa's preprocessor writes "0:2(9): preprocessor warning: ..." for a macro name with
    ``__`` and compiles the program: mapped as a warning, not an error (it led the refusal,
    above the real error, in yangxuan0261's Bloom.shader). Control: an error stays an error."""
    source = Source("", ["a.glsl"])
    mapped = source.map_messages('0:2(9): preprocessor warning: Macro names containing "__" are reserved\n'
                                 "0:3(1): error: `x' undeclared")
    assert mapped.splitlines() == ['a.glsl:2:9: warning: Macro names containing "__" are reserved',
                                   "a.glsl:3:1: error: `x' undeclared"]


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_for_loop_variable_used_after_its_loop(tmp_path, language):
    """FXC (HLSL before 2021) gives a for statement's variable the enclosing block's scope: a later
    ``for (k = 0; ...)`` and a read of k after it are the same variable (yangxuan0261's oil.shader).
    Three steps of 0.125 then two of 0.25: s = 0.875 and k = 2 after the second loop, computed as
    FXC's scope computes them (float64 below). Control: a later loop that declares its own k is
    left as written."""
    s, k = 0.0, 0
    for k in range(3):
        s += 0.125
    for k in range(2):
        s += 0.25
    k += 1  # the loop's last increment, which Python's range does not count
    body = ("            float s = 0;\n"
            "            for (int k = 0; k < 3; ++k) { s += 0.125; }\n"
            "            for (k = 0; k < 2; ++k) s += 0.25;\n"
            "            return float4(s, k * 0.125, 0, 1);")
    _assert_colour(render_on_corpus_sphere(tmp_path, _shader(tmp_path, "loop", body), language), [s, k * 0.125, 0.0], 0.0)
    own = "void f() {\n for (int k = 0; k < 3; ++k) { a(k); }\n for (int k = 0; k < 2; ++k) b(k);\n}\n"
    assert loop_variables_in_enclosing_scope(own) == own


# -- the Standard shader's add pass ---------------------------------------------------------------

STANDARD_ADD = """
Shader "t/{name}" {{
    Properties {{ _Color ("Color", Color) = (0.8, 0.6, 0.4, 1) _MainTex ("Albedo", 2D) = "white" {{}}
                  _Glossiness ("Smoothness", Range(0, 1)) = 0.5 _Metallic ("Metallic", Range(0, 1)) = 0 }}
    SubShader {{
        Pass {{ Tags {{ "LightMode" = "ForwardBase" }}
            CGPROGRAM
            #pragma vertex vertBase
            #pragma fragment fragBase
            #include "UnityStandardCoreForward.cginc"
            ENDCG
        }}
        Pass {{ Tags {{ "LightMode" = "ForwardAdd" }} Blend One One
            CGPROGRAM
            #pragma vertex vertAdd
            #pragma fragment {fragment}
            #include "UnityStandardCoreForward.cginc"
            half4 fragOwn(VertexOutputForwardAdd i) : SV_Target {{ return fragAdd(i); }}
            ENDCG
        }}
    }}
}}
"""


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_fragment_of_its_own_over_the_standard_add_pass(tmp_path, language):
    """UnityStandardCoreForward.cginc's add pass hands fragAdd a VertexOutputForwardAdd, Unity's
    own struct for it: a program's fragment that takes one and calls fragAdd (yangxuan0261's
    StandardExt dissolve) draws what fragAdd draws. Differential: the same shader with
    ``#pragma fragment fragAdd``, pixel for pixel. Control: the point light's add pass changes
    the image (the base pass alone is darker somewhere)."""
    own = render_on_corpus_sphere(tmp_path, _shader(tmp_path, "own", "", text=STANDARD_ADD.format(name="own", fragment="fragOwn")),
                  language)
    stock = render_on_corpus_sphere(tmp_path, _shader(tmp_path, "stock", "", text=STANDARD_ADD.format(name="stock", fragment="fragAdd")),
                    language)
    assert np.array_equal(own, stock)
    base_only = STANDARD_ADD.format(name="base", fragment="fragAdd").replace('"ForwardAdd"', '"ShadowCaster"')
    base = render_on_corpus_sphere(tmp_path, _shader(tmp_path, "base", "", text=base_only), language)
    covered = covered_pixels(stock)
    assert np.max(stock[covered][:, :3] - base[covered][:, :3]) > 0.05


# -- shaders whose passes all draw outside the camera's colour ------------------------------------

def _only_pass(tmp_path, name, light_mode):
    path = tmp_path / f"{name}.shader"
    path.write_text(f'Shader "t/{name}" {{ SubShader {{ Pass {{ Tags {{ "LightMode" = "{light_mode}" }}\nCGPROGRAM\n'
                    "#pragma vertex vert\n#pragma fragment frag\n#include \"UnityCG.cginc\"\n"
                    "float4 vert(float4 v : POSITION) : SV_POSITION { return UnityObjectToClipPos(v); }\n"
                    "float4 frag() : SV_Target { return 0; }\nENDCG\n} } }\n")
    return path


@pytest.mark.parametrize(("light_mode", "shown"), [
    ("MotionVectors", "the object is invisible in the camera's image"),
    ("Deferred", "Unity draws no pass of this SubShader into the camera's colour"),
])
def test_a_shader_of_skipped_passes_says_what_unity_shows(tmp_path, light_mode, shown):
    """A shader whose one pass is a MotionVectors (or Deferred) pass: the refusal names the file
    and the SubShader's line and says what Unity shows in the camera's colour for it. Control:
    a skipped editor pass gets no such words."""
    with pytest.raises(UnityShaderError) as info:
        parse.read_shader(_only_pass(tmp_path, "only", light_mode))
    assert f"only.shader:1: nothing here draws" in str(info.value) and shown in str(info.value)
    with pytest.raises(UnityShaderError) as info:
        parse.read_shader(_only_pass(tmp_path, "picking", "Picking"))
    assert "camera's" not in str(info.value)


# -- OpenGL extension macros in a Cg program --------------------------------------------------------

@pytest.mark.parametrize("language", LANGUAGES)
def test_gl_extension_macros_are_undefined_in_cg(tmp_path, language):
    """Unity preprocesses a Cg program as HLSL, where no GL_ macro is defined (NVIDIA's FXAA 3.11
    tests GL_ARB_gpu_shader5 to pick its gather path); Mesa and glslang predefine the extensions
    they support. ``#ifdef GL_ARB_gpu_shader5`` / ``#if defined(GL_NV_gpu_shader5)`` take their
    #else here as in Unity. Control: a code line's name that starts with GL_ is left as written."""
    from pbrlab.importers.unity.cg_spellings import respelled
    body = ("            #ifdef GL_ARB_gpu_shader5\n            return float4(1, 0, 0, 1);\n"
            "            #elif defined(GL_NV_gpu_shader5)\n            return float4(0, 0, 1, 1);\n"
            "            #else\n            return float4(0, 0.5, 0, 1);\n            #endif")
    _assert_colour(render_on_corpus_sphere(tmp_path, _shader(tmp_path, "gl_macros", body), language), [0.0, 0.5, 0.0], 0.0)
    assert respelled("float GL_count = 1;\n") == "float GL_count = 1;\n"
