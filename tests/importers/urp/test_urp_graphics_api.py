"""The graphics API a Unity program is compiled for (issue 34, session 45): Unity defines exactly
one platform macro per compile (``SHADER_API_D3D11``, ``SHADER_API_GLCORE``, ...; Unity manual,
"Built-in shader macros"), and a project that vendors Core RP's ShaderLibrary under ``Assets/``
picks its ``API/<platform>.hlsl`` header by it (Common.hlsl's ``#error unsupported shader api``
without one). pbrlab draws with OpenGL and follows its conventions (UNITY_UV_STARTS_AT_TOP and
UNITY_REVERSED_Z undefined), so the macro is ``SHADER_API_GLCORE`` (graphics_api.py), in both
languages and both pipelines.

Also: an include written ``#include "/API/X.hlsl"`` (a vendored Common.hlsl's spelling) is read
from the including file's folder, as Unity reads it (include_separators.py).

Each shader returns short binary fractions, exact in float32 and in the half-float target, so
the covered pixels must equal the float64 expectation exactly.
"""

from __future__ import annotations

import textwrap

import numpy as np
import pytest

from pbrlab.checking import unity_corpus as corpus
from pbrlab.importers.unity import graphics_api
from test_urp_scene_textures import _URP_PASS as URP_PASS  # pytest puts this folder on sys.path

# Each branch its own colour: Direct3D's, OpenGL core's, no platform (what pbrlab compiled
# before: the control), and another API's.
PLATFORM_BRANCHES = """
#if defined(SHADER_API_D3D11)
    #define PLATFORM_COLOUR float3(1.0, 0.0, 0.0)
#elif defined(SHADER_API_GLCORE)
    #define PLATFORM_COLOUR float3(0.25, 0.5, 0.75)
#elif defined(SHADER_API_VULKAN) || defined(SHADER_API_METAL) || defined(SHADER_API_GLES3)
    #define PLATFORM_COLOUR float3(0.0, 1.0, 0.0)
#else
    #define PLATFORM_COLOUR float3(0.0, 0.0, 1.0)
#endif
"""
GLCORE = np.array([0.25, 0.5, 0.75])
NO_PLATFORM = np.array([0.0, 0.0, 1.0])

# The scene-texture tests' URP pass (%(include)s after Core.hlsl, %(body)s the fragment's)
URP_SHADER = URP_PASS % {"name": "urp platform", "include": "%(platform)s",
                         "body": "return float4(PLATFORM_COLOUR, 1.0);"}

BUILTIN_SHADER = textwrap.dedent("""\
    Shader "t/builtin platform" {
        SubShader {
            Pass {
                CGPROGRAM
                #pragma vertex vert
                #pragma fragment frag
                #include "UnityCG.cginc"
                %(platform)s
                float4 vert(float4 p : POSITION) : SV_POSITION { return UnityObjectToClipPos(p.xyz); }
                fixed4 frag() : SV_Target { return fixed4(PLATFORM_COLOUR, 1.0); }
                ENDCG
            }
        }
    }
    """)

# A project's own copy of Core's Common.hlsl pattern: the platform header by macro, from its own
# API/ folder, named with a leading "/"; the header defines a texture macro of Core's API family
# and the clip-space constant GLCore's header gives OpenGL.
VENDORED_COMMON = """\
#ifndef MY_COMMON_INCLUDED
#define MY_COMMON_INCLUDED
#if defined(SHADER_API_D3D11)
#include "/API/MyD3D11.hlsl"
#elif defined(SHADER_API_GLCORE)
#include "/API/MyGLCore.hlsl"
#else
#error unsupported shader api
#endif
#endif
"""
VENDORED_D3D11 = """\
#define MY_TEXTURE2D(name) Texture2D name
#define MY_NEAR_CLIP_VALUE (1.0)
"""
VENDORED_GLCORE = """\
#define MY_TEXTURE2D(name) Texture2D name
#define MY_NEAR_CLIP_VALUE (-1.0)
"""
# GL's near clip value -1: (0.25, 0.5, 0.75); Direct3D's +1 would give (0.75, 1.0, 1.25)
VENDORED_SHADER = URP_PASS % {"name": "vendored common", "include": '#include "../ShaderLibrary/MyCommon.hlsl"',
                              "body": "return float4(float3(0.5, 0.75, 1.0) + 0.25 * MY_NEAR_CLIP_VALUE, 1.0);"}


