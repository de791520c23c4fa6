"""BRDF term references: glsl/pbr/brdf/, one function per GLSL function, in the
textbook form of each formula (the GLSL may be rearranged for float32; see its comments).

Conventions as in glsl/pbr/common/conventions.glsl: D_ distributions (1/sr), G_ the
masking-shadowing G, V_ = G / (4 NdotL NdotV), F_ Fresnel, Fd_ diffuse BRDFs with 1/π.
"""

import numpy as np

from .constants import INV_PI, PI

# Lagarde 2012 / Karis 2013 spherical-Gaussian Fresnel fit (PBR_F_SCHLICK_SG_A/B)
F_SCHLICK_SG_A = -5.55473
F_SCHLICK_SG_B = -6.98316
BURLEY_FD90_BASE = 0.5  # PBR_BURLEY_FD90_BASE
# Documented error bounds of two approximations (glsl comments; measured in float64):
V_SMITH_GGX_CORRELATED_FAST_MAX_REL_ERROR = 0.293  # Hammon 2017 vs Heitz 2014, measured 0.2922
F_SCHLICK_SG_MAX_ABS_ERROR = 0.0038                # SG vs Schlick, measured 0.00377 (F0 = 0)


def _f(x):
    return np.asarray(x, dtype=np.float64)


# ---- diffuse -------------------------------------------------------------------------

def Fd_Lambert():
    return INV_PI


def Fd_Burley(NdotV, NdotL, LdotH, perceptual_roughness):
    """Burley 2012 §5.3, with its 1/π."""
    NdotV, NdotL, LdotH, r = map(_f, (NdotV, NdotL, LdotH, perceptual_roughness))
    fd90 = BURLEY_FD90_BASE + 2.0 * r * LdotH ** 2
    return (1.0 + (fd90 - 1.0) * (1.0 - NdotL) ** 5) * (1.0 + (fd90 - 1.0) * (1.0 - NdotV) ** 5) / PI


# ---- Blinn-Phong lighting models (per unit M_spec) ------------------------------------

def BRDF_BlinnPhongClassic(NdotH, NdotL, spec_power):
    NdotH, NdotL, s = map(_f, (NdotH, NdotL, spec_power))
    with np.errstate(divide="ignore", invalid="ignore"):
        value = NdotH ** s / (PI * NdotL)
    return np.where(NdotL > 0.0, value, 0.0)


def BRDF_BlinnPhongModified(NdotH, spec_power):
    return _f(NdotH) ** _f(spec_power) / PI


def BRDF_BlinnPhongNormalized(NdotH, spec_power):
    s = _f(spec_power)
    return (s + 8.0) / (8.0 * PI) * _f(NdotH) ** s


# ---- distributions ---------------------------------------------------------------------

def D_BlinnPhong(NdotH, spec_power):
    s = _f(spec_power)
    return (s + 2.0) / (2.0 * PI) * _f(NdotH) ** s


def D_GGX(NdotH, alpha):
    """Walter et al. 2007 eq. 33, the lecture's form."""
    NdotH, a2 = _f(NdotH), _f(alpha) ** 2
    return a2 / (PI * (NdotH ** 2 * (a2 - 1.0) + 1.0) ** 2)


def D_GGX_from_one_minus(NdotH, one_minus_NdotH2, alpha):
    """Walter et al. 2007 eq. 33 with its denominator rearranged, NdotH²(alpha² - 1) + 1 =
    (1 - NdotH²) + NdotH² alpha², and 1 - NdotH² given (the same as D_GGX when it is)."""
    NdotH, a2 = _f(NdotH), _f(alpha) ** 2
    return a2 / (PI * (_f(one_minus_NdotH2) + NdotH ** 2 * a2) ** 2)


