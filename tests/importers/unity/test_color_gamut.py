"""Unity's UnityColorGamut.cginc (the built-in pipeline's HDR display encodings, which Unity's
Internal-BlitCopyHDRTonemappedToSDR reads): pbrlab's stand-in, rendered in both languages from a
minimal shader of our own, against the float64 standards (pbrlab.maths.reference.color_gamut:
SMPTE ST 2084 PQ, the BT.709 / BT.2020 / P3-D65 gamut matrices from their primaries (RP 177),
IEC 61966-2-1 sRGB), with a control each (the value another encoding gives).

Bounds, from float32 and GLSL's documented precision (GLSL ES 3.00 section 4.5.1, which the
Vulkan/SPIR-V path of the HLSL language shares): + - * round to 2^-24 relative, / to 2.5 ulp
(3 x 2^-24 here); log2 is within 3 ulp outside [0.5, 2] and 2^-21 absolute inside (taken as
2^-21 x max(|log2 x|, 1) absolute); exp2(t) within (3 + 2|t|) ulp (2^-23 each); pow(x, k) is
exp2(k log2 x). A relative error r in x gives |k| r in pow(x, k); the log2's error gives
ln 2 |k| that absolute error. ``_pow_rel`` adds these; each composite below follows its
formula step by step (first order; the terms are below 10^-4, so their products are negligible).
"""

from __future__ import annotations

import math
import textwrap

import numpy as np
import pytest

from pbrlab.checking import unity_corpus as corpus
from pbrlab.maths.reference import color_gamut as g

U = 2.0 ** -24
SHADER = textwrap.dedent("""\
    Shader "Test/ColorGamut"
    {
        SubShader
        {
            Pass
            {
                CGPROGRAM
                #pragma vertex vert
                #pragma fragment frag
                #include "UnityCG.cginc"
                #include "UnityColorGamut.cginc"
                float4 vert(float4 p : POSITION) : SV_POSITION { return UnityObjectToClipPos(p); }
                float4 frag() : SV_Target { return float4(%s, 1.0); }
                ENDCG
            }
        }
    }
    """)


def _render(tmp_path, expression, language):
    path = tmp_path / "g.shader"
    path.write_text(SHADER % expression)
    result = corpus.run_shader(path, language)
    assert result.status == "rendered", result.message
    covered = result.image[..., 3] == 1.0
    assert covered.mean() > 0.1
    return np.asarray(result.image, np.float64)[covered][:, :3]


def _log_abs(x):
    return 2.0 ** -21 * np.maximum(np.abs(np.log2(x)), 1.0)


def _pow_rel(x, rel_x, k):
    """Relative error of GLSL's pow(x, k) for x > 0 carrying relative error rel_x."""
    t = np.abs(k * np.log2(x))
    return abs(k) * rel_x + math.log(2.0) * abs(k) * _log_abs(x) + (3.0 + 2.0 * t) * 2.0 ** -23 + U * t


def _pq_encode_rel(y):
    p = np.asarray(y, np.float64) ** g.PQ_M1
    rel_p = _pow_rel(y, U, g.PQ_M1)
    r = (g.PQ_C1 + g.PQ_C2 * p) / (1.0 + g.PQ_C3 * p)
    rel_r = rel_p * (g.PQ_C2 * p / (g.PQ_C1 + g.PQ_C2 * p) + g.PQ_C3 * p / (1.0 + g.PQ_C3 * p)) + 7 * U
    return _pow_rel(r, rel_r, g.PQ_M2)


def _pq_decode_rel(e):
    r = np.asarray(e, np.float64) ** (1.0 / g.PQ_M2)
    rel_r = _pow_rel(e, U, 1.0 / g.PQ_M2)
    rel_num = rel_r * r / (r - g.PQ_C1) + U          # r - c1 cancels: r / (r - c1) ~ 6
    rel_den = rel_r * g.PQ_C3 * r / (g.PQ_C2 - g.PQ_C3 * r) + 2 * U
    ratio = (r - g.PQ_C1) / (g.PQ_C2 - g.PQ_C3 * r)
    return _pow_rel(ratio, rel_num + rel_den + 3 * U, 1.0 / g.PQ_M1)


