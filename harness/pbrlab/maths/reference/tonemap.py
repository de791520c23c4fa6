"""Exposure and tonemapper references: glsl/pbr/tonemap/. Colours on the last axis."""

import numpy as np

from .guards import HALF_MAX, sanitize

HABLE = dict(A=0.15, B=0.50, C=0.10, D=0.20, E=0.02, F=0.30)  # PBR_HABLE_A..F (Hable 2010)
HABLE_WHITE = 11.2                                          # PBR_HABLE_WHITE
# Hill 2016 (BakingLab ACES.hlsl) matrices, rows as written there (PBR_ACES_*_ROW*)
ACES_INPUT = np.array([[0.59719, 0.35458, 0.04823],
                       [0.07600, 0.90834, 0.01566],
                       [0.02840, 0.13383, 0.83777]])
ACES_OUTPUT = np.array([[1.60475, -0.53108, -0.07367],
                        [-0.10208, 1.10813, -0.00605],
                        [-0.00327, -0.07276, 1.07602]])
ACES_NARKOWICZ = dict(a=2.51, b=0.03, c=2.43, d=0.59, e=0.14)  # Narkowicz 2015
KHRONOS_NEUTRAL_F90 = 0.04          # Khronos PBR Neutral spec: F90
KHRONOS_NEUTRAL_KS = 0.8 - 0.04     # K_s (start of compression)
KHRONOS_NEUTRAL_KD = 0.15           # K_d (desaturation speed)
TONEMAPS = ("NONE", "REINHARD", "HABLE", "ACES_FITTED", "ACES_NARKOWICZ", "KHRONOS_NEUTRAL")


def _f(x):
    return np.asarray(x, dtype=np.float64)


def apply_exposure(color, exposure_ev):
    return _f(color) * (2.0 ** _f(exposure_ev))[..., None]


def tonemap_reinhard(color):
    c = _f(color)
    return c / (1.0 + c)


def tonemap_reinhard_extended(color, white_point):
    c, w = _f(color), _f(white_point)[..., None]
    return c * (1.0 + c / (w * w)) / (1.0 + c)


def hable_curve(x):
    x, k = _f(x), HABLE
    return ((x * (k["A"] * x + k["C"] * k["B"]) + k["D"] * k["E"])
            / (x * (k["A"] * x + k["B"]) + k["D"] * k["F"])) - k["E"] / k["F"]


def tonemap_hable(color):
    return hable_curve(color) / hable_curve(HABLE_WHITE)


def tonemap_aces_fitted(color):
    c = _f(color)
    v = c @ ACES_INPUT.T
    fitted = (v * (v + 0.0245786) - 0.000090537) / (v * (0.983729 * v + 0.4329510) + 0.238081)
    return np.clip(fitted @ ACES_OUTPUT.T, 0.0, 1.0)


def tonemap_aces_narkowicz(color):
    x, k = _f(color), ACES_NARKOWICZ
    return np.clip(x * (k["a"] * x + k["b"]) / (x * (k["c"] * x + k["d"]) + k["e"]), 0.0, 1.0)


def tonemap_khronos_neutral(color):
    """Khronos PBR Neutral, in the specification's own notation (README, 2024)."""
    c = _f(color)
    F90, Ks, Kd = KHRONOS_NEUTRAL_F90, KHRONOS_NEUTRAL_KS, KHRONOS_NEUTRAL_KD
    x = np.min(c, axis=-1)
    f = np.where(x <= 2.0 * F90, x - x * x / (4.0 * F90), F90)
    shifted = c - f[..., None]
    p = np.max(shifted, axis=-1)
    pn = 1.0 - (1.0 - Ks) ** 2 / (p + 1.0 - 2.0 * Ks)
    g = 1.0 / (Kd * (p - pn) + 1.0)
    with np.errstate(divide="ignore", invalid="ignore"):
        compressed = shifted * (pn / p * g)[..., None] + (pn * (1.0 - g))[..., None]
    return np.where((p <= Ks)[..., None], shifted, compressed)


def tonemap(color, variant="KHRONOS_NEUTRAL"):
    """pbr_tonemap under PBR_TONEMAP = PBR_TONEMAP_<variant>, with the shader's guards: input
    sanitised to [0, HALF_MAX] (NaN -> 0, +Inf -> 65504), output in [0, 1] (Hable and the
    curves that pass 1 are saturated). The tonemap_* functions above stay exact."""
    color = sanitize(color, HALF_MAX)
    table = {"NONE": lambda c: np.clip(_f(c), 0.0, 1.0), "REINHARD": tonemap_reinhard,
             "HABLE": tonemap_hable, "ACES_FITTED": tonemap_aces_fitted,
             "ACES_NARKOWICZ": tonemap_aces_narkowicz, "KHRONOS_NEUTRAL": tonemap_khronos_neutral}
    return np.clip(table[variant](color), 0.0, 1.0)
