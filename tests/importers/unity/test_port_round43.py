"""Constructs of real built-in-pipeline shaders (issue 34's samples, session 43: measured, not
committed) that one language rendered and the other refused, each in a minimal shader of ours,
drawn in both languages; the fragment returns a constant or a value computed from the
construct, checked on every covered pixel against float64 (HLSL's definition of the construct:
Microsoft's HLSL reference, C99's preprocessor), with the old behaviour as the control.

Readback as test_cg_dialect_round4.py: the corpus scene's ``linear`` image is the fragment's
colour (alpha the coverage)."""

from __future__ import annotations

import textwrap

import numpy as np
import pytest

from pbrlab.foundation.errors import PbrlabError
from pbrlab.importers.unity import conditionals, parse_pass, program
from pbrlab.importers.unity.port import port_text
from test_unity_names_round5 import _covered, _render  # pytest puts this folder on sys.path

LANGUAGES = ("glsl", "hlsl")
# float32 rounding of the few operations the constants below go through (each exact in binary
# but for 1/3-style quotients): 2 ulp of 1
EXACT = 2.5e-7

PASS = """
Shader "t/{name}" {{
    SubShader {{ Pass {{
        CGPROGRAM
        #pragma vertex vert
        #pragma fragment frag
        #include "UnityCG.cginc"
{head}
        struct v2f {{ float4 pos : SV_POSITION; float2 uv : TEXCOORD0;{members} }};
        v2f vert(float4 vertex : POSITION, float2 uv : TEXCOORD0) {{
            v2f o; o.pos = UnityObjectToClipPos(vertex); o.uv = uv;{vertex} return o; }}
        {fragment_return} frag(v2f i) : SV_Target {{
{body}
        }}
        ENDCG
    }} }}
}}
"""


def _shader(tmp_path, name, body, head="", members="", vertex="", fragment_return="float4", encoding="utf-8"):
    path = tmp_path / f"{name}.shader"
    text = textwrap.dedent(PASS.format(name=name, head=head, members=members, vertex=vertex, body=body,
                                       fragment_return=fragment_return))
    path.write_bytes(text.encode(encoding))
    return path


def _covered_rgb(image):
    return image[_covered(image), :3].astype(np.float64)


def _assert_colour(tmp_path, shader, language, want):
    rgb = _covered_rgb(_render(tmp_path, shader, language))
    assert np.abs(rgb - np.asarray(want, np.float64)).max() <= EXACT


# A project's macro that declares a varying with a semantic pasted from its parameter, defined
# per pass under #ifdef/#elif (sindharta's SinForwardLight.cginc's form): the member is the
# vertex stage's output in Unity; the port strips the pasted semantic from the macro's text.
MEMBER_MACRO_HEAD = """
        #define MY_PASS_BASE
        #ifdef MY_PASS_BASE
            #define MY_TINT_COORDS(idx) float3 tint : TEXCOORD##idx;
        #elif defined(MY_PASS_ADD)
            #define MY_TINT_COORDS(idx)
        #endif"""


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_macro_member_with_a_pasted_semantic_is_a_varying(tmp_path, language, monkeypatch):
    """The vertex stage's value (0.25, 0.5, 0.75) reaches the fragment through the macro's
    member. Control: read as before (the macro's member no varying of the pass model's, and a
    #define of the branch not taken still seen) it is not carried (HLSL zeroes the struct:
    black; GLSL: the member undefined), or the GLSL port refused the semantic."""
    shader = _shader(tmp_path, "member_macro", "            return float4(i.tint, 1);", MEMBER_MACRO_HEAD,
                     " MY_TINT_COORDS(3)", " o.tint = float3(0.25, 0.5, 0.75);")
    _assert_colour(tmp_path, shader, language, [0.25, 0.5, 0.75])
    monkeypatch.setattr(parse_pass, "expanded_member_macros", lambda body, text: body)
    shader = _shader(tmp_path, "member_macro_old", "            return float4(i.tint, 1);", MEMBER_MACRO_HEAD,
                     " MY_TINT_COORDS(3)", " o.tint = float3(0.25, 0.5, 0.75);")
    try:
        rgb = _covered_rgb(_render(tmp_path, shader, language))
    except PbrlabError:
        return
    assert np.abs(rgb - [0.25, 0.5, 0.75]).max() > 0.1


