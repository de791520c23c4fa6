"""The Academy Color Encoding System's colour spaces and Reference Rendering Transform helpers,
float64 (the reference for Core RP's ACES.hlsl names in pbrlab's Unity stand-in,
importers/unity/package_stand_ins/.../ShaderLibrary/ACES.hlsl). Sources:

- primaries and white points: SMPTE ST 2065-1 (ACES2065-1, AP0), Academy S-2014-004 (ACEScg,
  AP1), ITU-R BT.709 (sRGB's primaries, D65); RGB -> XYZ from primaries as SMPTE RP 177;
- chromatic adaptation: the Bradford transform (Lam 1985), ACES white (D60-like) <-> D65;
- ACEScc's log encoding: Academy S-2014-003, section 4.4;
- rgb_2_saturation, rgb_2_yc, rgb_2_hue, center_hue, sigmoid_shaper, glow_fwd, the RRT's glow and
  red-modifier constants, the dim-surround gamma 0.9811: the Academy's aces-dev CTL
  (ACESlib.RRT_Common, ACESlib.ODT_Common, ACESlib.Utilities_Color).

Colours on the last axis; matrices act on column vectors (``M @ rgb``).
"""

from __future__ import annotations

import numpy as np

ACES_WHITE = (0.32168, 0.33767)
D65 = (0.3127, 0.3290)
AP0 = ((0.7347, 0.2653), (0.0, 1.0), (0.0001, -0.0770))
AP1 = ((0.713, 0.293), (0.165, 0.830), (0.128, 0.044))
REC709 = ((0.64, 0.33), (0.30, 0.60), (0.15, 0.06))
BRADFORD = np.array([[0.8951, 0.2664, -0.1614], [-0.7502, 1.7135, 0.0367], [0.0389, -0.0685, 1.0296]])

# ACESlib.RRT_Common / ODT_Common
RRT_GLOW_GAIN, RRT_GLOW_MID = 0.05, 0.08
RRT_RED_SCALE, RRT_RED_PIVOT, RRT_RED_HUE, RRT_RED_WIDTH = 0.82, 0.03, 0.0, 135.0
RRT_SAT_FACTOR, ODT_SAT_FACTOR = 0.96, 0.93
DIM_SURROUND_GAMMA = 0.9811
CINEMA_WHITE, CINEMA_BLACK = 48.0, 48.0 / 2400.0


def _xyz(xy) -> np.ndarray:
    x, y = xy
    return np.array([x / y, 1.0, (1.0 - x - y) / y])


def rgb_to_xyz(primaries, white) -> np.ndarray:
    """RP 177: the columns are the primaries' XYZ scaled so that RGB (1, 1, 1) is the white, Y 1."""
    p = np.stack([_xyz(c) for c in primaries], axis=1)
    return p * np.linalg.solve(p, _xyz(white))


def bradford(source_white, target_white) -> np.ndarray:
    """The Bradford chromatic adaptation of XYZ from one white to another."""
    s, t = BRADFORD @ _xyz(source_white), BRADFORD @ _xyz(target_white)
    return np.linalg.inv(BRADFORD) @ np.diag(t / s) @ BRADFORD


AP0_2_XYZ = rgb_to_xyz(AP0, ACES_WHITE)
AP1_2_XYZ = rgb_to_xyz(AP1, ACES_WHITE)
XYZ_2_AP0 = np.linalg.inv(AP0_2_XYZ)
XYZ_2_AP1 = np.linalg.inv(AP1_2_XYZ)
REC709_2_XYZ = rgb_to_xyz(REC709, D65)
XYZ_2_REC709 = np.linalg.inv(REC709_2_XYZ)
D60_2_D65 = bradford(ACES_WHITE, D65)
D65_2_D60 = bradford(D65, ACES_WHITE)
SRGB_2_AP0 = XYZ_2_AP0 @ D65_2_D60 @ REC709_2_XYZ
SRGB_2_AP1 = XYZ_2_AP1 @ D65_2_D60 @ REC709_2_XYZ
AP0_2_SRGB = np.linalg.inv(SRGB_2_AP0)
AP1_2_SRGB = np.linalg.inv(SRGB_2_AP1)
AP0_2_AP1 = XYZ_2_AP1 @ AP0_2_XYZ
AP1_2_AP0 = XYZ_2_AP0 @ AP1_2_XYZ
AP1_RGB2Y = AP1_2_XYZ[1]  # AP1's luminance weights: the Y row