def _run(path, text, language):
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text)
    return corpus.run_shader(path, language)


def _assert_exactly(result, expected):
    assert result.status == "rendered", result.message
    covered = result.image[..., 3] == 1.0
    assert covered.mean() > 0.1
    assert np.array_equal(result.image[covered][:, :3].astype(np.float64),
                          np.broadcast_to(expected, (covered.sum(), 3)))


@pytest.mark.parametrize("language", corpus.LANGUAGES)
@pytest.mark.parametrize("pipeline", ["urp", "builtin"])
def test_the_platform_is_opengl_core_in_both_pipelines(tmp_path, language, pipeline):
    """SHADER_API_GLCORE, and no other platform's macro, in a URP and a built-in program."""
    shader = URP_SHADER if pipeline == "urp" else BUILTIN_SHADER
    _assert_exactly(_run(tmp_path / "p.shader", shader % {"platform": PLATFORM_BRANCHES}, language), GLCORE)


@pytest.mark.parametrize("language", corpus.LANGUAGES)
def test_control_without_the_platform_macro_the_last_branch_is_drawn(tmp_path, language, monkeypatch):
    """The old behaviour (no platform macro) draws the #else branch's blue: the check above
    tells the two apart."""
    monkeypatch.setattr(graphics_api, "program_defines", lambda unity_pass: {})
    result = _run(tmp_path / "p.shader", URP_SHADER % {"platform": PLATFORM_BRANCHES}, language)
    _assert_exactly(result, NO_PLATFORM)


def _vendored_project(tmp_path, common=VENDORED_COMMON):
    library = tmp_path / "Assets" / "URP" / "ShaderLibrary"
    (library / "API").mkdir(parents=True)
    (library / "MyCommon.hlsl").write_text(common)
    (library / "API" / "MyD3D11.hlsl").write_text(VENDORED_D3D11)
    (library / "API" / "MyGLCore.hlsl").write_text(VENDORED_GLCORE)
    return tmp_path / "Assets" / "URP" / "Shaders" / "v.shader"


@pytest.mark.parametrize("language", corpus.LANGUAGES)
def test_a_vendored_common_takes_its_own_glcore_header(tmp_path, language):
    """The vendored Common's ``#include "/API/MyGLCore.hlsl"`` is its own folder's API/ file (a
    leading "/" read from the including file's folder), chosen by SHADER_API_GLCORE: GL's near
    clip value -1 gives (0.25, 0.5, 0.75) exactly."""
    _assert_exactly(_run(_vendored_project(tmp_path), VENDORED_SHADER, language), GLCORE)


@pytest.mark.parametrize("language", corpus.LANGUAGES)
def test_control_a_vendored_common_without_a_platform_stops_at_its_error(tmp_path, language, monkeypatch):
    """Without the macro (the old behaviour) the vendored Common stops at its own #error, and
    the refusal names the file and line."""
    monkeypatch.setattr(graphics_api, "program_defines", lambda unity_pass: {})
    result = _run(_vendored_project(tmp_path), VENDORED_SHADER, language)
    assert result.status != "rendered"
    assert "MyCommon.hlsl:8" in result.message and "unsupported shader api" in result.message


