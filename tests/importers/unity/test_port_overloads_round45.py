"""User functions of real Unity shaders (issue 34's hidden4/hidden2 samples, session 45: measured,
not committed) that FXC accepts and pbrlab refused, each in a minimal shader of ours drawn in both
languages; the fragment's colour is checked on every covered pixel against float64 (HLSL's
definition: Microsoft's HLSL reference), with a control (the old behaviour restored) that the
check rejects.

Readback and tolerance as test_port_round43.py: EXACT is 2 ulp of 1 (every expected value below
is a sum of products of dyadic fractions, exact in float32)."""

from __future__ import annotations

import numpy as np
import pytest

from pbrlab.foundation.errors import PbrlabError
from pbrlab.importers.unity import cg_types, generate_pass, written_globals
from test_port_round43 import LANGUAGES, _assert_colour, _shader
from test_unity_names_round5 import _render  # pytest puts this folder on sys.path

# qieqie22's Fur.shader: ``FragmentSetup(inout float4 i_tex, ..., float4 tangentToWorld[3], ...,
# half facing = 1)`` called without ``facing`` through a macro: the shorter overload's array
# parameter lost its length
DEFAULTED_HEAD = """
        float3 weigh(float4 rows[2], half scale = 1, half2 bias = 0)
        {
            return rows[0].xyz * scale + rows[1].xyz + float3(bias, 0);
        }"""
DEFAULTED_BODY = """
            float4 rows[2];
            rows[0] = float4(0.25, 0.5, 0.125, 0);
            rows[1] = float4(0.125, 0, 0.25, 0);
            return float4(weigh(rows) + weigh(rows, 2) * 0.25, 1);"""


def _defaulted_expected():
    """HLSL's default arguments: weigh(rows) is weigh(rows, 1, 0) (the int 1 converted to half,
    the scalar 0 splatted to half2)."""
    r0, r1 = np.array([0.25, 0.5, 0.125]), np.array([0.125, 0.0, 0.25])
    return (r0 * 1 + r1) + (r0 * 2 + r1) * 0.25


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_default_argument_after_an_array_parameter(tmp_path, language, monkeypatch):
    """The port's shorter overloads (GLSL has no default arguments) declare the array parameter
    with its length, so they match the call and forward to the full function: (0.53125, 0.75,
    0.5). (The int 1 for the half parameter needs nothing: GLSL from 1.20 converts an int
    argument to a float parameter.) Control: the parameter declared without its length, as
    before, and the GLSL port is refused ("no matching function for call to weigh(...)", the
    Fur.shader refusal); glslang's HLSL front end took it already."""
    _assert_colour(tmp_path, _shader(tmp_path, "defaulted", DEFAULTED_BODY, DEFAULTED_HEAD), language,
                   _defaulted_expected())
    if language == "glsl":
        monkeypatch.setattr(cg_types, "written_parameter", lambda text, start, name_end, end: text[start:name_end])
        with pytest.raises(PbrlabError, match="weigh"):
            _render(tmp_path, _shader(tmp_path, "defaulted_old", DEFAULTED_BODY, DEFAULTED_HEAD), language)


# yunyufeiwei's fog.shader (a ShaderToy port): ``#define vec2 float2``, a global ``vec2 bsMo``
# written in the program's own ``vec4 main(vec2 fragCoord)``, declared (a prototype) before the
# fragment function that calls it and defined after it (a URP pass: HLSLPROGRAM, Core.hlsl)
SHADERTOY = """
Shader "t/{name}" {{
    SubShader {{ Tags {{ "RenderPipeline"="UniversalPipeline" }} Pass {{
        HLSLPROGRAM
        #pragma vertex vert
        #pragma fragment frag
        #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
        #define vec2 float2
        #define vec4 float4
        #define PROGRAM_OF_{name}  // each shader's own program text (the port caches by text)
        vec2 bias = vec2(0, 0);
        struct v2f {{ float4 pos : SV_POSITION; }};
        v2f vert(float4 vertex : POSITION) {{ v2f o; o.pos = TransformObjectToHClip(vertex.xyz); return o; }}
        vec4 main(vec2 p);
        float4 frag(v2f i) : SV_Target {{
            float4 c = main(float2(0.5, 0.25));
            return c + float4(bias, 0, 0);
        }}
        vec4 main(vec2 p) {{
            bias = p * 0.5;
            return vec4(bias, 0.25, 1);
        }}
        ENDHLSL
    }} }}
}}
"""


def _shadertoy(tmp_path, name):
    path = tmp_path / f"{name}.shader"
    path.write_text(SHADERTOY.format(name=name))
    return path


