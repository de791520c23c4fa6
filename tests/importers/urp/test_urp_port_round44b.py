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



def _rgb(tmp_path, language, name, body, include=""):
    """The covered pixels' RGB of the URP pass ``body`` (after ``include``) on the unit sphere."""
    pixels, _ = render_constant(tmp_path, urp_pass(name, body, include), language, environment=False)
    return pixels[:, :3]


def _refused(tmp_path, match, name, body, include=""):
    """The GLSL port refuses the pass (a control: the conversion taken out)."""
    with pytest.raises(PbrlabError, match=match):
        _rgb(tmp_path, "glsl", name, body, include)


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
    pixels = _rgb(tmp_path, language, "defined", body, DEFINED)
    s, c = 0.3 * 0.5, np.array([0.1, 0.2, 0.3]) * 2.0
    expected = np.array([s + s, s * c[0], c[2] - s])
    assert np.abs(pixels - expected).max() <= ARITHMETIC


def test_a_define_left_untyped_is_refused_by_the_glsl_port(tmp_path, monkeypatch):
    """Control: the pass's old reading (the define of unknown type, nothing spelled out)."""
    monkeypatch.setattr(cg_types._Parser, "defined_value", lambda self, name: None)
    body = "float4 s = _BlurRadius * 0.5; return float4(s.xyz, 1);"
    _refused(tmp_path, "cannot be assigned", "defined_old", body, DEFINED)


def _sincos(tmp_path, language, name, angle):
    body = f"""float h = {angle};
              float3 s, c;
              sincos(h, s, c);
              return float4(s.x, c.y, s.z * c.z, 1);"""
    return _rgb(tmp_path, language, name, body)


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


# hadashiA's ScreenSpaceFluid: ``uniform`` before the SRP texture macros (FXC: a global is
# uniform anyway); wrc1028's WaterPass: a ternary whose operand's name reads as a semantic.
UNIFORM_MACROS = """
    uniform TEXTURE2D(_NoiseTex);
    uniform SAMPLER(sampler_NoiseTex);
"""


def _ternary(tmp_path, language, name, depth):
    body = f"""float4 color01 = float4(0.2, 0.4, 0.6, 1);
              float4 color02 = float4(0.9, 0.1, 0.3, 1);
              float depth = {depth};
              float4 result = depth < 0.5 ? color01 : color02;
              return result * result;"""
    return _rgb(tmp_path, language, name, body, UNIFORM_MACROS)


@pytest.mark.parametrize("language", LANGUAGES)
def test_uniform_texture_macros_and_a_ternary_of_color_named_operands(tmp_path, language):
    """``d < 0.5 ? color01 : color02`` picks color01 (squared: 0.04, 0.16, 0.36), its operand
    ``color02`` no longer dropped as a COLOR semantic; control: depth 0.75 picks color02."""
    near = _ternary(tmp_path, language, "ternary", 0.25)
    assert np.abs(near - np.array([0.2, 0.4, 0.6]) ** 2).max() <= ARITHMETIC
    far = _ternary(tmp_path, language, "ternary_far", 0.75)
    assert np.abs(far - np.array([0.9, 0.1, 0.3]) ** 2).max() <= ARITHMETIC


def test_the_old_semantic_reading_of_a_ternary_is_refused(tmp_path, monkeypatch):
    """Control: ``: color02`` read as a semantic again leaves ``?`` without its ``:``."""
    from pbrlab.importers.unity import port
    monkeypatch.setattr(port, "_in_ternary", lambda code, pos: False)
    with pytest.raises(PbrlabError, match="syntax error"):
        _ternary(tmp_path, "glsl", "ternary_old", 0.25)


def test_uniform_before_sampler_kept_is_refused(tmp_path, monkeypatch):
    """Control: ``uniform`` kept before the sampler's constant stand-in."""
    import re
    from pbrlab.importers.unity import port
    monkeypatch.setattr(port, "_TRAILING_UNIFORM", re.compile(r"(?!)"))
    with pytest.raises(PbrlabError, match="duplicate storage qualifier"):
        _ternary(tmp_path, "glsl", "uniform_old", 0.25)


# RyouTomokin's KIIFPBR: a Varyings member float4 under #if, float3 under #else.
TWO_TYPED_MEMBER = """
    #define WIDE_NORMAL 1
    struct Packed {
    #if defined(WIDE_NORMAL)
        float4 normalWS;
    #else
        float3 normalWS;
    #endif
    };
"""
TWO_TYPED_BODY = """Packed p;
              p.normalWS = float4(float3(0.1, 0.2, 0.3), 0.4);
              return float4(p.normalWS.w, p.normalWS.x, 0.5, 1);"""


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_member_of_two_types_under_if_keeps_the_compiled_ones(tmp_path, language):
    """The #if branch compiled declares a float4: all four components are stored (0.4, 0.1)."""
    assert np.abs(_rgb(tmp_path, language, "two_typed", TWO_TYPED_BODY, TWO_TYPED_MEMBER) - np.array([0.4, 0.1, 0.5])).max() <= ARITHMETIC


