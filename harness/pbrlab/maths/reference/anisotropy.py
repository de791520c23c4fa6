"""Anisotropic specular references: glsl/pbr/brdf/d_ggx_anisotropic.glsl,
glsl/pbr/brdf/v_smith_ggx_correlated_anisotropic.glsl and glsl/pbr/shading/anisotropy.glsl,
in float64 and in the textbook form of each formula, plus a deterministic quadrature of the
exact anisotropic specular integral (the white furnace and the bent-normal measurement).

Sources:
  * Burley 2012, "Physically-Based Shading at Disney", appendix B.2 (anisotropic GTR2 = GGX);
    Heitz 2014, "Understanding the Masking-Shadowing Function in Microfacet-Based BRDFs",
    JCGT 3(2): the stretched (anisotropic) GGX, its Λ with the projected roughness
    α(ω)² = cos²φ αt² + sin²φ αb², and the height-correlated G2 = 1/(1 + Λ(v) + Λ(l)) (eq. 99).
  * Khronos, KHR_materials_anisotropy: alphaT = mix(alphaRoughness, 1, strength²),
    alphaB = alphaRoughness; the direction texture's rg in [-1, 1] rotated by
    anisotropyRotation counter-clockwise from the tangent.
  * The bent reflection normal of the Khronos glTF sample viewer (getIBLRadianceAnisotropy).

Frames: t, b, n orthonormal; in the quadratures t = x, b = y, n = z.
"""

from __future__ import annotations

import math

import numpy as np

from . import shading
from .brdf import F_Schlick, f90_from_f0
from .constants import PI


def _f(x):
    return np.asarray(x, dtype=np.float64)


def _dot(a, b):
    return np.sum(_f(a) * _f(b), axis=-1)


# ---- terms ----------------------------------------------------------------------------

def D_GGX_Anisotropic(NdotH, TdotH, BdotH, alpha_t, alpha_b):
    """Burley 2012 appendix B.2 / Heitz 2014: 1 / (π αt αb (T²/αt² + B²/αb² + N²)²)."""
    N, T, B, at, ab = map(_f, (NdotH, TdotH, BdotH, alpha_t, alpha_b))
    return 1.0 / (PI * at * ab * (T ** 2 / at ** 2 + B ** 2 / ab ** 2 + N ** 2) ** 2)


def lambda_GGX_Anisotropic(NdotX, TdotX, BdotX, alpha_t, alpha_b):
    """Heitz 2014: Λ = (sqrt(1 + α(ω)² tan²θ) - 1) / 2 with α(ω)² = cos²φ αt² + sin²φ αb²,
    written through the angles (cos φ = T / sin θ, tan θ = sin θ / N)."""
    N, T, B, at, ab = map(_f, (NdotX, TdotX, BdotX, alpha_t, alpha_b))
    sin2 = T ** 2 + B ** 2
    with np.errstate(divide="ignore", invalid="ignore"):
        cos2_phi = np.where(sin2 > 0.0, T ** 2 / np.where(sin2 > 0.0, sin2, 1.0), 1.0)
        alpha2 = cos2_phi * at ** 2 + (1.0 - cos2_phi) * ab ** 2
        tan2 = sin2 / N ** 2
    return (np.sqrt(1.0 + alpha2 * tan2) - 1.0) / 2.0


def G2_SmithGGXCorrelated_Anisotropic(NdotL, NdotV, TdotV, BdotV, TdotL, BdotL, alpha_t, alpha_b):
    """Heitz 2014 eq. 99 with the anisotropic Λ."""
    return 1.0 / (1.0 + lambda_GGX_Anisotropic(NdotV, TdotV, BdotV, alpha_t, alpha_b)
                  + lambda_GGX_Anisotropic(NdotL, TdotL, BdotL, alpha_t, alpha_b))