def test_a_define_in_a_branch_not_taken_is_blanked():
    """The drawn variant's text holds only the definition its branch takes (offsets kept);
    control: the taken branch's definition stays."""
    text = "#ifdef A\n#define M(i) float3 x : TEXCOORD##i;\n#else\n#define M(i)\n#endif\n"
    active = conditionals.active_text(text, {})
    assert len(active) == len(text)
    assert "TEXCOORD" not in active and "#define M(i)\n" in active


@pytest.mark.parametrize("language", LANGUAGES)
def test_comments_beside_semantics_and_a_shift_jis_nel_byte(tmp_path, language):
    """A comment between a semantic and the ``)`` or ``;`` that ends its declaration, or between
    a fragment's return semantic and its body, and a Shift-JIS comment holding byte 0x85 (the
    trail byte of "ュ", Latin-1's NEL: Python's splitlines broke the line there): the GLSL port
    refused each ("unexpected ':'", "unexpected end of file"); both languages draw the colour
    the next lines compute."""
    path = tmp_path / "comments.shader"
    text = textwrap.dedent("""
        Shader "t/comments" { SubShader { Pass {
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "UnityCG.cginc"
            struct v2f { float4 pos : SV_POSITION /* clip */; float2 uv : TEXCOORD0; };
            v2f vert(float4 vertex : POSITION, // position
                     float2 uv : TEXCOORD0 // texture coordinate
            ) { v2f o; o.pos = UnityObjectToClipPos(vertex); o.uv = uv; return o; }
            float4 frag(v2f i) : SV_Target // a note on the signature's line
                                           // and one more
            {
                // SJIS
                float3 c = float3(0.125, 0.375, 0.625);
                return float4(c, 1);
            }
            ENDCG
        } } }
    """).encode("utf-8").replace("SJIS".encode(), "スペキュラ".encode("shift_jis"))
    assert b"\x85" in text
    path.write_bytes(text)
    _assert_colour(tmp_path, path, language, [0.125, 0.375, 0.625])


@pytest.mark.parametrize("language", LANGUAGES)
def test_include_without_a_blank_and_a_literal_swizzle_after_a_comment(tmp_path, language):
    """``#include"file"`` (the C preprocessor and FXC take it; the GLSL path's reader did not
    see an include) and ``/*c*/0.25.xxx`` (a literal's swizzle right after a comment: the port
    left float3 unrenamed). Colour: the include's 0.5 times the splat 0.25 plus 0.125."""
    (tmp_path / "half_of.cginc").write_text("float half_of(float x) { return 0.5 * x; }\n")
    body = "            return float4(half_of(1.0) * /*c*/0.25.xxx + 0.125, 1);"
    shader = _shader(tmp_path, "include", body, '        #include"half_of.cginc"')
    _assert_colour(tmp_path, shader, language, [0.25, 0.25, 0.25])


