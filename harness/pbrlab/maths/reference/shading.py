"""Variant dispatch, the standard BRDF and punctual lighting:
glsl/pbr/shading/dispatch.glsl, standard.glsl and glsl/pbr/lighting/punctual.glsl.

Variant keywords mirror the GLSL selectors: ``specular_d="BECKMANN"`` is
``#define PBR_SPECULAR_D PBR_SPECULAR_D_BECKMANN``; ``glsl_defines`` builds that dict for
``pbrlab.evaluate(..., defines=...)``.
"""

import numpy as np

from . import brdf, remap
from .constants import LIGHT_UNIT_SCALE
from .guards import FLT_MIN, HALF_MAX, MIN_HALF_VECTOR_LENGTH_SQUARED, MIN_NDOT_HALF_SUM, MIN_NDOTV, MIN_VDOTH  # noqa: F401

# Edge constants, shared with glsl/pbr/shading/dispatch.glsl (tested equal).
MIN_PERCEPTUAL_ROUGHNESS = 0.045          # PBR_MIN_PERCEPTUAL_ROUGHNESS (Filament)
MIN_PERCEPTUAL_ROUGHNESS_MEDIUMP = 0.089  # PBR_MIN_PERCEPTUAL_ROUGHNESS_MEDIUMP (Filament mobile)

# Selector values in #define order (PBR_SPECULAR_D_GGX = 1, ...; every family counts from 1).
SPECULAR_D = ("GGX", "BECKMANN", "BLINN_PHONG")
SPECULAR_V = ("SMITH_GGX_CORRELATED", "SMITH_GGX_CORRELATED_FAST", "SMITH_GGX", "SCHLICK_GGX",
              "COOK_TORRANCE", "KELEMEN", "IMPLICIT", "SMITH_GGX_BOUND")
SPECULAR_F = ("SCHLICK", "SCHLICK_SG", "NONE", "F0")
DIFFUSE = ("LAMBERT", "BURLEY")
QUALITY = ("LOW", "HIGH", "MEDIUM")
# PBR_QUALITY -> default PBR_SPECULAR_V and PBR_SPECULAR_F (the tier block of dispatch.glsl)
QUALITY_DEFAULT_V = {"LOW": "SMITH_GGX_BOUND", "MEDIUM": "SMITH_GGX_CORRELATED_FAST",
                     "HIGH": "SMITH_GGX_CORRELATED"}
# (every tier keeps Schlick's Fresnel rise since issue 35; F0, F = f0, is an explicit choice only)
QUALITY_DEFAULT_F = {"LOW": "SCHLICK", "MEDIUM": "SCHLICK", "HIGH": "SCHLICK"}
# PBR_QUALITY -> PBR_TIER_MIN_PERCEPTUAL_ROUGHNESS and the cap of pbr_specular_lobe_limit
QUALITY_MIN_PERCEPTUAL_ROUGHNESS = {"LOW": MIN_PERCEPTUAL_ROUGHNESS_MEDIUMP,
                                    "MEDIUM": MIN_PERCEPTUAL_ROUGHNESS, "HIGH": MIN_PERCEPTUAL_ROUGHNESS}
# (HALF_MAX in LOW only where floats may be 16-bit, PBR_HALF_ARITHMETIC: not in float32 GLSL)
QUALITY_MAX_SPECULAR_LOBE = {"LOW": np.inf, "MEDIUM": np.inf, "HIGH": np.inf}
# PBR_QUALITY -> default PBR_ENERGY_COMPENSATION (issue 35: LOW's environment read is single
# scattering; PBR_IBL_DOMINANT_DIRECTION and PBR_IBL_HORIZON_OCCLUSION, also off in LOW, change
# nothing under the constant environments and unmapped normals the float64 renderer draws)
QUALITY_ENERGY_COMPENSATION = {"LOW": False, "MEDIUM": True, "HIGH": True}
# PBR_QUALITY -> default PBR_SPECULAR_OCCLUSION (surface.specular_occlusion)
QUALITY_SPECULAR_OCCLUSION = {"LOW": "AMBIENT", "MEDIUM": "LAGARDE", "HIGH": "LAGARDE"}
# PBR_QUALITY -> default PBR_DFG_LUT_LAYOUT (surface.dfg_lut_axes; the table the renderer binds)
QUALITY_DFG_LUT_LAYOUT = {"LOW": "SQRT", "MEDIUM": "WARPED", "HIGH": "WARPED"}