MATRICES = {"sRGB_2_AP0": SRGB_2_AP0, "sRGB_2_AP1": SRGB_2_AP1, "AP0_2_sRGB": AP0_2_SRGB, "AP1_2_sRGB": AP1_2_SRGB,
            "AP0_2_AP1_MAT": AP0_2_AP1, "AP1_2_AP0_MAT": AP1_2_AP0, "AP1_2_XYZ_MAT": AP1_2_XYZ,
            "XYZ_2_AP1_MAT": XYZ_2_AP1, "XYZ_2_REC709_MAT": XYZ_2_REC709, "D60_2_D65_CAT": D60_2_D65}


def _mul(m, c):
    return np.einsum("ij,...j->...i", m, np.asarray(c, np.float64))


def unity_to_aces(c):
    return _mul(SRGB_2_AP0, c)


def aces_to_acescg(c):
    return _mul(AP0_2_AP1, c)


def aces_to_acescc(x):
    """S-2014-003 4.4: (log2(x) + 9.72) / 17.52, below 2^-15 log2(2^-16 + x / 2), at or below 0
    the value at x = 0's limit of that, log2(2^-16)."""
    x = np.asarray(x, np.float64)
    small = (np.log2(2.0 ** -16 + np.maximum(x, 0.0) * 0.5) + 9.72) / 17.52
    return np.where(x < 2.0 ** -15, small, (np.log2(np.maximum(x, 2.0 ** -15)) + 9.72) / 17.52)


def acescc_to_aces(y):
    """S-2014-003 4.4's inverse (below (9.72 - 15) / 17.52 the small-value branch); clamped to
    the half float maximum 65504 at the top, as ACEScc's range ends there."""
    y = np.asarray(y, np.float64)
    top = (np.log2(65504.0) + 9.72) / 17.52
    return np.where(y < (9.72 - 15.0) / 17.52, (2.0 ** (y * 17.52 - 9.72) - 2.0 ** -16) * 2.0,
                    np.where(y < top, 2.0 ** (y * 17.52 - 9.72), 65504.0))


def rgb_2_saturation(rgb):
    rgb = np.asarray(rgb, np.float64)
    ma, mi = rgb.max(axis=-1), rgb.min(axis=-1)
    return (np.maximum(ma, 1e-4) - np.maximum(mi, 1e-4)) / np.maximum(ma, 1e-2)


def rgb_2_yc(rgb, yc_radius_weight=1.75):
    r, g, b = np.moveaxis(np.asarray(rgb, np.float64), -1, 0)
    chroma = np.sqrt(np.maximum(b * (b - g) + g * (g - r) + r * (r - b), 0.0))
    return (b + g + r + yc_radius_weight * chroma) / 3.0


def rgb_2_hue(rgb):
    """Degrees in [0, 360); 0 for a neutral colour (where the hue is undefined)."""
    r, g, b = np.moveaxis(np.asarray(rgb, np.float64), -1, 0)
    hue = np.degrees(np.arctan2(np.sqrt(3.0) * (g - b), 2.0 * r - g - b))
    hue = np.where((r == g) & (g == b), 0.0, hue)
    return np.where(hue < 0.0, hue + 360.0, hue)


def center_hue(hue, center):
    h = np.asarray(hue, np.float64) - center
    return np.where(h < -180.0, h + 360.0, np.where(h > 180.0, h - 360.0, h))


def sigmoid_shaper(x):
    """0 to 1 over -2 to 2: (1 + sign(x) (1 - t^2)) / 2, t = max(1 - |x| / 2, 0)."""
    x = np.asarray(x, np.float64)
    t = np.maximum(1.0 - np.abs(x / 2.0), 0.0)
    return (1.0 + np.sign(x) * (1.0 - t * t)) / 2.0


def glow_fwd(yc, gain, mid):
    yc = np.asarray(yc, np.float64)
    return np.where(yc <= 2.0 / 3.0 * mid, gain,
                    np.where(yc >= 2.0 * mid, 0.0, gain * (mid / np.maximum(yc, 1e-300) - 0.5)))


def dark_to_dim_surround(linear_cv):
    """ODT_Common's dark -> dim surround: AP1 -> XYZ -> xyY, Y^0.9811, back to AP1."""
    xyz = _mul(AP1_2_XYZ, linear_cv)
    s = np.maximum(xyz.sum(axis=-1), 1e-10)
    x, y = xyz[..., 0] / s, xyz[..., 1] / s
    big_y = np.clip(xyz[..., 1], 0.0, 65504.0) ** DIM_SURROUND_GAMMA
    m = big_y / np.maximum(y, 1e-10)
    return _mul(XYZ_2_AP1, np.stack([x * m, big_y, (1.0 - x - y) * m], axis=-1))