def _matrix_bound(m, x, abs_x):
    """|M x|'s error: x's own absolute error through |M|, plus the constants' rounding (2^-24)
    and the three products' and two sums' roundings (5 x 2^-24), each of sum |M_ij x_j|."""
    return np.abs(m) @ abs_x + 6 * U * (np.abs(m) @ np.abs(x))


PQ_LUMINANCE = np.array([0.01, 0.001, 0.1])   # 100, 10 and 1000 nits
PQ_SIGNAL = np.array([0.5, 0.3, 0.7])


@pytest.mark.parametrize("language", corpus.LANGUAGES)
def test_st2084_curves_are_smpte_pq(tmp_path, language):
    """LinearToST2084 of 100, 10 and 1000 nits (/ 10000) and ST2084ToLinear of the signals 0.5,
    0.3, 0.7 (x 16, exact) against ST 2084's inverse EOTF and EOTF. Control: a 2.2 power, the
    other transfer the cginc knows."""
    encoded = _render(tmp_path, "LinearToST2084(float3(0.01, 0.001, 0.1))", language)
    expected = g.pq_inverse_eotf(PQ_LUMINANCE)
    bound = expected * _pq_encode_rel(PQ_LUMINANCE)
    assert (np.abs(encoded - expected) <= bound).all(), (encoded[0], expected, bound)
    assert not (np.abs(encoded - PQ_LUMINANCE ** (1 / 2.2)) <= bound).all()
    decoded = _render(tmp_path, "ST2084ToLinear(float3(0.5, 0.3, 0.7)) * 16.0", language)
    expected = 16.0 * g.pq_eotf(PQ_SIGNAL)
    bound = expected * _pq_decode_rel(PQ_SIGNAL)
    assert (np.abs(decoded - expected) <= bound).all(), (decoded[0], expected, bound)
    assert not (np.abs(decoded - 16.0 * PQ_SIGNAL ** 2.2) <= bound).all()


SCENE = np.array([0.3, 0.6, 0.9])
SIGNAL = np.array([0.5, 0.55, 0.45])
PAPER_WHITE, MAX_NITS = 200.0, 1000.0


@pytest.mark.parametrize("language", corpus.LANGUAGES)
def test_hdr10_display_encoding_and_its_inverse(tmp_path, language):
    """SimpleHDRDisplayToneMapAndOETF to HDR10 (BT.2020 primaries, PQ of paper white 200 nits)
    of the linear scene (0.3, 0.6, 0.9), and InverseSimpleHDRDisplayToneMapAndOETF of the signal
    (0.5, 0.55, 0.45) back to BT.709 (x 0.125, exact), against the float64 composition. Control:
    the same curves without the gamut matrices (BT.709 primaries read as BT.2020)."""
    args = f"kColorGamutHDR10, false, {PAPER_WHITE}, {MAX_NITS}"
    encoded = _render(tmp_path, f"SimpleHDRDisplayToneMapAndOETF(float3(0.3, 0.6, 0.9), {args})", language)
    wide = g.REC709_TO_REC2020 @ SCENE * (PAPER_WHITE / g.PQ_PEAK_NITS)
    expected = g.display_encode(SCENE, g.HDR10, PAPER_WHITE, MAX_NITS)
    rel_wide = _matrix_bound(g.REC709_TO_REC2020, SCENE, U * SCENE) / wide + 2 * U   # the scale's rounding
    bound = expected * (_pq_encode_rel(wide) + g.PQ_M2 * g.PQ_M1 * rel_wide)
    assert (np.abs(encoded - expected) <= bound).all(), (encoded[0], expected, bound)
    assert not (np.abs(encoded - g.pq_inverse_eotf(SCENE * PAPER_WHITE / g.PQ_PEAK_NITS)) <= bound).all()

    decoded = _render(tmp_path, f"InverseSimpleHDRDisplayToneMapAndOETF(float3(0.5, 0.55, 0.45), {args}) * 0.125",
                      language)
    linear = g.pq_eotf(SIGNAL) / (PAPER_WHITE / g.PQ_PEAK_NITS)
    expected = 0.125 * g.display_decode(SIGNAL, g.HDR10, PAPER_WHITE, MAX_NITS)
    abs_linear = linear * (_pq_decode_rel(SIGNAL) + 4 * U)   # the divide by the scale (and the scale's own)
    bound = 0.125 * _matrix_bound(g.REC2020_TO_REC709, linear, abs_linear)
    assert (np.abs(decoded - expected) <= bound).all(), (decoded[0], expected, bound)
    assert not (np.abs(decoded - 0.125 * linear) <= bound).all()