def V_SmithGGXCorrelated_Anisotropic(NdotL, NdotV, TdotV, BdotV, TdotL, BdotL, alpha_t, alpha_b):
    """V = G2 / (4 NdotL NdotV) (not the GLSL's rearrangement)."""
    G2 = G2_SmithGGXCorrelated_Anisotropic(NdotL, NdotV, TdotV, BdotV, TdotL, BdotL, alpha_t, alpha_b)
    return G2 / (4.0 * _f(NdotL) * _f(NdotV))


# ---- the extension's mapping ------------------------------------------------------------

def anisotropic_alphas(alpha, strength):
    """KHR_materials_anisotropy: (alphaT, alphaB) = (mix(alpha, 1, s²), alpha); last axis 2.
    As the GLSL: alpha saturated, s² capped at 1."""
    alpha = np.clip(_f(alpha), 0.0, 1.0)
    s2 = np.minimum(_f(strength) ** 2, 1.0)
    alpha, s2 = np.broadcast_arrays(alpha, s2)
    return np.stack([alpha + (1.0 - alpha) * s2, alpha], axis=-1)


def anisotropy_direction(t, b, direction_sample, rotation):
    """KHR_materials_anisotropy: the sample (x, y) in [-1, 1]² rotated counter-clockwise by
    ``rotation`` (radians) in the (t, b) plane, normalised; a zero sample reads as (1, 0)."""
    d = _f(direction_sample)
    zero = np.sum(d * d, axis=-1, keepdims=True) == 0.0
    d = np.where(zero, np.array([1.0, 0.0]), d)
    c, s = np.cos(_f(rotation))[..., None], np.sin(_f(rotation))[..., None]
    x, y = d[..., :1], d[..., 1:2]
    out = _f(t) * (c * x - s * y) + _f(b) * (s * x + c * y)
    return out / np.linalg.norm(out, axis=-1, keepdims=True)


def brdf_anisotropic_specular(n, v, l, t, b, f0, perceptual_roughness, strength, quality="HIGH", f90=None):
    """D · V · F of the anisotropic lobe (1/sr, RGB on the last axis), with the edges of
    glsl/pbr/shading/anisotropy.glsl: roughness clamped to the tier's floor, NdotV clamped,
    0 for NdotL <= 0, for l = -v and for h below the surface (min(NdotL, n·(l + v)) < 2^-50).
    ``f90``: an explicit F90 (pbr_brdf_anisotropic_specular_f90), else F90 from F0."""
    n, v, l, t, b = map(_f, (n, v, l, t, b))
    NdotL = _dot(n, l)
    NdotV = np.clip(_dot(n, v), shading.MIN_NDOTV, 1.0)
    r = shading.clamp_perceptual_roughness(perceptual_roughness, quality)
    alphas = anisotropic_alphas(_f(r) ** 2, strength)
    at, ab = alphas[..., 0], alphas[..., 1]
    s = l + v
    s2 = _dot(s, s)
    # pbr_brdf_standard's selection in every tier (issue 25): NdotL and n·(l + v) reach 2^-50
    ok = np.minimum(NdotL, _dot(n, s)) >= shading.MIN_NDOT_HALF_SUM
    safe = np.where(ok[..., None], s, n)
    h = safe / np.linalg.norm(safe, axis=-1, keepdims=True)
    D = D_GGX_Anisotropic(_dot(n, h), _dot(t, h), _dot(b, h), at, ab)
    NdotL_safe = np.where(ok, np.maximum(NdotL, shading.MIN_NDOTV), 1.0)
    V = V_SmithGGXCorrelated_Anisotropic(NdotL_safe, NdotV, _dot(t, v), _dot(b, v), _dot(t, l), _dot(b, l), at, ab)
    DV = np.minimum(np.where(ok, D * V, 0.0), shading.QUALITY_MAX_SPECULAR_LOBE[quality])
    f0 = _f(f0)
    VdotH = 0.5 * np.sqrt(s2)
    f90 = f90_from_f0(f0) if f90 is None else _f(f90)
    return DV[..., None] * F_Schlick(f0, VdotH[..., None], f90[..., None])


