"""Roughness vocabulary and gloss remaps: glsl/pbr/material/remap.glsl."""

import numpy as np

CALLOFDUTY_LOG2_MAX_SPEC_POWER = 13.0  # PBR_CALLOFDUTY_LOG2_MAX_SPEC_POWER: s = 8192^g (Lazarov 2011)
CRYTEK_GLOSS_SCALE = 0.7               # PBR_CRYTEK_GLOSS_SCALE: alpha = (1 - 0.7 g)^2 (the lecture)


def _f(x):
    return np.asarray(x, dtype=np.float64)


def perceptual_roughness_from_smoothness(smoothness):
    return 1.0 - _f(smoothness)


def alpha_from_perceptual_roughness(perceptual_roughness):
    return _f(perceptual_roughness) ** 2


def perceptual_roughness_from_alpha(alpha):
    return np.sqrt(_f(alpha))


def alpha_from_smoothness(smoothness):
    return (1.0 - _f(smoothness)) ** 2


def specPower_from_gloss_CallOfDuty(gloss):
    return 8192.0 ** _f(gloss)


def alpha_from_gloss_Crytek(gloss):
    return (1.0 - CRYTEK_GLOSS_SCALE * _f(gloss)) ** 2


def alpha_from_gloss_Unreal(gloss):
    return (1.0 - _f(gloss)) ** 2


def specPower_from_alpha(alpha):
    """Walter et al. 2007 §5.2: s = 2 / alpha^2 - 2."""
    return 2.0 / _f(alpha) ** 2 - 2.0


def alpha_from_specPower(spec_power):
    return np.sqrt(2.0 / (_f(spec_power) + 2.0))