def _shadertoy_expected():
    """FXC's backwards-compatibility mode (Unity's): a non-static global is a uniform (unset: 0)
    the invocation may write, the value written read after it; ``main`` is a function like any
    other (the entry points are the pragmas'). main(0.5, 0.25) writes bias = (0.25, 0.125) and
    returns (0.25, 0.125, 0.25); the fragment adds bias."""
    bias = np.array([0.5, 0.25]) * 0.5
    return [bias[0] * 2, bias[1] * 2, 0.25]


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_function_named_main_writing_a_global_of_a_defined_type(tmp_path, language, monkeypatch):
    """(0.5, 0.25, 0.25): the program's ``main`` renamed in both languages (GLSL's entry point,
    and pbrlab's HLSL entry's name), the global typed by the program's #define copied as a
    written global (written_globals). Control: the type alias not read, as before, and both
    languages refuse the write ("assignment to read-only variable 'bias'" / "can't modify a
    uniform"); ``main`` not renamed, and both refuse it ("main() must return void" in the GLSL
    port; glslang's HLSL front end finds no body for main's prototype)."""
    _assert_colour(tmp_path, _shadertoy(tmp_path, "shadertoy"), language,
                   _shadertoy_expected())
    with monkeypatch.context() as patched:
        patched.setattr(written_globals, "_declarations", lambda active_program: written_globals._DECLARED)
        with pytest.raises(PbrlabError, match="bias|uniform"):
            _render(tmp_path, _shadertoy(tmp_path, "shadertoy_alias_old"), language)
    old_reserved = cg_types.is_reserved
    patched_reserved = {"glsl": ("is_reserved", lambda name: name != "main" and old_reserved(name)),
                        "hlsl": ("GLSLANG_HLSL_FUNCTION_NAMES", frozenset())}[language]
    monkeypatch.setattr(cg_types, *patched_reserved)
    with pytest.raises(PbrlabError, match="main"):
        _render(tmp_path, _shadertoy(tmp_path, "shadertoy_main_old"), language)


MAIN_ENTRY = """
Shader "t/{name}" {{
    SubShader {{ Pass {{
        CGPROGRAM
        #pragma vertex vert
        #pragma fragment main
        #include "UnityCG.cginc"
        #define PROGRAM_OF_{name}
        struct v2f {{ float4 pos : SV_POSITION; }};
        v2f vert(float4 vertex : POSITION) {{ v2f o; o.pos = UnityObjectToClipPos(vertex); return o; }}
        float4 main(v2f i) : SV_Target {{ return float4(0.5, 0.25, 0.125, 1); }}
        ENDCG
    }} }}
}}
"""


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_fragment_entry_named_main(tmp_path, language, monkeypatch):
    """``#pragma fragment main``: the entry's call uses the name the port gives the program's
    ``main`` (cg_types.ported_function_name), so its constant (0.5, 0.25, 0.125) is drawn.
    Control: the call by the name as written finds no such function in either language."""
    def shader(name):
        path = tmp_path / f"{name}.shader"
        path.write_text(MAIN_ENTRY.format(name=name))
        return path

    _assert_colour(tmp_path, shader("main_entry"), language, [0.5, 0.25, 0.125])
    monkeypatch.setattr(generate_pass, "ported_function_name", lambda name, language: name)
    with pytest.raises(PbrlabError, match="main"):
        _render(tmp_path, shader("main_entry_old"), language)


MAIN_MEMBER = """
Shader "t/{name}" {{
    SubShader {{ Pass {{
        CGPROGRAM
        #pragma vertex vert
        #pragma fragment frag
        #include "UnityCG.cginc"
        #define PROGRAM_OF_{name}
        struct v2f {{ float4 pos : SV_POSITION; float2 main : TEXCOORD0; }};
        v2f vert(float4 vertex : POSITION) {{
            v2f o; o.pos = UnityObjectToClipPos(vertex); o.main = float2(0.5, 0.25); return o; }}
        float4 frag(v2f i) : SV_Target {{ float main = 0.125; return float4(i.main, main, 1); }}
        ENDCG
    }} }}
}}
"""


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_member_and_a_local_named_main(tmp_path, language, monkeypatch):
    """A varying and a local named ``main`` are names like any other in HLSL: (0.5, 0.25, 0.125)
    in both languages (the GLSL port renames them with every GLSL-reserved name; the HLSL as
    written renames ``main`` only as a function's name). Control: ``main`` renamed as every
    name in the HLSL as written, and glslang finds no field ``main`` in the pass's struct (the
    entry point reads it by its name)."""
    def shader(name):
        path = tmp_path / f"{name}.shader"
        path.write_text(MAIN_MEMBER.format(name=name))
        return path

    _assert_colour(tmp_path, shader("main_member"), language, [0.5, 0.25, 0.125])
    if language == "hlsl":
        monkeypatch.setattr(cg_types, "GLSLANG_HLSL_RESERVED", frozenset({"char", "main"}))
        with pytest.raises(PbrlabError, match="main"):
            _render(tmp_path, shader("main_member_old"), language)


# A default before a parameter without one (session 46: the port raised a TypeError building the
# shorter overloads of such a head; a call may leave out only a trailing run of defaulted
# parameters, so there is no shorter form to build)
EARLY_DEFAULT_HEAD = """
        float3 tint(float3 c, half s = 2, float3 add)
        {
            return c * s + add;
        }"""
EARLY_DEFAULT_BODY = """
            return float4(tint(float3(0.25, 0.125, 0.5), 0.5, float3(0.125, 0.25, 0)), 1);"""


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_default_before_a_parameter_without_one(tmp_path, language):
    """The full call draws c * s + add = (0.25, 0.3125, 0.25) where the compiler takes the head,
    or the compiler's refusal names the line; never a traceback (the old port's TypeError, which
    no PbrlabError catches, fails this test)."""
    shader = _shader(tmp_path, "early_default", EARLY_DEFAULT_BODY, EARLY_DEFAULT_HEAD)
    try:
        _assert_colour(tmp_path, shader, language, np.array([0.25, 0.3125, 0.25]))
    except PbrlabError as error:
        assert "early_default" in str(error) and "default" in str(error).lower(), str(error)
