"""Two Cg forms of Unity's own CubeBlur.shader the GLSL port did not read (it was pinned as a
compiler's error): HLSLSupport.cginc's flow-control hints before a statement (`UNITY_UNROLL for
(...)`), which hid the function from the Cg type pass (its `0.5h` literals reached GLSL), and a
vector constant written as an object-like macro (`#define one half3(1., 1., 1.)`), whose
comparison `abs(v) == one` is componentwise in HLSL and must be `equal(...)` in GLSL."""

from __future__ import annotations

from pbrlab.importers.unity import cg_spellings, port

_LOOP = """half4 frag(float4 p : TEXCOORD0) : SV_Target {
    half s = 0.0h;
    UNITY_UNROLL for (int i = 0; i < 2; i++) { s += (half(i) + 0.5h); }
    UNITY_BRANCH if (s > 1.0h) { s = 1.0h; }
    return half4(s, s, s, 1);
}"""


def test_flow_hints_are_blanked_in_place_and_the_function_is_ported():
    spelled = cg_spellings.respelled(_LOOP)
    assert "UNITY_" not in spelled and len(spelled) == len(_LOOP)  # offsets kept
    glsl = port.port_text(_LOOP)
    assert "0.5h" not in glsl and "1.0h" not in glsl and "(float(i) + 0.5f)" in glsl  # (cg_spellings spells 0.5h 0.5f)


def test_a_hint_written_as_unrollx_is_blanked_too():
    text = "void f() { UNITY_UNROLLX(4) for (int i = 0; i < 4; i++) {} }"
    assert cg_spellings.respelled(text) == "void f() { " + " " * len("UNITY_UNROLLX(4)") + " for (int i = 0; i < 4; i++) {} }"


_CONSTANTS = """#define zero half3(0., 0., 0.)
#define one half3(1., 1., 1.)
half3 face(float3 uvw) { return lerp(zero, uvw, abs(uvw) == one); }"""


def test_a_vector_macro_constant_compares_componentwise():
    glsl = port.port_text(_CONSTANTS)
    assert "equal(abs(uvw), one)" in glsl


def test_a_macro_that_is_no_constructor_is_not_typed():
    """Control: a macro whose body calls a function (no type's constructor) has no known type,
    so the comparison is left as written."""
    glsl = port.port_text(_CONSTANTS.replace("#define one half3(1., 1., 1.)", "#define one make_one(1.)"))
    assert "abs(uvw) == one" in glsl
