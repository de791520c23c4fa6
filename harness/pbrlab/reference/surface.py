"""Float64 references of pbr/ibl/environment_brdf.glsl, pbr/surface/lighting_standard.glsl
and the helpers of pbr/unity/surface_standard.glsl (sources cited in the GLSL)."""

import numpy as np

from . import shading
from .material import DIELECTRIC_F0

MIN_SPECULAR_ALBEDO = 1e-4  # PBR_MIN_SPECULAR_ALBEDO


def _f(x):
    return np.asarray(x, np.float64)


def env_brdf_approx(NdotV, perceptual_roughness):
    """Karis 2014, "Physically Based Shading on Mobile": (A, B) on the last axis."""
    NdotV, r = _f(NdotV), _f(perceptual_roughness)
    c0 = np.array([-1.0, -0.0275, -0.572, 0.022])
    c1 = np.array([1.0, 0.0425, 1.04, -0.04])
    rr = r[..., None] * c0 + c1
    a004 = np.minimum(rr[..., 0] ** 2, np.exp2(-9.28 * NdotV)) * rr[..., 0] + rr[..., 1]
    return np.stack([-1.04 * a004 + rr[..., 2], 1.04 * a004 + rr[..., 3]], axis=-1)


def specular_albedo(f0, dfg):
    return _f(f0) * _f(dfg)[..., 0:1] + _f(dfg)[..., 1:2]


def energy_compensation(f0, dfg):
    """Fdez-Aguera 2019 as in Filament 5.3.4.7: 1 + f0 (1/(A+B) - 1)."""
    e = np.maximum(_f(dfg)[..., 0:1] + _f(dfg)[..., 1:2], MIN_SPECULAR_ALBEDO)
    return 1 + _f(f0) * (1 / e - 1)


def specular_occlusion(NdotV, occlusion, alpha):
    """Lagarde & de Rousiers 2014, listing 26."""
    return np.clip((_f(NdotV) + occlusion) ** np.exp2(-16 * _f(alpha) - 1) - 1 + occlusion, 0, 1)


def indirect_specular_split_sum(prefiltered, f0, perceptual_roughness, NdotV, occlusion, dfg,
                                energy_compensated=True):
    """Scalars and arrays shaped like NdotV; colours with a last axis of 3."""
    spec = _f(prefiltered) * specular_albedo(f0, dfg) * specular_occlusion(
        NdotV, _f(occlusion), _f(perceptual_roughness) ** 2)[..., None]
    return spec * energy_compensation(f0, dfg) if energy_compensated else spec


def one_minus_reflectivity_from_metallic(metallic):
    """Unity: (1 - 0.04) - metallic (1 - 0.04)."""
    return (1 - DIELECTRIC_F0) * (1 - _f(metallic))


def premultiply_alpha(diff_color, alpha, one_minus_reflectivity, transparent):
    """Unity's PreMultiplyAlpha: (diffuse, output alpha)."""
    if not transparent:
        return _f(diff_color), _f(alpha)
    return _f(diff_color) * alpha, 1 - one_minus_reflectivity + alpha * one_minus_reflectivity


def lighting_standard(diffuse_color, f0, perceptual_roughness, occlusion, n, v, light_dir,
                      light_color, indirect_diffuse, prefiltered, dfg, energy_compensated=True,
                      **variants):
    """pbr_lighting_standard: direct (pbr_shade_punctual) + indirect diffuse * occlusion +
    split-sum indirect specular. ``dfg`` is the environment BRDF at (NdotV, roughness).
    Vectors and colours have a last axis of 3; roughness and occlusion have the leading
    shape (or are scalars)."""
    r = shading.clamp_perceptual_roughness(perceptual_roughness)
    NdotV = np.maximum(np.sum(_f(n) * v, axis=-1), shading.MIN_NDOTV)
    direct = shading.shade_punctual(n, v, light_dir, light_color, diffuse_color, f0, r, **variants)
    spec = indirect_specular_split_sum(prefiltered, f0, r, NdotV, occlusion, dfg, energy_compensated)
    return direct + _f(diffuse_color) * _f(indirect_diffuse) * _f(occlusion)[..., None] + spec