def test_a_member_typed_by_its_last_declaration_is_refused(tmp_path, monkeypatch):
    """Control: the pass's old reading (the #else's float3) truncates the float4 stored."""
    monkeypatch.setattr(cg_types._Parser, "member_type", staticmethod(lambda fields, name, t: t))
    _refused(tmp_path, "cannot be assigned", "two_typed_old", TWO_TYPED_BODY, TWO_TYPED_MEMBER)


# wrc1028's WaterSG: Shader Graph's ``struct Bindings_X { };`` for a subgraph that binds nothing.
EMPTY_STRUCT = """
    struct Bindings_Nothing { };
    float Shade(float x, Bindings_Nothing IN) { return x * 0.5; }
"""
EMPTY_BODY = """Bindings_Nothing b = (Bindings_Nothing)0;
              return float4(Shade(0.25, b), 0.25, 0.5, 1);"""


@pytest.mark.parametrize("language", LANGUAGES)
def test_an_empty_struct_is_declared_and_passed(tmp_path, language):
    """FXC takes an empty struct; the GLSL port gives it an unused int (GLSL 3.30 section 4.1.8
    needs a member): the function called through it returns 0.125."""
    assert np.abs(_rgb(tmp_path, language, "empty_struct", EMPTY_BODY, EMPTY_STRUCT) - np.array([0.125, 0.25, 0.5])).max() <= ARITHMETIC


def test_an_empty_struct_as_written_is_refused_by_the_glsl_port(tmp_path, monkeypatch):
    """Control: without the stand-in member GLSL's grammar refuses the struct."""
    monkeypatch.setattr(cg_types._Parser, "EMPTY_MEMBER", "")
    _refused(tmp_path, "syntax error", "empty_struct_old", EMPTY_BODY, EMPTY_STRUCT)


# FractalAsim's DepthVisualizer: ``if (_KEYWORD)`` of a keyword of the variant (the harness
# defines it 1); cociorbaandrei's Toon: ``uint isFrontFace : SV_IsFrontFace``.
KEYWORD_CONDITION = """
    #pragma shader_feature_local _SELECT_NEAR _SELECT_FAR
"""
KEYWORD_BODY = """if (_SELECT_NEAR)
                  return float4(0.25, 0.5, 0.75, 1);
              return float4(0.75, 0.5, 0.25, 1);"""


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_keyword_as_an_if_condition_is_converted_to_bool(tmp_path, language):
    """The variant's first keyword is defined 1: FXC converts the int condition to bool (true)."""
    assert np.abs(_rgb(tmp_path, language, "keyword_if", KEYWORD_BODY, KEYWORD_CONDITION) - np.array([0.25, 0.5, 0.75])).max() <= ARITHMETIC


def test_a_keyword_condition_left_as_written_is_refused(tmp_path, monkeypatch):
    """Control: the pass's old reading (an unknown name's condition untouched)."""
    monkeypatch.setattr(cg_types, "_NAME", __import__("re").compile(r"(?!)"))
    _refused(tmp_path, "scalar boolean", "keyword_if_old", KEYWORD_BODY, KEYWORD_CONDITION)


FRONT_FACE = urp_pass("front_face_uint", "").replace(
    "float4 frag(Varyings IN) : SV_Target {",
    "float4 frag(Varyings IN, uint isFrontFace : SV_IsFrontFace) : SV_Target {\n"
    "    return isFrontFace ? float4(0.25, 0.5, 0.75, 1) : float4(0.75, 0.5, 0.25, 1);")


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_uint_front_face_is_nonzero_on_the_spheres_outside(tmp_path, language):
    """The sphere's visible faces are front faces: isFrontFace is nonzero (the first colour);
    the GLSL port used to initialise the uint with the float VFACE value, and was refused."""
    assert "uint isFrontFace" in FRONT_FACE
    pixels, _ = render_constant(tmp_path, FRONT_FACE, language, environment=False)
    assert np.abs(pixels[:, :3] - np.array([0.25, 0.5, 0.75])).max() <= ARITHMETIC


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_uint_front_face_is_zero_on_back_faces(tmp_path, language):
    """Control: culling the front faces shows the sphere's inside, whose faces are back faces:
    isFrontFace is 0 (the second colour)."""
    culled = FRONT_FACE.replace('Tags { "LightMode" = "UniversalForward" }',
                                'Tags { "LightMode" = "UniversalForward" }\n            Cull Front', 1)
    assert "Cull Front" in culled
    pixels, _ = render_constant(tmp_path, culled, language, environment=False)
    assert np.abs(pixels[:, :3] - np.array([0.75, 0.5, 0.25])).max() <= ARITHMETIC