@pytest.mark.parametrize("language", corpus.LANGUAGES)
def test_control_a_missing_platform_header_is_refused_by_name(tmp_path, language):
    """A leading-"/" include that names no file beside the including one is refused naming
    the include and its file (not looked up from the file system's root)."""
    common = VENDORED_COMMON.replace("/API/MyGLCore.hlsl", "/API/Missing.hlsl")
    result = _run(_vendored_project(tmp_path, common), VENDORED_SHADER, language)
    assert result.status != "rendered"
    assert "Missing.hlsl" in result.message and "MyCommon.hlsl" in result.message


# A project's copy of URP's ShaderLibrary/Core.hlsl under Assets/ (Unity's include guard): it
# declares the engine's per-draw inputs, as URP's own file does, and a Max3 of its own that no
# stand-in has (red). pbrlab reads its stand-in for URP's Core.hlsl in the copy's place
# (vendored_library.py): the stand-in's Core RP Max3 / Min3 answer.
VENDORED_CORE = """\
#ifndef %(guard)s
#define %(guard)s
CBUFFER_START(UnityPerDraw)
float4x4 unity_ObjectToWorld;
real4 unity_SHAr;
CBUFFER_END
float3 Max3(float3 a, float3 b, float3 c) { return float3(1.0, 0.0, 0.0); }
#endif
"""
VENDORED_CORE_SHADER = URP_PASS.replace(
    "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl", "../%%(folder)s/Core.hlsl") % {
    "name": "vendored core", "include": "",
    "body": "return float4(Max3(0.25, 0.5, 0.125), Min3(0.25, 0.5, 0.125), 0.75, 1.0);"}
STAND_IN_MAX_MIN = np.array([0.5, 0.125, 0.75])


def _vendored_core(tmp_path, folder="ShaderLibrary", guard="UNIVERSAL_PIPELINE_CORE_INCLUDED"):
    library = tmp_path / "Assets" / "URP" / folder
    library.mkdir(parents=True)
    (library / "Core.hlsl").write_text(VENDORED_CORE % {"guard": guard})
    return tmp_path / "Assets" / "URP" / "Shaders" / "v.shader", VENDORED_CORE_SHADER % {"folder": folder}


@pytest.mark.parametrize("language", corpus.LANGUAGES)
def test_a_vendored_copy_of_urp_core_reads_the_stand_in(tmp_path, language):
    """Core RP's Max3 / Min3 of (0.25, 0.5, 0.125): (0.5, 0.125), exactly, and the object drawn by
    the stand-in's TransformObjectToHClip."""
    _assert_exactly(_run(*_vendored_core(tmp_path), language), STAND_IN_MAX_MIN)


@pytest.mark.parametrize("language", corpus.LANGUAGES)
@pytest.mark.parametrize("case", ["own guard", "not below ShaderLibrary"])
def test_control_a_file_of_the_projects_own_is_compiled_as_written(tmp_path, language, case):
    """A Core.hlsl with a guard of the project's own, or outside a ShaderLibrary folder, is the
    project's file: compiled as written, its redeclaration of the engine's inputs (and no
    TransformObjectToHClip) is refused, naming the file."""
    kwargs = {"guard": "MY_OWN_CORE_INCLUDED"} if case == "own guard" else {"folder": "Library"}
    result = _run(*_vendored_core(tmp_path, **kwargs), language)
    assert result.status != "rendered"
    assert "Core.hlsl" in result.message or "TransformObjectToHClip" in result.message


@pytest.mark.parametrize("language", corpus.LANGUAGES)
def test_a_2d_renderer_light_pass_is_refused_naming_the_2d_lights(tmp_path, language):
    """URP's 2D Renderer's light passes include Shaders/2D/Include/LightingUtility.hlsl: refused at
    that #include line, naming the 2D lights' lookup textures (pbrlab's scenes have no 2D
    lights); the same program without it renders (the control: the refusal is the include's)."""
    include = '#include "Packages/com.unity.render-pipelines.universal/Shaders/2D/Include/LightingUtility.hlsl"'
    text = URP_SHADER % {"platform": include + "\n" + PLATFORM_BRANCHES}
    result = _run(tmp_path / "l.shader", text, language)
    assert result.status == "refused"
    line = 1 + text.splitlines().index(next(x for x in text.splitlines() if "LightingUtility" in x))
    assert f"l.shader:{line}:" in result.message and "_LightLookup" in result.message
    _assert_exactly(_run(tmp_path / "c.shader", URP_SHADER % {"platform": PLATFORM_BRANCHES}, language), GLCORE)