def _variants(specular_d, specular_v, specular_f, diffuse, quality):
    if quality not in QUALITY:
        raise ValueError(f"quality={quality!r}: expected one of {QUALITY}")
    if specular_v is None:
        specular_v = QUALITY_DEFAULT_V[quality]
    if specular_f is None:
        specular_f = QUALITY_DEFAULT_F[quality]
    for value, allowed, name in ((specular_d, SPECULAR_D, "specular_d"), (specular_v, SPECULAR_V, "specular_v"),
                                 (specular_f, SPECULAR_F, "specular_f"), (diffuse, DIFFUSE, "diffuse"),
                                 (quality, QUALITY, "quality")):
        if value not in allowed:
            raise ValueError(f"{name}={value!r}: expected one of {allowed}")
    return specular_d, specular_v, specular_f, diffuse


def glsl_defines(specular_d=None, specular_v=None, specular_f=None, diffuse=None, quality=None):
    """The #defines selecting these variants in GLSL (unset arguments keep the GLSL default)."""
    out = {}
    for macro, value in (("PBR_SPECULAR_D", specular_d), ("PBR_SPECULAR_V", specular_v),
                         ("PBR_SPECULAR_F", specular_f), ("PBR_DIFFUSE", diffuse),
                         ("PBR_QUALITY", quality)):
        if value is not None:
            out[macro] = f"{macro}_{value}"
    return out


def specular_D(NdotH, alpha, variant="GGX"):
    if variant == "GGX":
        return brdf.D_GGX(NdotH, alpha)
    if variant == "BECKMANN":
        return brdf.D_Beckmann(NdotH, alpha)
    if variant == "BLINN_PHONG":
        return brdf.D_BlinnPhong(NdotH, remap.specPower_from_alpha(alpha))
    raise ValueError(variant)


def specular_V(NdotL, NdotV, NdotH, VdotH, alpha, variant="SMITH_GGX_CORRELATED"):
    """pbr_specular_V, with the guards of the GLSL V terms: NdotL, NdotV clamped to
    [MIN_NDOTV, 1], VdotH to [MIN_VDOTH, 1] (guards.glsl); the brdf.V_* stay exact."""
    VdotH = np.clip(VdotH, MIN_VDOTH, 1.0)
    if variant == "COOK_TORRANCE":  # G takes the saturated cosines, only the 1/(4 NdotL NdotV) is floored
        G = brdf.G_CookTorrance(np.clip(NdotL, 0.0, 1.0), np.clip(NdotV, 0.0, 1.0), NdotH, VdotH)
        return G / (4.0 * np.clip(NdotL, MIN_NDOTV, 1.0) * np.clip(NdotV, MIN_NDOTV, 1.0))
    NdotL = np.clip(NdotL, MIN_NDOTV, 1.0)
    NdotV = np.clip(NdotV, MIN_NDOTV, 1.0)
    if variant == "SMITH_GGX_CORRELATED":
        return brdf.V_SmithGGXCorrelated(NdotL, NdotV, alpha)
    if variant == "SMITH_GGX_CORRELATED_FAST":
        return brdf.V_SmithGGXCorrelatedFast(NdotL, NdotV, alpha)
    if variant == "SMITH_GGX":
        return brdf.V_SmithGGX(NdotL, NdotV, alpha)
    if variant == "SCHLICK_GGX":
        return brdf.V_SchlickGGX(NdotL, NdotV, brdf.k_SchlickGGX_from_alpha(alpha))
    if variant == "COOK_TORRANCE":
        return brdf.V_CookTorrance(NdotL, NdotV, NdotH, VdotH)
    if variant == "KELEMEN":
        return brdf.V_Kelemen(VdotH)
    if variant == "IMPLICIT":
        return np.full(np.shape(NdotL), brdf.V_Implicit())
    if variant == "SMITH_GGX_BOUND":
        return brdf.V_SmithGGXBound(NdotL, NdotV)
    raise ValueError(variant)


