"""Colour-space references: glsl/pbr/color/ (srgb, gamma, luminance, transfer)."""

import numpy as np

from .guards import sanitize

# IEC 61966-2-1:1999 §5.2/§5.3 (PBR_SRGB_* in glsl/pbr/color/srgb.glsl)
SRGB_DECODE_THRESHOLD = 0.04045
SRGB_ENCODE_THRESHOLD = 0.0031308
SRGB_LINEAR_SLOPE = 12.92
SRGB_OFFSET = 0.055
SRGB_EXPONENT = 2.4

DISPLAY_GAMMA = 2.2                                  # PBR_DISPLAY_GAMMA (the lecture)
LUMINANCE_REC709 = np.array([0.2126, 0.7152, 0.0722])  # PBR_LUMINANCE_REC709 (BT.709-6 §3.2)

TRANSFERS = ("HARDWARE", "SRGB", "GAMMA22", "FAST")  # PBR_COLOR_TRANSFER_* in order


def srgb_to_linear(c):
    """Exact IEC 61966-2-1 decode, per element."""
    c = np.asarray(c, dtype=np.float64)
    power = ((np.maximum(c, SRGB_DECODE_THRESHOLD) + SRGB_OFFSET) / (1.0 + SRGB_OFFSET)) ** SRGB_EXPONENT
    return np.where(c <= SRGB_DECODE_THRESHOLD, c / SRGB_LINEAR_SLOPE, power)


def linear_to_srgb(c):
    """Exact IEC 61966-2-1 encode, per element."""
    c = np.asarray(c, dtype=np.float64)
    power = (1.0 + SRGB_OFFSET) * np.maximum(c, SRGB_ENCODE_THRESHOLD) ** (1.0 / SRGB_EXPONENT) - SRGB_OFFSET
    return np.where(c <= SRGB_ENCODE_THRESHOLD, c * SRGB_LINEAR_SLOPE, power)


def degamma(c):
    """The lecture's DeGamma: pow(c, 2.2) (negative inputs clamped to 0)."""
    return np.maximum(np.asarray(c, dtype=np.float64), 0.0) ** DISPLAY_GAMMA


def regamma(c):
    """The lecture's ReGamma: pow(c, 1/2.2) (negative inputs clamped to 0)."""
    return np.maximum(np.asarray(c, dtype=np.float64), 0.0) ** (1.0 / DISPLAY_GAMMA)


def degamma_fast(c):
    c = np.asarray(c, dtype=np.float64)
    return c * c


def regamma_fast(c):
    return np.sqrt(np.maximum(np.asarray(c, dtype=np.float64), 0.0))


def luminance(linear_color):
    return np.asarray(linear_color, dtype=np.float64) @ LUMINANCE_REC709


_DECODE = {"HARDWARE": lambda c: np.asarray(c, dtype=np.float64), "SRGB": srgb_to_linear,
           "GAMMA22": degamma, "FAST": degamma_fast}
_ENCODE = {"HARDWARE": lambda c: np.asarray(c, dtype=np.float64), "SRGB": linear_to_srgb,
           "GAMMA22": regamma, "FAST": regamma_fast}


def decode_color_texel(texel, transfer="HARDWARE"):
    """pbr_decode_color_texel under PBR_COLOR_TRANSFER = PBR_COLOR_TRANSFER_<transfer>."""
    return _DECODE[transfer](texel)


def encode_final_color(linear_color, transfer="HARDWARE"):
    """pbr_encode_final_color under PBR_COLOR_TRANSFER = PBR_COLOR_TRANSFER_<transfer>, with
    the shader's guard: the input is sanitised to [0, 1] first (NaN -> 0, +Inf -> 1)."""
    return _ENCODE[transfer](sanitize(linear_color, 1.0))