def D_GGX_from_sin2(sin2_theta_h, alpha):
    """Walter et al. 2007 eq. 33 in sin²θh = 1 - NdotH²: NdotH²(alpha² - 1) + 1 =
    alpha² + (1 - alpha²) sin²θh, a sum of non-negative terms (dv_ggx_smith_correlated.glsl)."""
    a2 = _f(alpha) ** 2
    return a2 / (PI * (a2 + (1.0 - a2) * _f(sin2_theta_h)) ** 2)


def D_Beckmann(NdotH, alpha):
    """Walter et al. 2007 eq. 25; 0 at NdotH = 0 (the limit)."""
    NdotH, a2 = _f(NdotH), _f(alpha) ** 2
    c2 = NdotH ** 2
    with np.errstate(divide="ignore", invalid="ignore"):
        value = np.exp((c2 - 1.0) / (a2 * c2)) / (PI * a2 * c2 ** 2)
    return np.where(NdotH > 0.0, value, 0.0)


# ---- masking-shadowing and visibility -------------------------------------------------

def G_CookTorrance(NdotL, NdotV, NdotH, VdotH):
    NdotL, NdotV, NdotH, VdotH = map(_f, (NdotL, NdotV, NdotH, VdotH))
    return np.minimum(1.0, np.minimum(2.0 * NdotH * NdotV / VdotH, 2.0 * NdotH * NdotL / VdotH))


def V_CookTorrance(NdotL, NdotV, NdotH, VdotH):
    return G_CookTorrance(NdotL, NdotV, NdotH, VdotH) / (4.0 * _f(NdotL) * _f(NdotV))


def G1_SmithGGX(NdotX, alpha):
    """Walter et al. 2007 eq. 34: 2 / (1 + sqrt(1 + alpha^2 tan^2)), via the tangent."""
    c, a2 = _f(NdotX), _f(alpha) ** 2
    with np.errstate(divide="ignore", invalid="ignore"):
        tan2 = (1.0 - c * c) / (c * c)
        g1 = 2.0 / (1.0 + np.sqrt(1.0 + a2 * tan2))
    return np.where(c > 0.0, g1, 0.0)


def G_SmithGGX(NdotL, NdotV, alpha):
    return G1_SmithGGX(NdotL, alpha) * G1_SmithGGX(NdotV, alpha)


def V_SmithGGX(NdotL, NdotV, alpha):
    """The lecture's Viz_GGX-R (separable), written without the cosines."""
    NdotL, NdotV, a2 = _f(NdotL), _f(NdotV), _f(alpha) ** 2
    return 1.0 / ((NdotV + np.sqrt(a2 + (1.0 - a2) * NdotV ** 2))
                  * (NdotL + np.sqrt(a2 + (1.0 - a2) * NdotL ** 2)))


def G1_SchlickGGX(NdotX, k):
    c, k = _f(NdotX), _f(k)
    return c / (c * (1.0 - k) + k)


def G_SchlickGGX(NdotL, NdotV, k):
    return G1_SchlickGGX(NdotL, k) * G1_SchlickGGX(NdotV, k)


def V_SchlickGGX(NdotL, NdotV, k):
    NdotL, NdotV, k = map(_f, (NdotL, NdotV, k))
    return 1.0 / (4.0 * (NdotL * (1.0 - k) + k) * (NdotV * (1.0 - k) + k))


def k_SchlickGGX_from_alpha(alpha):
    return _f(alpha) / 2.0


def k_SchlickGGX_hotness(perceptual_roughness):
    return (0.5 + _f(perceptual_roughness) / 2.0) ** 2 / 2.0


def lambda_GGX(NdotX, alpha):
    """Heitz 2014: Λ(x) = (sqrt(1 + alpha^2 tan^2 θx) - 1) / 2."""
    c, a2 = _f(NdotX), _f(alpha) ** 2
    return (np.sqrt(1.0 + a2 * (1.0 - c * c) / (c * c)) - 1.0) / 2.0


