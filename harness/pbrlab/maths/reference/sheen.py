"""Float64 references of the sheen layer (KHR_materials_sheen): glsl/pbr/brdf/d_charlie.glsl,
glsl/pbr/brdf/v_charlie.glsl and glsl/pbr/shading/sheen.glsl, written from the formulas of

* Estevez & Kulla 2017, "Production Friendly Microfacet Sheen BRDF" (SIGGRAPH 2017 course
  "Physically Based Shading in Theory and Practice"): eq. 2 (the "Charlie" distribution), §3
  (the fitted Λ, table 1's five parameters interpolated on (1 - r)², the reflection about
  cos θ = 1/2 and the terminator softening), §4 (albedo scaling of the base);
* KHR_materials_sheen (Khronos, ratified), "Implementation Notes": r = alpha_g =
  sheenRoughness², the visibility V = 1 / ((1 + Λ(NdotV) + Λ(NdotL)) 4 NdotV NdotL), the
  cheaper visibility of Ashikhmin & Premoze 2007 (Neubelt & Pettineo 2013's form), and the
  layering sheenColor · f_sheen + base · min(1 - max3(sheenColor) E(NdotV),
  1 - max3(sheenColor) E(NdotL)).

Each function is the textbook formula; the guards the GLSL applies (alpha floor, cosine
floor) are constants here and applied where a function models a guarded GLSL entry point
(``sheen_lobe``, ``sheen_albedo_scaling`` take perceptual roughness as the GLSL does).
"""

import numpy as np

from .constants import PI
from .guards import MIN_NDOTV

# PBR_SHEEN_MIN_PERCEPTUAL_ROUGHNESS / PBR_SHEEN_MIN_ALPHA (d_charlie.glsl, tested equal).
SHEEN_MIN_PERCEPTUAL_ROUGHNESS = 0.07
SHEEN_MIN_ALPHA = SHEEN_MIN_PERCEPTUAL_ROUGHNESS ** 2

# Estevez & Kulla 2017, table 1: the Λ fit's parameters (a, b, c, d, e) at r = 1 (first
# column) and r = 0 (second), interpolated by t = (1 - r)² (PBR_SHEEN_LAMBDA_* of v_charlie.glsl).
LAMBDA_AT_R1 = (21.5473, 3.82987, 0.19823, -1.97760, -4.32054)
LAMBDA_AT_R0 = (25.3245, 3.32435, 0.16801, -1.27393, -4.85967)

# pbr_sheen_albedo_approx's coefficients (PBR_SHEEN_ALBEDO_APPROX_C0..C3, rows i = power of x,
# columns = powers of y) and offset; fitted to the shipped table by sheen_table.fit_sheen_albedo_approx.
SHEEN_ALBEDO_APPROX = (
    (1.035856, -2.405441, -0.8081028, 2.034246),
    (-1.120514, -0.4725056, 2.033727, -0.8119602),
    (8.214515, -0.7163682, -6.965961, 3.255338),
    (-12.93151, 8.414441, 3.456867, -3.622073),
)
SHEEN_ALBEDO_APPROX_OFFSET = 0.001


def _f(x):
    return np.asarray(x, dtype=np.float64)


def D_Charlie(NdotH, alpha):
    """Estevez & Kulla 2017 eq. 2: D = (2 + 1/r) sin(θh)^(1/r) / (2π), r = alpha."""
    NdotH, r = _f(NdotH), _f(alpha)
    sin2 = np.maximum(1.0 - NdotH * NdotH, 0.0)
    return (2.0 + 1.0 / r) * sin2 ** (0.5 / r) / (2.0 * PI)


def sheen_lambda_exponent(x, alpha):
    """Estevez & Kulla 2017 §3: L(x) = a / (1 + b x^c) + d x + e, with each parameter
    lerp(value at r = 1, value at r = 0, (1 - r)²)."""
    x, r = _f(x), _f(alpha)
    t = (1.0 - r) ** 2
    a, b, c, d, e = (p1 + (p0 - p1) * t for p1, p0 in zip(LAMBDA_AT_R1, LAMBDA_AT_R0))
    return a / (1.0 + b * x ** c) + d * x + e