# A copy of URP's Shaders/UnlitInput.hlsl (Unity's guard) whose text would stop the compile: the
# stand-in's UnlitInput answers (its _BaseColor, the material's property).
VENDORED_UNLIT_INPUT = """\
#ifndef %(guard)s
#define %(guard)s
#error "the project's copy was compiled"
#endif
"""
UNLIT_INPUT_SHADER = (URP_PASS % {"name": "vendored unlit input", "include": '#include "UnlitInput.hlsl"',
                                  "body": "return float4(_BaseColor.rgb, 1.0);"}).replace(
    "    SubShader {", '    Properties { _BaseColor ("Colour", Color) = (0.25, 0.5, 0.75, 1) }\n    SubShader {', 1)


@pytest.mark.parametrize("language", corpus.LANGUAGES)
@pytest.mark.parametrize("guard", ["UNIVERSAL_UNLIT_INPUT_INCLUDED", "MY_UNLIT_INPUT_INCLUDED"])
def test_a_vendored_copy_of_a_urp_shaders_include_reads_the_stand_in(tmp_path, language, guard):
    """A copy below a Shaders/ folder with Unity's guard: the stand-in's _BaseColor, the material's
    (0.25, 0.5, 0.75), exactly; with a guard of the project's own (the control) its own text, whose
    #error refuses it."""
    folder = tmp_path / "Assets" / "URP" / "Shaders"
    folder.mkdir(parents=True)
    (folder / "UnlitInput.hlsl").write_text(VENDORED_UNLIT_INPUT % {"guard": guard})
    result = _run(folder / "u.shader", UNLIT_INPUT_SHADER, language)
    if guard.startswith("UNIVERSAL"):
        _assert_exactly(result, GLCORE)
    else:
        assert result.status == "refused" and "the project's copy was compiled" in result.message


# Core RP's API header's precision forms of a texture declaration (API/GLCore.hlsl's
# TEXTURE2D_FLOAT / TEXTURE2D_HALF, a project's copy of URP's CopyDepthPass declares its depth so)
PRECISION_FORMS_SHADER = (URP_PASS % {
    "name": "texture precision forms",
    "include": "TEXTURE2D_FLOAT(_FloatTex); TEXTURE2D_HALF(_HalfTex); SAMPLER(sampler_FloatTex);",
    "body": "return float4(SAMPLE_TEXTURE2D(_FloatTex, sampler_FloatTex, float2(0.5, 0.5)).rgb * float3(0.25, 0.5, 0.75)"
            " + SAMPLE_TEXTURE2D(_HalfTex, sampler_FloatTex, float2(0.5, 0.5)).rgb, 1.0);"}).replace(
    "    SubShader {", '    Properties { _FloatTex ("F", 2D) = "%(float)s" {} _HalfTex ("H", 2D) = "black" {} }\n'
    "    SubShader {", 1)


@pytest.mark.parametrize("language", corpus.LANGUAGES)
@pytest.mark.parametrize("default", ["white", "black"])
def test_the_api_headers_precision_forms_declare_textures(tmp_path, language, default):
    """TEXTURE2D_FLOAT / TEXTURE2D_HALF declare the material's 2D textures: the "white" default
    times (0.25, 0.5, 0.75) plus the "black" one, exactly; the "black" default (the control) gives 0."""
    expected = GLCORE if default == "white" else np.zeros(3)
    _assert_exactly(_run(tmp_path / "t.shader", PRECISION_FORMS_SHADER % {"float": default}, language), expected)