@pytest.mark.parametrize("language", LANGUAGES)
def test_an_own_overload_of_a_built_in_name(tmp_path, language):
    """A program's own ``cross`` of five parameters beside calls of the intrinsic cross(float3,
    float3): HLSL picks by the arguments (a user function overloads an intrinsic); GLSL hides
    every built-in of a name the shader declares, so the port renames the program's own. Red:
    the own function's 0.5 r + w + e; green, blue: the intrinsic's cross product's y and z
    (numpy's cross, float64). The GLSL port refused it ("no matching function for call to
    cross(vec3, vec3)")."""
    head = """
        float cross(float2 p, float2 c, float r, float w, float e) { return 0.5 * r + w + e + 0 * dot(p, c); }"""
    body = """
            float3 k = cross(float3(0.5, 0.25, 0), float3(0, 0.5, 0.5));
            return float4(cross(i.uv, i.uv, 0.5, 0.125, 0.0625), k.y, k.z, 1);"""
    want = [0.5 * 0.5 + 0.125 + 0.0625, *np.cross([0.5, 0.25, 0.0], [0.0, 0.5, 0.5])[1:]]
    _assert_colour(tmp_path, _shader(tmp_path, "own_cross", body, head), language, want)


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_uint_modulo_assigned_an_int_and_a_struct_named_output(tmp_path, language):
    """``u %= 8`` of a uint2 (HLSL converts the int to uint; GLSL 330 refused the mixed
    operands) and a fragment output struct named ``output`` (a word GLSL reserves): 13 % 8 = 5,
    21 % 8 = 5, over 8."""
    head = "        struct output { float4 col : SV_Target; };"
    body = """
            uint2 u = uint2(13, 21);
            u %= 8;
            output o;
            o.col = float4(u.x / 8.0, u.y / 16.0, 0.25, 1);
            return o;"""
    shader = _shader(tmp_path, "modulo", body, head, fragment_return="output").read_text()
    path = tmp_path / "modulo.shader"
    path.write_text(shader.replace("output frag(v2f i) : SV_Target", "output frag(v2f i)"))
    _assert_colour(tmp_path, path, language, [5 / 8, 5 / 16, 0.25])


FORWARDING_HEAD = """
        float my_half(float x) { return 0.5 * x; }
        #define MY_HALF(x) my_half(x)"""


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_forwarding_macro_has_its_functions_type(tmp_path, language):
    """A macro that forwards its parameters to a function (URP's SHADERGRAPH_SAMPLE_SCENE_DEPTH
    -> a float function) is a float: ``(MY_HALF(0.5)).xxx`` swizzles it and ``float4 v =
    MY_HALF(1.0)`` splats it, as FXC does (the GLSL port refused both: "cannot access field
    xxx of non-structure", "initializer of type float")."""
    body = """
            float4 v = MY_HALF(1.0);
            return float4((MY_HALF(0.5)).xxx * v.w + float3(0, 0.125, 0.25), 1);"""
    _assert_colour(tmp_path, _shader(tmp_path, "forwarding", body, FORWARDING_HEAD), language,
                   [0.125, 0.25, 0.375])


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_multi_element_matrix_swizzle_assigned(tmp_path, language):
    """``m._m00_m10_m20 = v;`` writes column 0's first three rows (HLSL: ``_mRC`` is row R,
    column C); glslang refused the line ("';' : Expected"). The column is read back element
    by element; the other elements stay 0."""
    body = """
            float4x4 m = (float4x4)0;
            m._m00_m10_m20 = float3(0.25, 0.5, 0.75);
            return float4(m._m00, m._m10 + m._m01, m._m20 + m._m22, 1);"""
    _assert_colour(tmp_path, _shader(tmp_path, "swizzle", body), language, [0.25, 0.5, 0.75])


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_one_parameter_macro_called_with_empty_parentheses(tmp_path, language, monkeypatch):
    """``TRANSFER_SHADOW();`` (AutoLight's TRANSFER_SHADOW(a)): one empty argument in C (C99
    6.10.3) and for FXC, so the variant without shadows expands it to nothing; glslang's HLSL
    front end counted no argument ("Too few args in Macro"). Control: the HLSL as written
    without the spelling is refused so."""
    head = '        #include "AutoLight.cginc"'
    body = "            return float4(0.5, 0.25, 0.125, 1);"
    vertex = " TRANSFER_SHADOW();"
    _assert_colour(tmp_path, _shader(tmp_path, "empty_argument", body, head, vertex=vertex), language,
                   [0.5, 0.25, 0.125])
    if language == "hlsl":
        monkeypatch.setattr(program, "empty_arguments_spelled", lambda text, included: text)
        with pytest.raises(PbrlabError, match="Too few args"):
            _render(tmp_path, _shader(tmp_path, "empty_argument_old", body, head, vertex=vertex), language)


