"""What the GLSL port of real URP passes needed beyond the first slices (issue 34): a struct
whose members depend on the preprocessor, zeroed by ``(Struct)0``; HLSL default arguments
holding half literals (``0.5h``); a semantic before an #if line in a parameter list; Core
RP's and URP's include files by their own names (Packing.hlsl, UnityInstancing.hlsl,
ShaderVariablesFunctions.hlsl: pbrlab's stand-ins). Each fails on the main branch before it
(the shader is refused there: no stand-in, then the port's GLSL does not compile); the
control shows the GLSL fails without the zero function."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from pbrlab.foundation.errors import PbrlabError
from pbrlab.importers.unity import cg_types

from test_urp_front_end import SHADERS, _render

CONDITIONAL = SHADERS / "urp_conditional_struct.shader"
# Both renders interpolate the same UVs over the same plane; 0.5 u is exact in float32, so
# the two agree to the last bit (measured: 0.0 in both languages); 1e-6 is the bound the
# other URP front-end tests use for renders computed the same way.
BOUND = 1e-6


@pytest.mark.parametrize("language", ["glsl", "hlsl"])
def test_a_conditional_struct_zeroed_and_defaults_draw_half_u_v_and_zero(language):
    """(0.5 u, v, 0): the half-literal default halves u (rcp(0.5) * 0.5 leaves it), the
    member vert never writes is (Varyings)0's zero, not another branch's layout."""
    got = _render(CONDITIONAL, language)
    want = _render(SHADERS / "urp_uv.shader", language).copy()
    want[..., 0] *= 0.5
    assert (got[..., 3] > 0).all()
    # a gradient (the view spans v from 0.16 to 0.84), not a flat colour; no blue
    assert np.ptp(got[..., 1]) > 0.6 and np.ptp(got[..., 0]) > 0.3 and (got[..., 2] == 0).all()
    assert np.mean(np.abs(got - want) > BOUND) == 0.0


def test_without_the_zero_function_the_glsl_port_fails(monkeypatch, tmp_path):
    """Control: the prototype alone (no body at the end of the file) leaves the GLSL unlinked."""
    monkeypatch.setattr(cg_types._Parser, "_define_conditional_zero",
                        lambda self, name, start, end, members, inside: self.edits.close(end, f" {name} pbr_unity_zero_{name}();"))
    copy = tmp_path / "conditional_struct.shader"
    copy.write_text(CONDITIONAL.read_text())
    with pytest.raises(PbrlabError, match="pbr_unity_zero_Varyings|link|undefined"):
        _render(copy, "glsl")


def test_the_zero_keeps_the_struct_s_if_lines_and_the_enclosing_ones():
    code = ("#ifndef GUARD\n#define GUARD\n#if defined(A)\n#else\n"
            "struct S {\n    float4 p;\n#if B\n    float2 uv;\n#else\n    float3 uv;\n#endif\n"
            "    UNITY_VERTEX_INPUT_INSTANCE_ID\n};\n"
            "S make() { S s = (S)0; return s; }\n#endif\n#endif\n")
    ported = cg_types.convert(code, srp=True)
    lines = ported.splitlines()
    assert lines[12] == "}; S pbr_unity_zero_S();"  # the prototype on the struct's last line
    assert "S s = pbr_unity_zero_S();" in ported
    tail = ported[ported.index("#endif\n#endif\n") + len("#endif\n#endif\n"):]
    # the enclosing #if and its #else (not the include guard), then the members under #if B
    assert tail.split() == ("#if defined(A) #else #ifndef PBR_UNITY_ZERO_S_DEFINED #define PBR_UNITY_ZERO_S_DEFINED "
                            "S pbr_unity_zero_S() { S z; z.p = float4(0.0); #if B z.uv = float2(0.0); #else "
                            "z.uv = float3(0.0); #endif return z; } #endif #endif").split()
    assert len(lines[:16]) == len(code.splitlines())  # the port keeps the original's lines


def test_a_struct_without_if_lines_keeps_its_constructor_zero():
    ported = cg_types.convert("struct T { float a; float2 b; };\nT f() { return (T)0; }\n", srp=True)
    assert "T(0.0, float2(0.0))" in ported and "pbr_unity_zero" not in ported


def test_the_built_in_pipeline_s_port_keeps_its_constructor_zeros():
    """Only SRP programs get the zero functions: a built-in pipeline's struct with an #if keeps
    the port it had (its macro members expand to nothing there)."""
    code = "struct V {\n    float4 p;\n#if A\n    float2 uv;\n#endif\n};\nV f() { return (V)0; }\n"
    assert "pbr_unity_zero" not in cg_types.convert(code)
    assert "pbr_unity_zero_V()" in cg_types.convert(code, srp=True)


def test_a_default_argument_s_half_literal_loses_its_suffix_in_the_overload():
    ported = cg_types.convert("half f(half x, half s = 0.5h) { return x * s; }\n", srp=True)
    assert "f(x, (0.5))" in ported and "0.5h" not in ported


@pytest.mark.parametrize("language", ["glsl", "hlsl"])
def test_a_varying_under_a_pipeline_keyword_reaches_the_fragment_stage(language):
    """URP enables _ADDITIONAL_LIGHTS where a pass declares it; the reader reads the pass's
    structs with it on (parse.URP.keywords), so the varying under ``#ifdef _ADDITIONAL_LIGHTS``
    is carried between the stages (before: in neither language, the fragment read 0 in HLSL
    and an undefined value in GLSL). Content: the world position + 0.5 on the plane y = 0
    filling the view: green 0.5 everywhere, red and blue spanning the plane's extent seen."""
    got = _render(SHADERS / "urp_keyword_varying.shader", language)
    assert (got[..., 3] > 0).all()
    assert np.abs(got[..., 1] - 0.5).max() < 1e-6    # y = 0: float32 rounding of 0.5 + ~1e-8
    assert np.ptp(got[..., 0]) > 0.6 and np.ptp(got[..., 2]) > 0.6  # x and z vary across it
    assert got[..., 0].min() > 0.0 and got[..., 0].max() < 1.0      # within the unit plane