def _f90(f0, f90):
    """The grazing reflectance with a trailing axis: the caller's (pbr_specular_F_f90,
    KHR_materials_specular's specularFactor) or, for None, f90_from_f0(f0)."""
    return brdf.f90_from_f0(f0)[..., None] if f90 is None else np.asarray(f90, np.float64)[..., None]


def specular_F(f0, VdotH, variant="SCHLICK", f90=None):
    """pbr_specular_F[_f90]: the Schlick forms take F90 = f90_from_f0(f0) (Schüler 2009 /
    Filament), or the caller's ``f90``."""
    f90 = _f90(f0, f90)
    if variant == "SCHLICK":
        return brdf.F_Schlick(f0, np.asarray(VdotH)[..., None], f90)
    if variant == "SCHLICK_SG":
        return brdf.F_SchlickSG(f0, np.asarray(VdotH)[..., None], f90)
    if variant == "NONE":
        return np.ones(np.broadcast_shapes(np.shape(f0), np.shape(VdotH) + (3,)))
    if variant == "F0":  # no Fresnel rise (an explicit choice; no tier selects it since issue 35)
        return np.broadcast_to(np.asarray(f0, np.float64), np.broadcast_shapes(np.shape(f0), np.shape(VdotH) + (3,)))
    raise ValueError(variant)


def specular_F_deviation_bound(f0, variant="SCHLICK", f90=None):
    """pbr_specular_F_deviation_bound[_f90]: max |F - Schlick(f0, f90)| over VdotH (last axis
    RGB); an explicit ``f90`` must be at least every channel of f0."""
    f0 = np.asarray(f0, dtype=np.float64)
    if variant == "SCHLICK":
        return np.zeros_like(f0)
    if variant == "SCHLICK_SG":
        return brdf.F_SCHLICK_SG_MAX_ABS_ERROR * (_f90(f0, f90) - f0)
    if variant == "NONE":
        return 1.0 - f0
    if variant == "F0":
        return np.zeros_like(f0)
    raise ValueError(variant)


def diffuse_Fd(NdotV, NdotL, LdotH, perceptual_roughness, variant="LAMBERT"):
    if variant == "LAMBERT":
        return np.full(np.broadcast_shapes(np.shape(NdotV), np.shape(NdotL)), brdf.Fd_Lambert())
    if variant == "BURLEY":
        return brdf.Fd_Burley(NdotV, NdotL, LdotH, perceptual_roughness)
    raise ValueError(variant)


def clamp_perceptual_roughness(perceptual_roughness, quality="HIGH"):
    return np.clip(np.asarray(perceptual_roughness, dtype=np.float64),
                   QUALITY_MIN_PERCEPTUAL_ROUGHNESS[quality], 1.0)


def _dot(a, b):
    return np.sum(a * b, axis=-1)


