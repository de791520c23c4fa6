"""Literals of real shaders (issue 34's hidden7 sample, session 46) that Unity's compiler takes
and the HLSL path (glslang, then spirv-cross) or the GLSL port refused, each in a minimal
built-in shader of ours drawn in both languages; the fragment returns values computed from the
literal, checked on every covered pixel against float64, with a control (the old spelling) that
the compilers refuse. Readback and tolerance as test_port_round43.py (EXACT: 2 ulp of 1; every
value below is a dyadic fraction, exact in float32)."""

from __future__ import annotations

import re

import pytest

from pbrlab.foundation.errors import PbrlabError
from pbrlab.importers.unity import cg_spellings, sample_offsets
from test_port_round43 import LANGUAGES, _assert_colour, _shader
from test_unity_names_round5 import _render  # pytest puts this folder on sys.path

_NEVER = re.compile(r"(?!x)x")

# redducks100's terrain passes: ``opacityAsDensity += 0.001h * splatControl;``
HALF = """
            half a = 0.25h + 0.125H;
            half3 b = half3(.5h, 5e-1h, 0.0h) * (i.uv.x * 0.0h + 1.0h);
            half t = i.uv.x > 2.0 ? 0.75h : 0.25h;  // (a ternary of two: glslang keeps 16 bits)
            return float4(a, b.x * 1.5h, b.y + b.z + t, 1);"""


@pytest.mark.parametrize("language", LANGUAGES)
def test_half_literals_are_floats(tmp_path, language, monkeypatch):
    """Direct3D 10+ targets map half to float (Microsoft's HLSL reference, "Scalar Types"), so a
    ``0.25h`` literal is the float 0.25: (0.375, 0.75, 0.75). Control: the suffix left, glslang
    makes 16-bit constants and spirv-cross's GLSL asks for an FP16 extension the driver lacks."""
    _assert_colour(tmp_path, _shader(tmp_path, "half", HALF), language, [0.375, 0.75, 0.75])
    if language == "hlsl":
        monkeypatch.setattr(cg_spellings, "_HALF_LITERAL", _NEVER)
        with pytest.raises(PbrlabError, match="FP16"):
            _render(tmp_path, _shader(tmp_path, "half_old", HALF), language)


# TxN's Kuwahara: Hugo Elias's hash with its decimal constant written after ``0x``.
WIDE_HEX = """
            uint n = 3u;
            n = n * 0x10u + 0x1376312589U;
            return float4(float(n & 0xFFu) / 256.0, float((n >> 8) & 0xFFu) / 256.0,
                          float((n >> 24) & 0xFFu) / 256.0, 1);"""


def _wide_hex_expected():
    """uint arithmetic is modulo 2^32 (Microsoft's HLSL reference, "Scalar Types": uint is 32
    bits); the 36-bit literal's low 32 bits are what a 32-bit sum keeps either way."""
    n = (3 * 0x10 + 0x1376312589) % 2 ** 32
    return [(n & 0xFF) / 256, ((n >> 8) & 0xFF) / 256, ((n >> 24) & 0xFF) / 256]


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_hex_literal_wider_than_32_bits_keeps_its_low_32_bits(tmp_path, language, monkeypatch):
    """The hash's bytes: (0xB9, 0x25, 0x76) / 256. Control: the literal as written, both paths
    refuse it ("out of range" in GLSL, "too big" in glslang's HLSL)."""
    assert cg_spellings.respelled("x = 0x1376312589U;") == "x = 0x0076312589U;"  # columns kept
    _assert_colour(tmp_path, _shader(tmp_path, "wide_hex", WIDE_HEX), language, _wide_hex_expected())
    monkeypatch.setattr(cg_spellings, "_WIDE_HEX", _NEVER)
    with pytest.raises(PbrlabError, match="out of range|too big"):
        _render(tmp_path, _shader(tmp_path, "wide_hex_old", WIDE_HEX), language)


# HengyuanLee's BilateralBlur's form (rendered in tests/importers/urp/test_urp_port_s46.py)
OFFSET_PROGRAM = """float4 Blur(float2 uv, int2 delta, Texture2D t, SamplerState s) : SV_Target
{
    float3 a = t.Sample(s, uv, delta * -1); // a comment
    return float4(a, 1);
}
float4 across(float2 uv) { return Blur(uv, int2(1, 0), _T, sampler_T); }
float4 up(float2 uv) { return Blur(uv,
    int2(0, 1), _T, sampler_T) + Blur(uv, int2(1, 0), _T, sampler_T); }
"""


def test_a_parameter_offset_is_specialised_per_constant_with_lines_kept():
    """One specialisation per distinct constant (two here, three calls), each declaring the
    parameter a static const; the lines kept (errors map back). Control: a call that passes a
    variable leaves the text as written (FXC too needs the offset to fold to an immediate)."""
    spelled = sample_offsets.specialised_offsets(OFFSET_PROGRAM)
    assert spelled.count("\n") == OFFSET_PROGRAM.count("\n")
    assert "static const int2 delta = int2(1,0);" in spelled and "static const int2 delta = int2(0,1);" in spelled
    assert spelled.count("Blur_pbrlab_offset0(uv,") == 2 and spelled.count("Blur_pbrlab_offset1(uv,") == 1
    assert "int2 delta," not in spelled
    variable = OFFSET_PROGRAM.replace("int2(1, 0), _T", "int2(k, 0), _T")
    assert sample_offsets.specialised_offsets(variable) == variable