def G2_SmithGGXCorrelated(NdotL, NdotV, alpha):
    """Heitz 2014 eq. 99: G2 = 1 / (1 + Λ(v) + Λ(l))."""
    return 1.0 / (1.0 + lambda_GGX(NdotV, alpha) + lambda_GGX(NdotL, alpha))


def V_SmithGGXCorrelated(NdotL, NdotV, alpha):
    """Height-correlated visibility, from G2 / (4 NdotL NdotV) (not the GLSL's rearrangement)."""
    return G2_SmithGGXCorrelated(NdotL, NdotV, alpha) / (4.0 * _f(NdotL) * _f(NdotV))


def V_SmithGGXCorrelatedFast(NdotL, NdotV, alpha):
    """Hammon 2017: G2 ≈ 2 NdotL NdotV / lerp(2 NdotL NdotV, NdotL + NdotV, alpha)."""
    NdotL, NdotV, alpha = map(_f, (NdotL, NdotV, alpha))
    lerp = 2.0 * NdotL * NdotV * (1.0 - alpha) + (NdotL + NdotV) * alpha
    return 0.5 / lerp


def V_SmithGGXBound(NdotL, NdotV):
    """Heitz 2014 eq. 99 with each square root bounded by 1: 0.5 / (NdotL + NdotV) <= V."""
    return 0.5 / (_f(NdotL) + _f(NdotV))


def G_Implicit(NdotL, NdotV):
    return _f(NdotL) * _f(NdotV)


def V_Implicit():
    return 0.25


def G_Kelemen(NdotL, NdotV, VdotH):
    return _f(NdotL) * _f(NdotV) / _f(VdotH) ** 2


def V_Kelemen(VdotH):
    return 0.25 / _f(VdotH) ** 2


# ---- Fresnel --------------------------------------------------------------------------

def F_Schlick(f0, VdotH, f90=1.0):
    """Schlick 1994, elementwise (for RGB f0 [..., 3] pass VdotH[..., None])."""
    f0 = _f(f0)
    return f0 + (_f(f90) - f0) * (1.0 - _f(VdotH)) ** 5


def F_SchlickSG(f0, VdotH, f90=1.0):
    """Lagarde 2012 / Karis 2013 spherical-Gaussian Schlick, elementwise."""
    f0, VdotH = _f(f0), _f(VdotH)
    return f0 + (_f(f90) - f0) * 2.0 ** ((F_SCHLICK_SG_A * VdotH + F_SCHLICK_SG_B) * VdotH)


# Schüler 2009 (ShaderX7 ch. 2.6) as written in Filament's brdf.fs: f90 = saturate(dot(f0,
# vec3(50 * 0.33))). Shared with glsl/pbr/brdf/f_schlick.glsl PBR_F90_FROM_F0_SCALE.
F90_FROM_F0_SCALE = 50 * 0.33


def f90_from_f0(f0):
    """Grazing reflectance that follows F0 (F0 = 0 -> 0; grey F0 >= 0.0202 -> 1); last axis RGB."""
    return np.clip(np.sum(_f(f0), axis=-1) * F90_FROM_F0_SCALE, 0.0, 1.0)


def F_Dielectric(cos_theta, eta):
    """Exact unpolarised Fresnel from Snell's law and the s/p amplitude ratios
    (Born & Wolf §1.5.3), an independent formulation of Walter 2007 eq. 22."""
    ci, eta = np.abs(_f(cos_theta)), _f(eta)
    sin2_t = (1.0 - ci * ci) / (eta * eta)
    tir = sin2_t >= 1.0
    ct = np.sqrt(np.maximum(1.0 - sin2_t, 0.0))
    with np.errstate(divide="ignore", invalid="ignore"):
        rs = ((ci - eta * ct) / (ci + eta * ct)) ** 2
        rp = ((ct - eta * ci) / (ct + eta * ci)) ** 2
    return np.where(tir, 1.0, 0.5 * (rs + rp))
