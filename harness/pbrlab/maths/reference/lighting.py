"""Float64 references of pbr/lighting/attenuation.glsl and pbr/lighting/sh9.glsl."""

import numpy as np

MIN_LIGHT_DISTANCE_SQUARED = 1e-8  # PBR_MIN_LIGHT_DISTANCE_SQUARED

# Ramamoorthi & Hanrahan 2001, "An Efficient Representation for Irradiance Environment
# Maps", eq. 13.
SH9_C1, SH9_C2, SH9_C3, SH9_C4, SH9_C5 = 0.429043, 0.511664, 0.743125, 0.886227, 0.247708


def range_window(distance2, range_):
    """Karis 2013, "Real Shading in Unreal Engine 4", eq. 9 window: saturate(1-(d/r)^4)^2."""
    ratio2 = np.asarray(distance2, np.float64) / (np.asarray(range_, np.float64) ** 2)
    return np.clip(1 - ratio2 * ratio2, 0, 1) ** 2


def distance_attenuation(distance2, range_):
    distance2 = np.asarray(distance2, np.float64)
    return range_window(distance2, range_) / np.maximum(distance2, MIN_LIGHT_DISTANCE_SQUARED)


def spot_attenuation(l, spot_direction, cos_outer, inv_cos_range):
    """Lagarde & de Rousiers 2014, "Moving Frostbite to PBR", listing 4 (squared ramp)."""
    cos_angle = np.sum(-np.asarray(l, np.float64) * spot_direction, axis=-1)
    return np.clip((cos_angle - cos_outer) * inv_cos_range, 0, 1) ** 2


def sh9_irradiance(sh, n):
    """Irradiance E(n) from SH9 radiance coefficients sh[9, 3]; n[..., 3] -> [..., 3]."""
    sh = np.asarray(sh, np.float64)
    x, y, z = (np.asarray(n, np.float64)[..., i:i + 1] for i in range(3))
    return (SH9_C1 * sh[8] * (x * x - y * y) + SH9_C3 * sh[6] * z * z + SH9_C4 * sh[0] - SH9_C5 * sh[6]
            + 2 * SH9_C1 * (sh[4] * x * y + sh[7] * x * z + sh[5] * y * z)
            + 2 * SH9_C2 * (sh[3] * x + sh[1] * y + sh[2] * z))