def anisotropic_bent_normal(n, v, anisotropic_direction, strength, perceptual_roughness):
    """Khronos sample viewer: normalize(mix(cross(cross(d, v), d), n, bend⁴)),
    bend = 1 - s (1 - r), s = min(|strength|, 1), r saturated; n where the mix vanishes."""
    n, v, d = map(_f, (n, v, anisotropic_direction))
    s = np.minimum(np.abs(_f(strength)), 1.0)[..., None]
    r = np.clip(_f(perceptual_roughness), 0.0, 1.0)[..., None]
    anisotropic_normal = np.cross(np.cross(d, v), d)
    w = (1.0 - s * (1.0 - r)) ** 4
    bent = anisotropic_normal * (1.0 - w) + n * w
    length = np.linalg.norm(bent, axis=-1, keepdims=True)
    return np.where(length > 0.0, bent / np.where(length > 0.0, length, 1.0), n)


# ---- quadrature of the exact specular integral ------------------------------------------
#
# Over the half vector h, importance-parameterised by the anisotropic GGX itself (Heitz 2014,
# the slope-space form of the stretched distribution): with u in [0, 1), φ in [0, 2π),
#   r = sqrt(u / (1 - u)),  h ∝ (αt r cos φ, αb r sin φ, 1),
# the measure is exactly D(h) (n·h) dω_h = du dφ / (2π) (slope density
# 1/(π αt αb (1 + r²)²), dω_h = cos³θ_h d(slopes), D = P22 / cos⁴θ_h). So, with
# l = 2 (v·h) h - v and dω_l = 4 (v·h) dω_h,
#   ∫ f(l, v) L(l) (n·l)+ dω_l = ∫ V F L(l) (n·l)+ 4 (v·h) / (n·h) · D (n·h) dω_h,
# a smooth integrand in (u, φ) but for the horizon n·l = 0, where it falls to 0 continuously
# (a kink): u is Gauss-Legendre on panels (after the substitution below), φ the trapezoid
# rule (periodic). Doubling both node counts changes the albedo by little (measured and bounded in tests/library/test_anisotropy.py), and at strength
# 0 it agrees with reference/directional_albedo.py's independent quadrature.

# u = 1 - (1 - s)²: the integrand carries 1/(n·h) ~ α / sqrt(1 - u) near the horizon
# (integrable, but it leaves Gauss-Legendre in u a sqrt(tail) error at grazing views), and
# du = 2 (1 - s) ds cancels it. s panels halve towards s = 1 until 1 - s < S_TAIL · min(αt, αb)
# (h sweeps from near n to the horizon over 1 - s ~ α), and a last panel closes at s = 1.
# For a view v, each azimuth's panels are cut at the s where n·l = 0 (found by bisection:
# n·l = n·v > 0 at s = 0, -n·v < 0 at s = 1, one crossing along an azimuth), so the kink
# of the horizon is a panel edge and Gauss-Legendre converges spectrally on both sides.
S_TAIL = 1e-3
U_NODES = 24       # Gauss-Legendre nodes per s panel
PHI_NODES = 384    # trapezoid nodes on [0, 2π)
_BISECTIONS = 60   # halvings of [0, 1]: below float64 resolution


def _half_vectors(alpha_t, alpha_b, s, phi):
    """h(s, φ) for broadcast s, φ: ∝ (αt r cos φ, αb r sin φ, 1) times 1 - s = sqrt(1 - u),
    finite up to s = 1."""
    rs = np.sqrt(1.0 - (1.0 - s) ** 2)
    h = np.stack(np.broadcast_arrays(alpha_t * rs * np.cos(phi), alpha_b * rs * np.sin(phi), 1.0 - s + 0.0 * phi),
                 axis=-1)
    return h / np.linalg.norm(h, axis=-1, keepdims=True)


