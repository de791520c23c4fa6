"""Colour-space functions (glsl/pbr/color/) against harness/pbrlab/maths/reference/color.py, and the
two linear-space paths of the lecture compared in 8-bit steps (LSB = 1/255 of full scale)."""

import numpy as np
import pytest

from library_helpers import RTOL_WELL_CONDITIONED, as_f32, assert_close, evaluate, record, vec3
from pbrlab.maths.reference import color

# Linear values: dense in [0, 1] with the toe resolved, plus HDR values up to 16.
LINEAR = as_f32(np.concatenate([np.linspace(0.0, 1.0, 65537), np.geomspace(1e-7, 1e-2, 4097),
                                np.linspace(1.0, 16.0, 1025)]))
ENCODED = as_f32(np.concatenate([np.linspace(0.0, 1.0, 65537), np.arange(256) / 255.0]))
# pow() in GLSL is exp2(y·log2 x): the log2 absolute error (< 2^-21 near 1, GLSL 4.60
# §4.7.1) times the exponent (<= 2.4) gives <= 1.2e-6 relative; 1e-5 covers it with
# margin. atol 1e-9 (linear units): the sRGB toe values near 0 are below float32's
# relative resolution of the reference's tiny outputs only at exactly 0.
POW_RTOL = RTOL_WELL_CONDITIONED


def as_rgb(x):
    return np.stack([x, x[::-1], np.roll(x, 7)], axis=-1)


@pytest.mark.parametrize("glsl, ref, data", [
    ("pbr_srgb_to_linear", color.srgb_to_linear, ENCODED),
    ("pbr_linear_to_srgb", color.linear_to_srgb, LINEAR),
    ("pbr_degamma", color.degamma, ENCODED),
    ("pbr_regamma", color.regamma, LINEAR),
    ("pbr_degamma_fast", color.degamma_fast, ENCODED),
    ("pbr_regamma_fast", color.regamma_fast, LINEAR),
])
def test_color_curve_matches_reference(glsl, ref, data):
    rgb = as_rgb(data)
    # The GLSL curves take their input through pbr_sanitize(c, 1.0) (IEC 61966-2-1 defines
    # them on [0, 1]; guards.glsl): the exact reference is evaluated on the clipped input,
    # so the HDR part of LINEAR (1 .. 16) checks the clamp, the rest the curve itself.
    expected = ref(np.clip(rgb, 0.0, 1.0))
    assert_close(glsl, evaluate(f"{glsl}(c)", c=vec3(rgb)), expected, rtol=POW_RTOL, atol=1e-9)


def test_srgb_scalar_overloads_match_vec3():
    got = evaluate("vec3(pbr_srgb_to_linear(x), pbr_linear_to_srgb(x), 0.0)", x=ENCODED)
    np.testing.assert_array_equal(got[:, 0], evaluate("pbr_srgb_to_linear(vec3(x)).x", x=ENCODED))
    np.testing.assert_array_equal(got[:, 1], evaluate("pbr_linear_to_srgb(vec3(x)).x", x=ENCODED))


def test_srgb_round_trip_is_identity():
    got = evaluate("pbr_linear_to_srgb(pbr_srgb_to_linear(c))", c=vec3(as_rgb(ENCODED)))
    assert_close("sRGB decode->encode round trip", got, as_rgb(ENCODED), rtol=2 * POW_RTOL, atol=1e-7)


def test_srgb_constants_are_the_standard():
    """The curves meet at the thresholds within the standard's rounding (IEC 61966-2-1)."""
    t = color.SRGB_ENCODE_THRESHOLD
    assert abs(color.linear_to_srgb(t) - color.SRGB_DECODE_THRESHOLD) < 1e-6
    assert abs(((color.SRGB_DECODE_THRESHOLD + 0.055) / 1.055) ** 2.4 - color.SRGB_DECODE_THRESHOLD / 12.92) < 1e-8


def to_8bit(x):
    return np.round(np.clip(x, 0.0, 1.0) * 255.0).astype(int)


def test_diy_exact_srgb_encode_agrees_with_hardware_path_within_1_lsb():
    """The lecture's two paths: DIY (encode in the final-colour hook, written to a UNORM8
    target) vs hardware (GL_FRAMEBUFFER_SRGB, which encodes exactly; modelled by the
    float64 curve, rounded to 8 bits). With the exact curves they agree within 1 LSB."""
    linear = as_rgb(LINEAR[LINEAR <= 1.0])
    diy = evaluate("pbr_encode_final_color(c)", defines={"PBR_COLOR_TRANSFER": "PBR_COLOR_TRANSFER_SRGB"}, c=vec3(linear))
    lsb = np.abs(to_8bit(diy) - to_8bit(color.linear_to_srgb(linear)))
    record("DIY sRGB encode vs hardware, 8-bit LSB", float(lsb.max()), 0.0, "<= 1 LSB")
    assert lsb.max() <= 1


@pytest.mark.parametrize("transfer, expected_max_lsb", [("GAMMA22", 9), ("FAST", 10)])
def test_gamma_approximations_error_reported(transfer, expected_max_lsb):
    """pow 2.2 and sqrt encodes are approximations: their worst 8-bit error against the
    exact encode is measured, recorded and pinned (documented in glsl/pbr/color/gamma.glsl)."""
    linear = as_rgb(LINEAR[LINEAR <= 1.0])
    got = evaluate("pbr_encode_final_color(c)", defines={"PBR_COLOR_TRANSFER": f"PBR_COLOR_TRANSFER_{transfer}"},
                   c=vec3(linear))
    lsb = np.abs(to_8bit(got) - to_8bit(color.linear_to_srgb(linear)))
    record(f"{transfer} encode vs exact sRGB, 8-bit LSB", float(lsb.max()), 0.0, "reported")
    assert lsb.max() == expected_max_lsb


@pytest.mark.parametrize("transfer", color.TRANSFERS)
def test_color_transfer_selector_matches_reference(transfer):
    defines = {"PBR_COLOR_TRANSFER": f"PBR_COLOR_TRANSFER_{transfer}"}
    rgb = as_rgb(ENCODED)
    got = evaluate("pbr_decode_color_texel(c)", defines=defines, c=vec3(rgb))
    assert_close(f"pbr_decode_color_texel {transfer}", got, color.decode_color_texel(rgb, transfer), rtol=POW_RTOL, atol=1e-9)
    rgb = as_rgb(LINEAR)
    got = evaluate("pbr_encode_final_color(c)", defines=defines, c=vec3(rgb))
    assert_close(f"pbr_encode_final_color {transfer}", got, color.encode_final_color(rgb, transfer), rtol=POW_RTOL, atol=1e-9)


def test_color_transfer_default_is_hardware_identity():
    rgb = as_rgb(ENCODED)
    np.testing.assert_array_equal(evaluate("pbr_decode_color_texel(c)", c=vec3(rgb)), rgb.astype(np.float32))


def test_luminance_matches_reference_and_white_is_one():
    rgb = as_rgb(LINEAR)
    assert_close("pbr_luminance", evaluate("pbr_luminance(c)", c=vec3(rgb)), color.luminance(rgb),
                 rtol=RTOL_WELL_CONDITIONED)
    assert abs(float(evaluate("pbr_luminance(vec3(1.0))", x=0.0)) - 1.0) <= 2 ** -23
