"""Constructs of real Unity shaders (issue 34's hidden6 sample, session 45, second round: measured,
not committed) that FXC accepts and the GLSL port refused, each in a minimal shader of ours, drawn
in both languages; the fragment returns values computed from the construct, checked on every
covered pixel against float64 (HLSL's definition: Microsoft's HLSL reference), with a control
(the old behaviour restored) that the check rejects. Readback and tolerance as
test_port_round45.py (EXACT: 2 ulp of 1; every expected value is a sum of dyadic fractions)."""

from __future__ import annotations

import numpy as np
import pytest

from pbrlab.foundation.errors import PbrlabError
from pbrlab.importers.unity import cg_types, port
from test_port_round43 import LANGUAGES, _assert_colour, _shader
from test_unity_names_round5 import _render  # pytest puts this folder on sys.path

FUNCTION_MACRO_HEAD = """
        #include "AutoLight.cginc"
        #define MY_ONE(a) 1.0
        #define MY_SCALED_X(v, k) (v.x * k)
        #define MY_VECTOR(x) float4(x, 0.5, 0.75, 1)"""
FUNCTION_MACRO = """
            float3 shadow = SHADOW_ATTENUATION(i);
            float3 s = MY_ONE(i);
            float3 t = MY_SCALED_X(float2(0.25, 0.5), 0.5);
            float2 w = MY_VECTOR(0.25);
            return float4(shadow * s * 0.25 + t + float3(w, 0), 1);"""


def _function_macro_expected():
    """FXC splats a scalar to the vector it initialises and truncates a longer vector to the
    first components (warning X3206, Microsoft's HLSL reference "Implicit conversions");
    SHADOW_ATTENUATION without a shadow map is 1 (Unity's AutoLight.cginc, no SHADOWS_* keyword)."""
    shadow, s, t = np.ones(3), np.ones(3), np.full(3, 0.25 * 0.5)
    w = np.array([0.25, 0.5, 0.75, 1.0])[:2]
    return shadow * s * 0.25 + t + np.array([w[0], w[1], 0.0])


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_function_like_macro_has_its_bodys_type(tmp_path, language, monkeypatch):
    """``float3 shadow = SHADOW_ATTENUATION(i);`` (Goligoly's MyPBR shaders; the port's library
    defines ``SHADOW_ATTENUATION(a)`` as ``1.0``): a use of a function-like macro of one
    expression has the body's type with its arguments' types for the parameters, so a float is
    splatted and a float4 truncated as FXC does: (0.625, 0.875, 0.375). Control: untyped (the
    old reading), the GLSL port is refused as before ("initializer of type float cannot be
    assigned to variable of type vec3")."""
    shader = _shader(tmp_path, "function_macro", FUNCTION_MACRO, FUNCTION_MACRO_HEAD)
    _assert_colour(tmp_path, shader, language, _function_macro_expected())
    if language == "glsl":
        monkeypatch.setattr(cg_types._Parser, "macro_value", lambda self, name, args: (None, True))
        with pytest.raises(PbrlabError, match="initializer of type float"):
            _render(tmp_path, _shader(tmp_path, "function_macro_old", FUNCTION_MACRO, FUNCTION_MACRO_HEAD), language)


def test_macro_definitions_that_disagree_leave_the_use_untyped():
    """One definition under #if, another under #else with another type: the pass cannot tell
    which the preprocessor keeps, so the use stays untyped (no conversion spelled), as a body
    continued on the next line (its first line read alone is no body); control: one
    definition is typed (the float splatted to the vec3 it initialises)."""
    one = "#define F(a) 1.0\nvoid f() { float3 x = F(0); }\n"
    both = "#if A\n#define F(a) 1.0\n#else\n#define F(a) float3(a, a, a)\n#endif\nvoid f() { float3 x = F(0); }\n"
    assert "float3 x = float3(F(0));" in cg_types.convert(one)
    assert "float3 x = F(0);" in cg_types.convert(both)
    continued = "#define F(a) (a) \\\n  * 2\nvoid f() { float3 x = F(0); }\n"  # its first line no whole body
    assert "float3 x = F(0);" in cg_types.convert(continued)


# a non-symmetric matrix: a row read as a column, or an element's indices swapped, shows
MATRIX_DEFINE_HEAD = """
        static const float4x4 MY_M = float4x4(1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16) / 32.0;
        #define MY_COLUMN0 MY_M._11_21_31
        #define MY_ELEMENT(m) m._m12
        #define MY_SET(m) m._m01 = 0.5"""
MATRIX_DEFINE = """
            float4x4 m = MY_M;
            MY_SET(m);
            return float4(MY_COLUMN0.xy, MY_ELEMENT(MY_M) + m._12, 1);"""


def _matrix_define_expected():
    """Microsoft's HLSL reference, "Per-component math" (matrix swizzles): ``_RC`` is row R,
    column C from 1, ``_mRC`` from 0; the constructor takes rows."""
    m = np.arange(1.0, 17.0).reshape(4, 4) / 32.0
    column0 = m[0:3, 0]
    written = m.copy()
    written[0, 1] = 0.5
    return [column0[0], column0[1], m[1, 2] + written[0, 1]]


@pytest.mark.parametrize("language", LANGUAGES)
def test_matrix_swizzles_in_a_define(tmp_path, language, monkeypatch):
    """``#define CAMERA_NEAR_PLANE_UL _CameraNearPlaneCorners._11_21_31`` (ssell's
    VolumetricFog): a matrix swizzle in a macro's body, read and written, one-based and
    zero-based: (1/32, 5/32, 7/32 + 1/2). Control: without the spelling of a #define's elements
    the GLSL port is refused as before ("cannot access field `_11'"); code's were spelled already."""
    shader = _shader(tmp_path, "matrix_define", MATRIX_DEFINE, MATRIX_DEFINE_HEAD)
    _assert_colour(tmp_path, shader, language, _matrix_define_expected())
    if language == "glsl":
        monkeypatch.setattr(port, "_matrix_elements_in_defines", lambda text: text)
        with pytest.raises(PbrlabError, match="_11|_m12|_m01"):
            _render(tmp_path, _shader(tmp_path, "matrix_define_old", MATRIX_DEFINE, MATRIX_DEFINE_HEAD), language)