def _horizon_s(alpha_t, alpha_b, v, phi):
    """Per azimuth, the s in (0, 1) where n·l = 2 (v·h)(n·h) - n·v crosses 0."""
    lo, hi = np.zeros_like(phi), np.ones_like(phi)
    for _ in range(_BISECTIONS):
        mid = 0.5 * (lo + hi)
        h = _half_vectors(alpha_t, alpha_b, mid, phi)
        lit = 2.0 * (h @ v) * h[..., 2] - v[2] > 0.0
        lo, hi = np.where(lit, mid, lo), np.where(lit, hi, mid)
    return lo


def half_vector_quadrature(alpha_t, alpha_b, v=None, u_nodes=U_NODES, phi_nodes=PHI_NODES):
    """Unit half vectors h [..., 3] (t = x, b = y, n = z) and weights w with
    Σ w g(h) ≈ ∫ g(h) D(h) (n·h) dω_h for the anisotropic GGX (αt, αb); with a view v (n·v > 0),
    over the half vectors whose reflection l = reflect(-v, h) is above the horizon only."""
    alpha_t, alpha_b = float(alpha_t), float(alpha_b)
    x, wx = np.polynomial.legendre.leggauss(u_nodes)
    panels = max(1, math.ceil(-math.log2(S_TAIL * min(alpha_t, alpha_b))))
    edges = np.concatenate([[0.0], 1.0 - 0.5 ** np.arange(1, panels + 1), [1.0]])
    phi = np.arange(phi_nodes) * (2.0 * math.pi / phi_nodes)
    edges = np.broadcast_to(edges, (phi_nodes, edges.size))
    if v is not None:
        edges = np.minimum(edges, _horizon_s(alpha_t, alpha_b, _f(v), phi)[:, None])
    a, c = edges[:, :-1, None], edges[:, 1:, None]                    # (φ, panel, 1)
    s = (0.5 * (c - a) * x + 0.5 * (c + a)).reshape(phi_nodes, -1)
    ws = (0.5 * (c - a) * wx).reshape(phi_nodes, -1)
    h = _half_vectors(alpha_t, alpha_b, s, phi[:, None])
    w = ws * 2.0 * (1.0 - s) / phi_nodes
    return h.reshape(-1, 3), w.ravel()


def specular_integral(v, alpha_t, alpha_b, radiance=None, f0=None, **quadrature):
    """∫ D V F L(l) (n·l)+ dω_l for the unit view v (t = x, b = y, n = z), float64.
    F = 1 when f0 is None (else Schlick with the library's F90, grey f0); L = 1 when
    ``radiance`` is None (else a function of unit directions [..., 3])."""
    v = _f(v)
    h, w = half_vector_quadrature(alpha_t, alpha_b, v, **quadrature)
    VdotH = h @ v
    l = 2.0 * VdotH[:, None] * h - v
    NdotL, NdotV, NdotH = l[:, 2], v[2], h[:, 2]
    ok = (NdotL > 0.0) & (VdotH > 0.0)
    NdotL_safe = np.where(ok, NdotL, 1.0)
    V = V_SmithGGXCorrelated_Anisotropic(NdotL_safe, NdotV, v[0], v[1], l[:, 0], l[:, 1], alpha_t, alpha_b)
    g = V * NdotL_safe * 4.0 * VdotH / NdotH
    if f0 is not None:
        f0 = float(f0)
        g = g * F_Schlick(f0, VdotH, f90_from_f0(np.full(3, f0)))
    if radiance is not None:
        g = g * radiance(l)
    return float(np.sum(np.where(ok, g, 0.0) * w))


def directional_albedo(v, alpha_t, alpha_b, **quadrature):
    """The white furnace: ∫ f (n·l) dω_l at F = 1, L = 1 (<= 1 for a single-scattering lobe)."""
    return specular_integral(v, alpha_t, alpha_b, **quadrature)


# ---- the test environment and the image-based approximation -----------------------------