MACRO_PARAMS = """#if defined(SM)
#define MASK_PARAM , const half4 shadow_mask
#define MASK_ARG , shadow_mask
#else
#define MASK_PARAM
#define MASK_ARG
#endif
void f(in const float3 p, inout half3 d MASK_PARAM, const half3 albedo = half3(1, 1, 1), float3 o = 0) { d += albedo + o; }
"""
CALLER = "void g() { half3 d = 0; f(float3(0, 0, 0), d MASK_ARG); }\n"


def test_defaults_after_a_parameter_list_macro_forward_what_the_macro_declares():
    """Delt06's ``..., inout half3 spec SHADOW_MASK_PARAM, const half3 albedo = ...``: the shorter
    forms keep the macro and forward its parameters through PBR_UNITY_ARGS_<macro>, defined at
    the end of the file under each #define's own #if lines; the caller's argument macro is read
    past (its ``half3 d = 0`` is still splatted); ``in const`` becomes GLSL's ``const in``; a
    scalar default of a vector parameter is splatted (``float3(0)``)."""
    ported = cg_types.convert(MACRO_PARAMS + CALLER, srp=True)
    assert "half3 d = float3(0)" in ported  # the caller read past its argument macro
    assert "void f(const in float3 p, inout half3 d MASK_PARAM);" in ported  # the prototype, on its line
    tail = ported.split("void g()")[1]
    assert "#if defined(SM)\n#undef PBR_UNITY_ARGS_MASK_PARAM\n#define PBR_UNITY_ARGS_MASK_PARAM , shadow_mask\n#endif" in tail
    assert "#else\n#undef PBR_UNITY_ARGS_MASK_PARAM\n#define PBR_UNITY_ARGS_MASK_PARAM \n#endif" in tail
    assert ("void f(const in float3 p, inout half3 d MASK_PARAM) { f(p, d PBR_UNITY_ARGS_MASK_PARAM, "
            "(half3(1, 1, 1)), (float3(0))); }") in tail
    assert len(ported.split("void g()")[0].splitlines()) == 8  # lines kept up to the caller


@pytest.mark.parametrize("mask", [False, True])
def test_the_forwarding_overloads_compile_in_glsl_with_the_macro_either_way(mask, tmp_path):
    """The port compiles with the macro empty and with it declaring a parameter."""
    import pbrlab
    from pbrlab.importers.unity import port
    code = ("#define SM\n" if mask else "") + MACRO_PARAMS + (
        "float4 pbr_test() { half4 shadow_mask = half4(1, 1, 1, 1); half3 d = 0; f(float3(0, 0, 0), d MASK_ARG); "
        "return float4(d, 1); }\n")
    (tmp_path / "t.glsl").write_text(port.port_text(code, srp=True))
    got = pbrlab.evaluate("pbr_test()", includes=["unity_compat/cg_compat.glsl", "t.glsl"], include_dirs=[tmp_path])
    assert np.asarray(got).tolist() == [1.0, 1.0, 1.0, 1.0]  # d += albedo (1) + o (0)