@pytest.mark.parametrize("language", corpus.LANGUAGES)
@pytest.mark.parametrize("gamut", ["kColorGamutSRGB", "kColorGamutP3D65G22", "kColorGamutRec709"])
def test_sdr_and_p3_decodings(tmp_path, language, gamut):
    """InverseSimpleHDRDisplayToneMapAndOETF of (0.5, 0.55, 0.45) for an sRGB display (IEC
    61966-2-1's decode), P3-D65 with a 2.2 power (paper white 200 of 1000 nits, then to BT.709),
    and Rec.709 (divided by paper white / 80 nits), x 0.5. Control: the sRGB display's value for
    the other two, and the 2.2 power for sRGB."""
    code = {"kColorGamutSRGB": g.SRGB, "kColorGamutP3D65G22": g.P3D65_G22, "kColorGamutRec709": g.REC709_CODE}[gamut]
    pixels = _render(tmp_path, f"InverseSimpleHDRDisplayToneMapAndOETF(float3(0.5, 0.55, 0.45), {gamut}, false,"
                     f" {PAPER_WHITE}, {MAX_NITS}) * 0.5", language)
    expected = 0.5 * g.display_decode(SIGNAL, code, PAPER_WHITE, MAX_NITS)
    powered = SIGNAL ** 2.2
    if code == g.SRGB:
        base = (SIGNAL + 0.055) / 1.055
        bound = expected * (_pow_rel(base, 3 * U, 2.4) + U)
        control = 0.5 * powered
    elif code == g.P3D65_G22:
        linear = powered / (PAPER_WHITE / MAX_NITS)
        bound = 0.5 * _matrix_bound(g.P3_TO_REC709, linear, linear * (_pow_rel(SIGNAL, U, 2.2) + 4 * U))
        control = 0.5 * g.display_decode(SIGNAL, g.SRGB, PAPER_WHITE, MAX_NITS)
    else:
        bound = expected * 5 * U   # the scale's divide and rounding, the divide, the product
        control = 0.5 * g.display_decode(SIGNAL, g.SRGB, PAPER_WHITE, MAX_NITS)
    assert (np.abs(pixels - expected) <= bound).all(), (pixels[0], expected, bound)
    assert not (np.abs(pixels - control) <= bound).all()


def test_stand_in_matrices_are_the_standards_to_ten_digits():
    """The cginc's four matrices (written to 10 decimals) against the float64 derivation from the
    primaries: within 5e-11 each (their last digit's rounding). Control: Unity's 6-digit values
    differ by more (e.g. Rec709ToRec2020[0][0] 0.627402 vs 0.62740390)."""
    from pathlib import Path
    import re
    import pbrlab
    text = (Path(pbrlab.__file__).parent / "importers" / "unity" / "cginc" / "UnityColorGamut.cginc").read_text()
    for name, matrix in (("Rec709ToRec2020", g.REC709_TO_REC2020), ("Rec2020ToRec709", g.REC2020_TO_REC709),
                         ("Rec709ToP3D65Mat", g.REC709_TO_P3), ("P3D65MatToRec709", g.P3_TO_REC709)):
        body = re.search(rf"{name} = float3x3\(([^)]*)\)", text).group(1)
        written = np.array([float(v) for v in body.replace("\n", " ").split(",")]).reshape(3, 3)
        assert np.abs(written - matrix).max() <= 5e-11, name
    assert abs(0.627402 - g.REC709_TO_REC2020[0, 0]) > 5e-11