def brdf_standard(n, v, l, diffuse_color, f0, perceptual_roughness, *, specular_d="GGX",
                  specular_v=None, specular_f=None, diffuse="LAMBERT", quality="HIGH", f90=None):
    """pbr_brdf_standard: diffuse_color * Fd + D * V * F, with the same edges as the GLSL
    (NdotL saturated, and n·(l + v) = saturate(NdotL) + n·v: below the horizon the value at
    NdotL = 0, finite, which the caller's max(0, NdotL) makes no light; roughness clamp per
    tier; NdotV clamp; |l + v|² + 2^-126; LdotH = |l+v|/2; no lobe where n·(l + v) < 2^-50:
    h below the surface (χ+, only from a view below the horizon) and l = -v; D · V capped at
    HALF_MAX in the LOW tier). ``f90``: pbr_brdf_standard_f90's
    explicit grazing reflectance (shaped like the leading axes), None for F90 from F0.

    GGX's 1 - NdotH² is |(l + v) - n (n·(l + v))|² / |l + v|² (the GLSL's rejection form:
    |n × ĥ|² for a lit light). V's cosines are floored at MIN_NDOTV, except in the fused GGX
    quotients of the tiers' V (dv_ggx_*.glsl), which take NdotL as it is."""
    d_var, v_var, f_var, fd_var = _variants(specular_d, specular_v, specular_f, diffuse, quality)
    n, v, l, diffuse_color, f0 = (np.asarray(x, dtype=np.float64) for x in (n, v, l, diffuse_color, f0))
    shape = np.broadcast_shapes(n.shape, v.shape, l.shape, diffuse_color.shape, f0.shape,
                                np.shape(perceptual_roughness) + (3,))
    n, v, l, diffuse_color, f0 = (np.broadcast_to(x, shape) for x in (n, v, l, diffuse_color, f0))
    roughness = np.broadcast_to(clamp_perceptual_roughness(perceptual_roughness, quality), shape[:-1])
    alpha = remap.alpha_from_perceptual_roughness(roughness)

    NdotL = np.clip(_dot(n, l), 0.0, 1.0)
    n_dot_v = _dot(n, v)
    NdotV = np.clip(n_dot_v, MIN_NDOTV, 1.0)
    half_sum = l + v
    half_length2 = _dot(half_sum, half_sum) + FLT_MIN  # pbr_length2_nonzero
    LdotH = 0.5 * np.sqrt(half_length2)
    diffuse_part = diffuse_color * diffuse_Fd(NdotV, NdotL, LdotH, roughness, fd_var)[..., None]

    # l + v has a direction above the surface (guards.MIN_NDOT_HALF_SUM, every tier)
    n_dot_half_sum = NdotL + n_dot_v
    has_half = n_dot_half_sum >= MIN_NDOT_HALF_SUM
    rejection = half_sum - n_dot_half_sum[..., None] * n
    sin2 = _dot(rejection, rejection) / half_length2
    n_dot_h = n_dot_half_sum / np.sqrt(half_length2)
    NdotH = np.clip(n_dot_h, 0.0, 1.0)
    VdotH = np.where(has_half, LdotH, 1.0)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        if d_var == "GGX":  # 1 - NdotH² from the rejection: no cancellation at the mirror (every tier)
            D = brdf.D_GGX_from_sin2(sin2, alpha)
        else:
            D = specular_D(NdotH, alpha, d_var)
        if d_var == "GGX" and v_var == "SMITH_GGX_CORRELATED":  # fused: NdotL as it is
            # at NdotL = 0 (below the horizon) the limit of G2 / (4 NdotL NdotV): Λ(l) ~
            # alpha / (2 NdotL) as NdotL -> 0 (Heitz 2014 eq. 72), so V -> 1 / (2 alpha NdotV)
            lit = NdotL > 0.0
            V = np.where(lit, brdf.V_SmithGGXCorrelated(np.where(lit, NdotL, 1.0), NdotV, alpha),
                         0.5 / (NdotV * alpha))
        elif d_var == "GGX" and v_var == "SMITH_GGX_CORRELATED_FAST":
            V = brdf.V_SmithGGXCorrelatedFast(NdotL, NdotV, alpha)
        elif d_var == "GGX" and v_var == "SMITH_GGX_BOUND":  # fused: 0.5 / n·(l + v), n·v as it is
            V = brdf.V_SmithGGXBound(NdotL, n_dot_v)
        else:
            V = specular_V(NdotL, NdotV, NdotH, VdotH, alpha, v_var)
    F = specular_F(f0, VdotH, f_var, None if f90 is None else np.broadcast_to(f90, shape[:-1]))
    lobe = np.minimum(D * V, QUALITY_MAX_SPECULAR_LOBE[quality])
    # χ+(n·h) (Walter et al. 2007 eq. 33): no lobe for h below the surface
    specular_part = np.where(has_half[..., None], lobe[..., None] * F, 0.0)
    return diffuse_part + specular_part


def shade_punctual(n, v, l, light_radiance, diffuse_color, f0, perceptual_roughness, **variants):
    """pbr_shade_punctual: light_radiance * π * BRDF * max(0, NdotL) (the lecture's convention).

    ``variants``: specular_d, specular_v, specular_f, diffuse, quality (see ``glsl_defines``).
    """
    n, l = np.asarray(n, dtype=np.float64), np.asarray(l, dtype=np.float64)
    NdotL = np.clip(_dot(n, l), 0.0, 1.0)
    value = brdf_standard(n, v, l, diffuse_color, f0, perceptual_roughness, **variants)
    return np.asarray(light_radiance, dtype=np.float64) * value * (LIGHT_UNIT_SCALE * NdotL)[..., None]
