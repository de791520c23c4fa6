"""The GLSL port's syntax of constructs Unity's compiler takes (issue 34, session 47: causes of
hidden8's refusals, each redone in a minimal built-in shader of ours and drawn in both languages):
a GLSL reserved word as a parameter inside the default-argument overloads the port writes, GLSL's
type names as variables, a Direct3D 11 Texture2DArray, HLSL's scalar splat when choosing among a
program's own overloads, the sign of a bool, a cast to a struct, and ``printf``. Each fragment
returns values computed from the construct, checked on every covered pixel against float64 (the
construct's definition in Microsoft's HLSL reference), with a control that fails without the
change. Readback and tolerance as test_port_round43.py (EXACT: 2 ulp of 1; every value below is
a dyadic fraction, exact in float32). A control's HLSL is typed afresh (program._fxc_spelled
keeps the HLSL pass's text per program text)."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from pbrlab.foundation.errors import PbrlabError
from pbrlab.importers.unity import UnityShaderWarning, cg_types, program, properties, shader_messages, texture_methods
from test_port_round43 import LANGUAGES, _assert_colour, _shader
from test_unity_names_round5 import _render  # pytest puts this folder on sys.path

SHADERS = Path(__file__).parent / "shaders" / "s47-port"

# --- 1. GLSL's reserved words in the overloads the port writes for default arguments -------------
RESERVED_HEAD = """
        struct output { float3 c; };
        output shade(output input, float sample = 0.5, float filter = 0.25, float resource = 1) {
            float common = input.c.x + sample; output o; o.c = float3(common, filter, input.c.z) * resource; return o; }
        float smooth(float partition, float active = 1, float superp = 0, float lowp = 0) { return partition * active + superp + lowp; }"""
RESERVED_BODY = """
            output o; o.c = float3(0.25, 0.5, 0.125);
            float3 c = shade(o).c;
            return float4(c.x, c.y * smooth(2.0), c.z, 1);"""


@pytest.mark.parametrize("language", LANGUAGES)
def test_reserved_words_in_a_default_argument_overload_are_renamed(tmp_path, language, monkeypatch):
    """HLSL reserves none of these names (Microsoft's HLSL reference, "Keywords"); GLSL 3.30
    does (section 3.6: input, output, sample, filter, common, partition, active, superp,
    resource, lowp). shade(o) with its defaults: common = 0.25 + 0.5, (0.75, 0.25, 0.125) * 1;
    smooth(2.0) = 2 * 1 + 0 + 0: (0.75, 0.5, 0.125). Control: the overloads written with the
    names as the program spells them (cg_types.renamed_reserved the identity), GLSL refuses
    "illegal use of reserved word" (the HLSL as written has no such overloads)."""
    _assert_colour(tmp_path, _shader(tmp_path, "reserved", RESERVED_BODY, head=RESERVED_HEAD), language,
                   [0.75, 0.5, 0.125])
    if language == "glsl":
        monkeypatch.setattr(cg_types, "renamed_reserved", lambda text: text)
        with pytest.raises(PbrlabError, match="reserved word"):
            _render(tmp_path, _shader(tmp_path, "reserved_old", RESERVED_BODY, head=RESERVED_HEAD), language)


# a GLSL built-in function the port writes in the program's own scope (not() for HLSL's !v)
NOT_BODY = """
            float not = 0.25;
            float2 s = float2(0.5, 2.0);
            bool2 nb = !(s > 1.0);
            return float4(not, nb.x ? 0.5 : 0.0, nb.y ? 0.5 : 0.125, 1);"""


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_variable_named_as_a_builtin_the_port_writes(tmp_path, language, monkeypatch):
    """``not`` is no HLSL keyword; the port writes HLSL's componentwise !v as GLSL's not(v), which
    a local ``not`` would hide: (0.25, !(0.5 > 1) -> 0.5, !(2 > 1) -> 0.125). Control: ``not``
    taken out of cg_types.RESERVED, GLSL finds no function ``not`` (a float hides it)."""
    _assert_colour(tmp_path, _shader(tmp_path, "not_name", NOT_BODY), language, [0.25, 0.5, 0.125])
    if language == "glsl":
        monkeypatch.setattr(cg_types, "RESERVED", cg_types.RESERVED - {"not"})
        with pytest.raises(PbrlabError):
            _render(tmp_path, _shader(tmp_path, "not_name_old", NOT_BODY), language)


# --- 2. GLSL's type names as a program's variables ------------------------------------------------
TYPE_NAMES_BODY = """
            float2 vec2 = float2(0.25, 0.5);
            float mat4 = 0.125;
            int ivec3 = 2;
            float3 vec3 = float3(vec2, mat4 * ivec3);
            return float4(vec3, 1);"""


@pytest.mark.parametrize("language", LANGUAGES)
def test_glsl_type_names_are_a_programs_variables(tmp_path, language, monkeypatch):
    """vec2, vec3, mat4, ivec3 are GLSL 3.30's type names (section 3.6) and no HLSL keyword:
    (0.25, 0.5, 0.125 * 2). Control: without them among the names renamed (cg_types.RESERVED
    for the port, GLSLANG_HLSL_RESERVED for glslang's HLSL front end, whose keyword table holds
    vec2..vec4 and mat2..mat4), each compiler refuses the declaration."""
    _assert_colour(tmp_path, _shader(tmp_path, "type_names", TYPE_NAMES_BODY), language, [0.25, 0.5, 0.25])
    monkeypatch.setattr(cg_types, "RESERVED", cg_types.RESERVED - cg_types.GLSL_TYPE_NAMES)
    monkeypatch.setattr(cg_types, "GLSLANG_HLSL_RESERVED", frozenset({"char"}))
    program._fxc_spelled.cache_clear()
    with pytest.raises(PbrlabError):
        _render(tmp_path, _shader(tmp_path, "type_names_old", TYPE_NAMES_BODY), language)


# --- 3. Direct3D 11's Texture2DArray --------------------------------------------------------------
@pytest.mark.parametrize("language", LANGUAGES)
def test_a_texture2darray_object_is_sampled_through_its_methods(tmp_path, language, monkeypatch):
    """texture_array_methods.shader: Sample and SampleLevel of a Texture2DArray at (uv, layer)
    (Microsoft's HLSL reference, "Texture2DArray"); the property's "gray" fills the array's one
    layer (texture_arrays.py), a float texel: (gray.r * 0.5, gray.g, 0.25). Control: the port
    without the 2D array among its texture objects (texture_methods._COMBINED) refuses it."""
    gray = properties.DEFAULT_TEXELS["gray"]
    want = [gray[0] * 0.5, gray[1], 0.25]
    _assert_colour(tmp_path, SHADERS / "texture_array_methods.shader", language, want)
    if language == "glsl":
        monkeypatch.setattr(texture_methods, "_COMBINED", {k: v for k, v in texture_methods._COMBINED.items()
                                                           if k != "Texture2DArray"})
        old = tmp_path / "texture_array_methods_old.shader"  # (a scene reads a shader file once)
        old.write_text((SHADERS / "texture_array_methods.shader").read_text())
        with pytest.raises(PbrlabError, match="unknown method"):
            _render(tmp_path, old, language)


# --- 4. HLSL's scalar splat choosing among a program's own overloads ------------------------------
OVERLOAD_HEAD = """
        float2 wrap(float2 x, float2 y) { return x - y * floor(x / y); }
        float3 wrap(float3 x, float3 y) { return x - y * floor(x / y); }
        float4 wrap(float4 x, float4 y) { return x - y * floor(x / y); }"""
OVERLOAD_BODY = """
            float3 v = float3(2.5, 3.25, -0.5);
            return float4(wrap(v, 2.0) * 0.5, 1);"""


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_scalar_argument_is_splatted_to_the_overload_hlsl_chooses(tmp_path, language, monkeypatch):
    """wrap(v3, 2.0): HLSL splats the scalar and picks the float3 overload (exact for v3; the
    float2 one would truncate v3, the float4 one cannot take it: clang's HLSL conversion
    ranks), ShaderToy's mod x - y * floor(x / y) per component, halved. Control: without the
    ranked choice (cg_types._best_converted) the port leaves the call as written and GLSL finds
    no overload of (vec3, float)."""
    want = [0.5 * (x - 2.0 * math.floor(x / 2.0)) for x in (2.5, 3.25, -0.5)]
    _assert_colour(tmp_path, _shader(tmp_path, "splat", OVERLOAD_BODY, head=OVERLOAD_HEAD), language, want)
    if language == "glsl":
        monkeypatch.setattr(cg_types, "_best_converted", lambda sigs, args: None)
        with pytest.raises(PbrlabError, match="no matching function"):
            _render(tmp_path, _shader(tmp_path, "splat_old", OVERLOAD_BODY, head=OVERLOAD_HEAD), language)


# --- 5. the sign of a bool ------------------------------------------------------------------------
BOOL_SIGN_BODY = """
            bool b = i.uv.x < 2.0;
            float n = -b;
            float p = +b;
            int k = -b + 3;
            return float4(n + 1.25, p * 0.5, k * 0.25, 1);"""


@pytest.mark.parametrize("language", LANGUAGES)
def test_the_sign_of_a_bool_is_an_int(tmp_path, language, monkeypatch):
    """b is true on the whole sphere (uv.x <= 1): HLSL promotes a bool operand of - and + to int
    (C++'s integral promotion, which DXC's clang keeps; glslang's HLSL converts bool operands of
    arithmetic to int), so -b = -1, +b = 1: (-1 + 1.25, 0.5, (3 - 1) * 0.25). Control: without
    the conversion (cg_types._Parser.bool_sign the operand's type, nothing written) both
    compilers refuse the bool operand."""
    _assert_colour(tmp_path, _shader(tmp_path, "bool_sign", BOOL_SIGN_BODY), language, [0.25, 0.5, 0.5])
    monkeypatch.setattr(cg_types._Parser, "bool_sign", lambda self, x: x.t)
    program._fxc_spelled.cache_clear()
    with pytest.raises(PbrlabError):
        _render(tmp_path, _shader(tmp_path, "bool_sign_old", BOOL_SIGN_BODY), language)


# --- 6. a cast to a struct ------------------------------------------------------------------------
STRUCT_CAST_HEAD = """
        struct VertexOutput { float4 a : TEXCOORD1; float w[2] : TEXCOORD2; int k : TEXCOORD4; };
        VertexOutput make(float x) {
            VertexOutput o = (VertexOutput)1.5;
            o.a.x = x;
            VertexOutput p = (VertexOutput)o;
            return (VertexOutput)(p);
        }"""
STRUCT_CAST_BODY = """
            VertexOutput o = make(0.25);
            return float4(o.a.x, o.a.y * 0.25, o.w[1] * o.k * 0.5, 1);"""


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_cast_to_a_struct(tmp_path, language, monkeypatch):
    """(S)1.5 fills every component of every member with 1.5 converted to its type (Microsoft's
    HLSL reference, "Casting and conversions": scalar to structure; float to int truncates:
    k = 1); (S)o of an S is o. (0.25, 1.5 * 0.25, 1.5 * 1 * 0.5). Control: the casts left as
    written (cg_types._Parser.struct_cast reads none), GLSL refuses ``(VertexOutput)`` as a
    constructor without arguments."""
    _assert_colour(tmp_path, _shader(tmp_path, "struct_cast", STRUCT_CAST_BODY, head=STRUCT_CAST_HEAD), language,
                   [0.25, 0.375, 0.75])
    if language == "glsl":
        monkeypatch.setattr(cg_types._Parser, "struct_cast", lambda self, cast: None)
        with pytest.raises(PbrlabError):
            _render(tmp_path, _shader(tmp_path, "struct_cast_old", STRUCT_CAST_BODY, head=STRUCT_CAST_HEAD), language)


# the zero of a struct whose members a macro of the program's declares, and a scalar cast to a
# struct holding a matrix, a nested struct and an array of them
MACRO_MEMBERS_HEAD = """
        struct Inner { float2 p; float q[2]; };
        #define EXTRA_MEMBERS float4 e1; float e2;
        struct WithMacro { float x; EXTRA_MEMBERS };
        struct Big { float a, b; Inner arr[2]; float3x3 m; };"""
MACRO_MEMBERS_BODY = """
            WithMacro w = (WithMacro)0;
            Big h = (Big)0.25;
            return float4(w.x + w.e1.x + w.e2 + 0.5, h.m[1][2], h.arr[1].q[0] + h.b, 1);"""


@pytest.mark.parametrize("language", LANGUAGES)
def test_struct_zero_and_scalar_casts_construct_every_member(tmp_path, language, monkeypatch):
    """(WithMacro)0 zeroes the members EXTRA_MEMBERS declares too; (Big)0.25 puts 0.25 in every
    element, a matrix's off-diagonal ones included (HLSL's scalar-to-matrix replicates; GLSL's
    mat3(x) would fill the diagonal only): (0 + 0.5, 0.25, 0.25 + 0.25). Control: the macro's
    members unknown (cg_types._Parser.own_macro_members None), GLSL refuses the constructor
    ("insufficient parameters in constructor")."""
    _assert_colour(tmp_path, _shader(tmp_path, "macro_members", MACRO_MEMBERS_BODY, head=MACRO_MEMBERS_HEAD),
                   language, [0.5, 0.25, 0.5])
    if language == "glsl":
        monkeypatch.setattr(cg_types._Parser, "own_macro_members", lambda self, macro: None)
        with pytest.raises(PbrlabError, match="insufficient parameters"):
            _render(tmp_path, _shader(tmp_path, "macro_members_old", MACRO_MEMBERS_BODY, head=MACRO_MEMBERS_HEAD),
                    language)


# --- 7. printf ------------------------------------------------------------------------------------
PRINTF_BODY = """
            float v = 0.25;
            printf("v = %f (of %d)", v, 2);
            return float4(v, 0.5, 0.125, 1);"""


@pytest.mark.parametrize("language", LANGUAGES)
def test_printf_is_dropped_with_a_warning_naming_its_line(tmp_path, language, monkeypatch):
    """Microsoft's HLSL reference, "printf function": a message to Direct3D's information queue
    (Shader Model 4 on) that does nothing where the device has none; the pixels are the
    fragment's (0.25, 0.5, 0.125), and a warning names the call's line in the shader file.
    Control: the call kept (shader_messages._PRINTF matching nothing),
    GLSL refuses the string and spirv-cross glslang's debug printf."""
    shader = _shader(tmp_path, "printf", PRINTF_BODY)
    line = 1 + next(k for k, text in enumerate(shader.read_text().splitlines()) if "printf(" in text)
    with pytest.warns(UnityShaderWarning, match=rf"printf\.shader:{line}: printf dropped"):
        _assert_colour(tmp_path, shader, language, [0.25, 0.5, 0.125])
    monkeypatch.setattr(shader_messages, "_PRINTF", __import__("re").compile(r"(?!x)x"))
    with pytest.raises(PbrlabError):
        _render(tmp_path, _shader(tmp_path, "printf_old", PRINTF_BODY), language)


def test_printf_inside_a_string_or_comment_is_left():
    """Only a ``printf(...);`` statement is blanked, its lines kept; one in a comment is text."""
    program = 'float f() {\n  // printf("x");\n  printf("a(b)%d",\n   1);\n  return 1; }\n'
    out, dropped = shader_messages.dropped_printf_calls(program, Path("p.shader"), 10)
    assert out.count("\n") == program.count("\n") and "// printf" in out and 'printf("a' not in out
    assert dropped == [d for d in dropped if d.startswith("p.shader:12: printf dropped")] and len(dropped) == 1