def test_the_port_strips_a_pasted_semantic_and_semantics_before_comments():
    """The GLSL port's text: no semantic left (control: the text before the port has them)."""
    source = ("#define C(i) float3 v : TEXCOORD##i;\n"
              "struct s { float4 p : SV_POSITION /* x */; C(2) };\n"
              "float4 f(float4 a : POSITION // y\n) : SV_Target // z\n{ return a; }\n")
    ported = port_text(source)
    assert "TEXCOORD" not in ported and "SV_" not in ported and "POSITION" not in ported
    assert "/* x */" in ported and "// z" in ported
    assert ported.count("\n") == source.count("\n")


SAMPLER_LOCAL = """
Shader "t/sampler_local" {{
    Properties {{ _RampMap ("ramp", 2D) = "{default}" {{}} }}
    SubShader {{ Pass {{
        CGPROGRAM
        #pragma vertex vert
        #pragma fragment frag
        #include "UnityCG.cginc"
        sampler2D _RampMap;
        struct v2f {{ float4 pos : SV_POSITION; }};
        v2f vert(float4 vertex : POSITION) {{ v2f o; o.pos = UnityObjectToClipPos(vertex); return o; }}
        float3 tinted(sampler2D ramp, float3 tint) {{ return tex2D(ramp, float2(0.5, 0.5)).rgb * tint; }}
        float4 frag(v2f i) : SV_Target {{
            sampler2D ramp = _RampMap;
            return float4(tinted(ramp, float3(0.25, 0.5, 0.75)) + 0.125, 1);
        }}
        ENDCG
    }} }}
}}
"""


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_sampler_local_reads_the_global_it_names(tmp_path, language):
    """``sampler2D ramp = _RampMap;`` in a function (Amplify Shader Editor's code): HLSL takes
    it, GLSL declares samplers only as uniforms and parameters (the port refused it). The white
    default's texel times the tint, plus 0.125; control: the black default gives 0.125 alone
    (the local reads the texture)."""
    for default, texel in (("white", 1.0), ("black", 0.0)):
        path = tmp_path / f"sampler_local_{default}.shader"
        path.write_text(textwrap.dedent(SAMPLER_LOCAL.format(default=default)))
        _assert_colour(tmp_path, path, language, texel * np.array([0.25, 0.5, 0.75]) + 0.125)


WRITTEN_ACROSS = """
Shader "t/written_across" {
    Properties { _Angle ("angle", Range(0, 360)) = 90 }
    SubShader { Pass {
        CGPROGRAM
        #pragma vertex vert
        #pragma fragment frag
        #include "UnityCG.cginc"
        float _Angle;
        #include "shapes.cginc"
        struct v2f { float4 pos : SV_POSITION; };
        v2f vert(float4 vertex : POSITION) { v2f o; o.pos = UnityObjectToClipPos(vertex); return o; }
        float4 frag(v2f i) : SV_Target { float a = remapped_angle(); return float4(a, _Angle, 0.125, 1); }
        ENDCG
    } }
}
"""
SHAPES = "float remapped_angle() { _Angle = _Angle / 360.0; return _Angle * 0.5; }\n"


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_global_the_program_declares_and_its_include_writes(tmp_path, language, monkeypatch):
    """Unity compiles with FXC's backwards-compatibility mode, which lets a program write a
    global (written_globals.py): the value written lives in the invocation. Here the program
    declares ``_Angle`` (90) and its own include writes it: red 90 / 360 / 2, green the value
    written (90 / 360) read back in the program. Control: without the copy across files both
    languages refused the write ("assignment to read-only variable", "can't modify a
    uniform")."""
    (tmp_path / "shapes.cginc").write_text(SHAPES)
    path = tmp_path / "written_across.shader"
    path.write_text(textwrap.dedent(WRITTEN_ACROSS))
    _assert_colour(tmp_path, path, language, [0.125, 0.25, 0.125])
    monkeypatch.setattr(parse_pass, "copied_across_includes", lambda program, folder, defines, rewritten, known:
                        (program, rewritten, ()))
    old = tmp_path / "written_across_old.shader"
    old.write_text(textwrap.dedent(WRITTEN_ACROSS))
    with pytest.raises(PbrlabError, match="read-only|uniform"):
        _render(tmp_path, old, language)