# A deterministic, analytic environment (radiance, linear): a sky brightening towards the
# zenith and a compact sun, a spherical Gaussian exp(λ (l·c - 1)) of angular width ~1/sqrt(λ)
# = 0.2 rad, off every symmetry plane of the lobe frame (so the lobe's stretch matters).
ENV_SKY = (0.2, 0.3)                                   # L_sky = 0.2 + 0.3 z
ENV_SUN_DIRECTION = (0.45, 0.3, math.sqrt(1.0 - 0.45 ** 2 - 0.3 ** 2))
ENV_SUN_SHARPNESS = 25.0
ENV_SUN_INTENSITY = 4.0


def test_environment(l):
    """Radiance of the test environment for unit directions l [..., 3] (t = x, b = y, n = z)."""
    l = _f(l)
    c = np.asarray(ENV_SUN_DIRECTION)
    return (ENV_SKY[0] + ENV_SKY[1] * l[..., 2]
            + ENV_SUN_INTENSITY * np.exp(ENV_SUN_SHARPNESS * (l @ c - 1.0)))


def _frame(z):
    """An orthonormal frame (x, y, z) around the unit vector z."""
    z = _f(z)
    helper = np.array([1.0, 0.0, 0.0]) if abs(z[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
    x = np.cross(helper, z)
    x /= np.linalg.norm(x)
    return x, np.cross(z, x), z


def prefiltered_radiance(r, alpha, radiance=test_environment, **quadrature):
    """The GGX-prefiltered environment at the reflection direction r (Karis 2013, "Real Shading
    in Unreal Engine 4", eq. 7 with n = v = r: ∫ L(l) (r·l)+ D dl / ∫ (r·l)+ D dl, l sampled
    from the isotropic GGX of ``alpha``), what a prefiltered cubemap returns at r."""
    h_local, w = half_vector_quadrature(alpha, alpha, (0.0, 0.0, 1.0), **quadrature)
    x, y, z = _frame(r)
    h = h_local[:, :1] * x + h_local[:, 1:2] * y + h_local[:, 2:] * z
    RdotH = h_local[:, 2]
    l = 2.0 * RdotH[:, None] * h - _f(r)
    weight = np.maximum(l @ _f(r), 0.0) * w
    return float(np.sum(radiance(l) * weight) / np.sum(weight))


def reflect(incident, normal):
    incident, normal = _f(incident), _f(normal)
    return incident - 2.0 * _dot(normal, incident)[..., None] * normal


def image_based_specular(v, bent_normal, perceptual_roughness, strength, radiance=test_environment):
    """The sample viewer's anisotropic IBL specular at F = 1: the prefiltered environment at
    reflect(-v, bentNormal), isotropic roughness perceptualRoughness² (lod from
    perceptualRoughness), times the EXACT anisotropic directional albedo, so that the error
    against specular_integral measures the bent normal (the lobe's direction and shape),
    not the split-sum albedo."""
    alphas = anisotropic_alphas(float(perceptual_roughness) ** 2, strength)
    r = reflect(-_f(v), _f(bent_normal))
    r = r / np.linalg.norm(r)
    albedo = directional_albedo(v, alphas[0], alphas[1])
    return prefiltered_radiance(r, float(perceptual_roughness) ** 2, radiance) * albedo


# Measured by tests/library/test_anisotropy.py::test_bent_normal_error_against_exact_integral
# (GPU bent normal, float64 integrals, the grid BENT_NORMAL_GRID under test_environment):
# worst |approx / exact - 1| of the bent-normal image-based specular. Shared with
# glsl/pbr/shading/anisotropy.glsl PBR_ANISOTROPIC_BENT_NORMAL_MAX_REL_ERROR.
BENT_NORMAL_MAX_REL_ERROR = 2.05
# (perceptual roughness, strength, view polar angle in degrees, view azimuth from t in degrees)
BENT_NORMAL_GRID = {"roughness": (0.2, 0.4, 0.6, 0.8), "strength": (0.5, 1.0), "theta_v": (0, 45, 70),
                    "phi_v": (0, 60)}
