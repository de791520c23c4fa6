"""Float64 references of pbr/shading/clearcoat.glsl and pbr/surface/lighting_clearcoat.glsl:
KHR_materials_clearcoat's coat (the extension README's "Layering": F0 0.04 from IOR 1.5,
coat lobe D · V of its own roughness and normal) with the two base weights the GLSL selects
(sources cited there)."""

import numpy as np

from . import brdf, shading, surface

CLEARCOAT_IOR = 1.5
CLEARCOAT_F0 = ((CLEARCOAT_IOR - 1.0) / (CLEARCOAT_IOR + 1.0)) ** 2  # 0.04
LAYERINGS = ("ALBEDO", "FRESNEL")


def _f(x):
    return np.asarray(x, np.float64)


def clearcoat_punctual(nc, v, l, light_radiance, coat_perceptual_roughness, **variants):
    """The coat's reflection of a punctual light: shade_punctual with no diffuse, f0 0.04."""
    nc = _f(nc)
    zero = np.zeros_like(nc)
    f0 = np.full_like(nc, CLEARCOAT_F0)
    return shading.shade_punctual(nc, v, l, light_radiance, zero, f0, coat_perceptual_roughness, **variants)


def clearcoat_albedo(dfg):
    """f0 A + f90 B at f0 0.04 (f90 = 1), saturated (the analytic DFG fit overshoots 1)."""
    dfg = _f(dfg)
    f90 = brdf.f90_from_f0(np.full(3, CLEARCOAT_F0))
    return np.clip(CLEARCOAT_F0 * dfg[..., 0] + f90 * dfg[..., 1], 0.0, 1.0)


def clearcoat_base_weight(mask, NcdotV, dfg, layering="ALBEDO"):
    """What the base keeps: 1 - mask E_coat (ALBEDO) or 1 - mask F_Schlick(NcdotV) (FRESNEL)."""
    if layering == "FRESNEL":
        reflected = brdf.F_Schlick(CLEARCOAT_F0, NcdotV, 1.0)
    elif layering == "ALBEDO":
        reflected = clearcoat_albedo(dfg)
    else:
        raise ValueError(f"layering {layering!r}: one of {LAYERINGS}")
    return 1.0 - _f(mask) * reflected


def lighting_clearcoat(base, mask, coat_perceptual_roughness, nc, v, light_dir, light_color,
                       coat_prefiltered, occlusion, dfg, layering="ALBEDO", **variants):
    """pbr_lighting_clearcoat with the coat's environment BRDF ``dfg`` at (NcdotV, roughness)
    given (the GPU reads its table; callers pass the float64 integral or the same table)."""
    r = shading.clamp_perceptual_roughness(coat_perceptual_roughness, variants.get("quality", "HIGH"))
    NcdotV = np.maximum(np.sum(_f(nc) * _f(v), axis=-1), shading.MIN_NDOTV)
    direct = clearcoat_punctual(nc, v, light_dir, light_color, r, **variants)
    environment = _f(coat_prefiltered) * (clearcoat_albedo(dfg) * surface.specular_occlusion(
        NcdotV, _f(occlusion), r * r, variants.get("quality", "HIGH")))[..., None]
    weight = clearcoat_base_weight(mask, NcdotV, dfg, layering)
    return _f(base) * weight[..., None] + _f(mask)[..., None] * (direct + environment)
