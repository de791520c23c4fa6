"""The type pass of the GLSL port and FXC's conversions (issue 34's hidden URP sample, session 44,
second round): values whose type the pass did not know, so HLSL's implicit conversion was left
out and the GLSL port refused what Unity's compiler accepts.

  * a #define of the program's own names (Ashlining's blurs: ``#define _BlurRadius _Params.y``,
    then ``float4 poissonScale = (_BlurRadius * 30) * mask;``): the pass types it where a use
    meets it (cg_types._Parser.defined_value) and splats or truncates as FXC does;
  * ``sincos(h, s3, c3)`` of a scalar angle and vector outputs (FractalAsim's HueShift): FXC
    promotes the angle to the outputs' type.

Scene and readback: test_urp_library_round2.render_constant (a unit sphere; covered pixels). Each
check is a pixel against float64, and a control: the conversion taken out (the pass's old
behaviour) is refused by the GLSL port again, or a perturbed input moves the pixel."""

from __future__ import annotations

import numpy as np
import pytest

from pbrlab.foundation.errors import PbrlabError
from pbrlab.importers.unity import cg_types
from test_urp_library_round2 import render_constant, urp_pass  # pytest puts this folder on sys.path

LANGUAGES = ("glsl", "hlsl")
# Constants through float32 arithmetic of two or three operations: 4 ulps of a value below 1.
ARITHMETIC = 4 * 2.0 ** -24
# GLSL 3.30 (section 8.1) leaves sin/cos's precision to the implementation; Mesa's llvmpipe
# evaluates single-precision minimax polynomials after range reduction (lp_build_sin / cos),
# a few float32 ulps on [0, 1]; 16 ulps of a value below 1 bounds it. Changing the angle by
# 0.1 moves sin(h) by about 0.09, 10^5 times the bound (the perturbed control).
TRIG = 16 * 2.0 ** -24

DEFINED = """
    static const half2 _Params = half2(0.1, 0.3);
    static const float4 _Tint = float4(0.1, 0.2, 0.3, 0.4);
    #define _BlurRadius _Params.y
    #define TINT_TWICE _Tint * 2
"""


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_define_of_a_globals_member_is_splatted_as_fxc_does(tmp_path, language):
    """``float4 s = _BlurRadius * 0.5;`` fills all four components with 0.15 (Microsoft's HLSL
    reference, "Casting and conversions": a scalar to a vector is replicated), and ``float3 c =
    TINT_TWICE;`` keeps the first three of the float4 (FXC warning X3206, implicit truncation),
    written ``(TINT_TWICE).xyz``: the define's expression is not one name, so the swizzle is
    parenthesised."""
    body = """float4 s = _BlurRadius * 0.5;
              float3 c = TINT_TWICE;
              return float4(s.x + s.w, s.y * c.x, c.z - s.z, 1);"""
    pixels, _ = render_constant(tmp_path, urp_pass("defined", body, DEFINED), language, environment=False)
    s, c = 0.3 * 0.5, np.array([0.1, 0.2, 0.3]) * 2.0
    expected = np.array([s + s, s * c[0], c[2] - s])
    assert np.abs(pixels[:, :3] - expected).max() <= ARITHMETIC


def test_a_define_left_untyped_is_refused_by_the_glsl_port(tmp_path, monkeypatch):
    """Control: the pass's old reading (the define of unknown type, nothing spelled out)."""
    monkeypatch.setattr(cg_types._Parser, "defined_value", lambda self, name: None)
    body = "float4 s = _BlurRadius * 0.5; return float4(s.xyz, 1);"
    with pytest.raises(PbrlabError, match="cannot be assigned"):
        render_constant(tmp_path, urp_pass("defined_old", body, DEFINED), "glsl", environment=False)


def _sincos(tmp_path, language, name, angle):
    body = f"""float h = {angle};
              float3 s, c;
              sincos(h, s, c);
              return float4(s.x, c.y, s.z * c.z, 1);"""
    pixels, _ = render_constant(tmp_path, urp_pass(name, body), language, environment=False)
    return pixels[:, :3]


@pytest.mark.parametrize("language", LANGUAGES)
def test_sincos_of_a_scalar_angle_fills_vector_outputs(tmp_path, language):
    """HLSL's sincos takes one template type for x, s and c (Microsoft's HLSL reference,
    "sincos"); FXC promotes the scalar angle to the outputs' float3, so every component of s is
    sin(h) and of c cos(h). Control: another angle moves the pixel."""
    h = 0.5
    expected = np.array([np.sin(h), np.cos(h), np.sin(h) * np.cos(h)])
    pixels = _sincos(tmp_path, language, "sincos", h)
    assert np.abs(pixels - expected).max() <= TRIG
    assert np.abs(_sincos(tmp_path, language, "sincos_other", 0.6) - expected).min() > 1000 * TRIG


def test_sincos_without_the_splat_is_refused_by_the_glsl_port(tmp_path, monkeypatch):
    """Control: the pass's old reading (no splat) is refused again."""
    monkeypatch.setattr(cg_types._Parser, "sincos_splat", lambda self, x, s, c: None)
    with pytest.raises(PbrlabError, match="cannot be assigned"):
        _sincos(tmp_path, "glsl", "sincos_old", 0.5)