def sheen_lambda(cos_theta, alpha):
    """Estevez & Kulla 2017 §3 (KHR's lambda_sheen): Λ = exp(L(cos θ)) for cos θ < 1/2,
    exp(2 L(1/2) - L(1 - cos θ)) above, the reflection that makes Λ(1) finite and smooth."""
    c, r = _f(cos_theta), _f(alpha)
    low = np.exp(sheen_lambda_exponent(np.minimum(c, 0.5), r))
    high = np.exp(2.0 * sheen_lambda_exponent(0.5, r) - sheen_lambda_exponent(np.maximum(1.0 - c, 0.0), r))
    return np.where(c < 0.5, low, high)


def sheen_lambda_softened(cos_theta, alpha):
    """Estevez & Kulla 2017 §3, terminator softening: Λ'(cos θ) = Λ(cos θ)^(1 + 2 (1 - cos θ)^8).
    Not used by the library (v_charlie.glsl says why); here to measure what it would change."""
    c = _f(cos_theta)
    return sheen_lambda(c, alpha) ** (1.0 + 2.0 * (1.0 - c) ** 8)


def V_Charlie(NdotL, NdotV, alpha):
    """KHR_materials_sheen's sheen visibility (Estevez & Kulla 2017's height-correlated G2
    over 4 NdotL NdotV): 1 / ((1 + Λ(NdotV) + Λ(NdotL)) 4 NdotV NdotL)."""
    NdotL, NdotV, r = _f(NdotL), _f(NdotV), _f(alpha)
    return 1.0 / ((1.0 + sheen_lambda(NdotV, r) + sheen_lambda(NdotL, r)) * 4.0 * NdotV * NdotL)


def V_Neubelt(NdotL, NdotV):
    """Ashikhmin & Premoze 2007 as written by Neubelt & Pettineo 2013 (KHR's cheaper option):
    V = 1 / (4 (NdotL + NdotV - NdotL NdotV))."""
    NdotL, NdotV = _f(NdotL), _f(NdotV)
    return 1.0 / (4.0 * (NdotL + NdotV - NdotL * NdotV))


def sheen_alpha(sheen_perceptual_roughness):
    """alpha_g = sheenRoughness² (KHR), with the library's floor (d_charlie.glsl)."""
    r = np.clip(_f(sheen_perceptual_roughness), SHEEN_MIN_PERCEPTUAL_ROUGHNESS, 1.0)
    return r * r


def sheen_lobe(NdotL, NdotV, NdotH, sheen_color, sheen_perceptual_roughness, visibility="CHARLIE"):
    """pbr_sheen_lobe: sheenColor D V (1/sr, no cosine), 0 for NdotL <= 0; cosines floored at
    PBR_MIN_NDOTV as every V of the library. ``sheen_color`` has a last axis of 3."""
    NdotL, NdotV, NdotH = _f(NdotL), _f(NdotV), _f(NdotH)
    alpha = sheen_alpha(sheen_perceptual_roughness)
    cl, cv = np.clip(NdotL, MIN_NDOTV, 1.0), np.clip(NdotV, MIN_NDOTV, 1.0)
    vis = V_Charlie(cl, cv, alpha) if visibility == "CHARLIE" else V_Neubelt(cl, cv)
    value = D_Charlie(np.clip(NdotH, 0.0, 1.0), alpha) * vis
    return np.where((NdotL > 0.0)[..., None], value[..., None] * _f(sheen_color), 0.0)


def sheen_albedo_scaling(sheen_color, E):
    """KHR_materials_sheen: 1 - max3(sheenColor) E, the factor of the base layer."""
    return 1.0 - np.max(_f(sheen_color), axis=-1) * _f(E)


def sheen_albedo_scaling_punctual(sheen_color, E_view, E_light):
    """KHR_materials_sheen for a light: min(1 - max3(c) E(NdotV), 1 - max3(c) E(NdotL))."""
    return np.minimum(sheen_albedo_scaling(sheen_color, E_view), sheen_albedo_scaling(sheen_color, E_light))


def lut_axes(NdotV, sheen_perceptual_roughness):
    """(x, y) in [0, 1] of the sheen albedo table's warped axes (pbr_sheen_lut_uv before the
    texel centring): log-spaced from MIN_NDOTV and SHEEN_MIN_PERCEPTUAL_ROUGHNESS to 1. The
    table (sheen_table.py) and the fit below share them."""
    NdotV = np.clip(np.asarray(NdotV, np.float64), 0.0, 1.0)
    r = np.clip(np.asarray(sheen_perceptual_roughness, np.float64), 0.0, 1.0)
    x = np.log2(np.maximum(NdotV, MIN_NDOTV) / MIN_NDOTV) / np.log2(1.0 / MIN_NDOTV)
    y = np.log2(np.maximum(r, SHEEN_MIN_PERCEPTUAL_ROUGHNESS) / SHEEN_MIN_PERCEPTUAL_ROUGHNESS) \
        / np.log2(1.0 / SHEEN_MIN_PERCEPTUAL_ROUGHNESS)
    return np.clip(x, 0.0, 1.0), np.clip(y, 0.0, 1.0)


def sheen_albedo_approx(NdotV, sheen_perceptual_roughness):
    """pbr_sheen_albedo_approx: the fit exp(sum_i x^i C_i . (1, y, y², y³)) - offset, on the
    table's axes (lut_axes), floored at 0."""
    x, y = lut_axes(NdotV, sheen_perceptual_roughness)
    C = np.asarray(SHEEN_ALBEDO_APPROX, np.float64)
    ys = np.stack([np.ones_like(y), y, y * y, y * y * y], axis=-1)
    p = sum(x ** i * (ys @ C[i]) for i in range(4))
    return np.maximum(np.exp(p) - SHEEN_ALBEDO_APPROX_OFFSET, 0.0)


# pbr/surface/lighting_sheen.glsl: the sheen over a lit base (PBR_SHEEN_ENERGY).
ENERGIES = ("NORMALIZED", "SPECIFICATION")


def sheen_energy_scale(E, energy="NORMALIZED"):
    """pbr_sheen_energy_scale: 1 / max(1, E) (NORMALIZED) or 1 (SPECIFICATION)."""
    E = _f(E)
    if energy == "SPECIFICATION":
        return np.ones_like(E)
    if energy != "NORMALIZED":
        raise ValueError(f"energy {energy!r}: one of {ENERGIES}")
    return 1.0 / np.maximum(E, 1.0)


def sheen_effective_albedo(E, energy="NORMALIZED"):
    """pbr_sheen_effective_albedo: min(E, 1) (NORMALIZED) or E (SPECIFICATION)."""
    E = _f(E)
    if energy == "SPECIFICATION":
        return E
    if energy != "NORMALIZED":
        raise ValueError(f"energy {energy!r}: one of {ENERGIES}")
    return np.minimum(E, 1.0)


def lighting_sheen(base, sheen_color, sheen_perceptual_roughness, n, v, light_dir, light_color,
                   sheen_prefiltered, occlusion, E, energy="NORMALIZED", visibility="CHARLIE"):
    """pbr_lighting_sheen with the view's sheen albedo ``E`` = E(NdotV, r) given (the GPU reads
    its table or the fit; callers pass the float64 integral or the same values):
    base (1 - max3(c) E') + s π c D V NdotL light + prefiltered c E' occlusion, clamped scaling."""
    n, v, l = _f(n), _f(v), _f(light_dir)
    c = _f(sheen_color)
    NdotV = np.maximum(np.sum(n * v, axis=-1), MIN_NDOTV)
    NdotL = np.clip(np.sum(n * l, axis=-1), 0.0, 1.0)
    h = l + v
    length = np.linalg.norm(h, axis=-1, keepdims=True)
    h = np.where(length > 0.0, h / np.where(length > 0.0, length, 1.0), 0.0)
    NdotH = np.clip(np.sum(n * h, axis=-1), 0.0, 1.0)
    albedo = sheen_effective_albedo(E, energy)
    lobe = sheen_lobe(NdotL, NdotV, NdotH, np.broadcast_to(c, n.shape), sheen_perceptual_roughness, visibility)
    direct = lobe * _f(light_color) * (PI * NdotL * sheen_energy_scale(E, energy))[..., None]
    environment = _f(sheen_prefiltered) * c * (albedo * _f(occlusion))[..., None]
    scaling = np.clip(sheen_albedo_scaling(np.broadcast_to(c, n.shape), albedo), 0.0, 1.0)
    return _f(base) * scaling[..., None] + direct + environment
