"""Float64 references of pbr/ibl/environment_brdf.glsl, pbr/shading/energy_conservation.glsl,
pbr/surface/lighting_standard.glsl and the helpers of pbr/unity/surface_standard.glsl
(sources cited in the GLSL)."""

import numpy as np

from . import brdf, shading
from .material import DIELECTRIC_F0

MIN_SPECULAR_ALBEDO = 1e-4  # PBR_MIN_SPECULAR_ALBEDO
MIN_ONE_MINUS_REFLECTIVITY = 1e-4  # PBR_MIN_ONE_MINUS_REFLECTIVITY

# The DFG table's layout (PBR_DFG_LUT_* of environment_brdf.glsl, tested equal): texel i, j
# holds (A, B) at x = i / (WIDTH - 1), y = j / (HEIGHT - 1) of the warped axes
#   x = log2(1 + NdotV / C_NDOTV) / log2(1 + 1 / C_NDOTV),
#   y = log2((alpha + C_ALPHA) / (ALPHA_MIN + C_ALPHA)) / log2((1 + C_ALPHA) / (ALPHA_MIN + C_ALPHA)).
DFG_LUT_WIDTH = 256
DFG_LUT_HEIGHT = 256
DFG_LUT_C_NDOTV = 0.003
DFG_LUT_C_ALPHA = 0.003
DFG_LUT_ALPHA_MIN = shading.MIN_PERCEPTUAL_ROUGHNESS ** 2


DFG_LUT_LAYOUTS = ("WARPED", "SQRT")  # PBR_DFG_LUT_LAYOUT_*: the LOW tier reads SQRT
#   SQRT: x = sqrt(NdotV), y = perceptual roughness (no warp constants).


def _layout(layout):
    if layout not in DFG_LUT_LAYOUTS:
        raise ValueError(f"layout={layout!r}: expected one of {DFG_LUT_LAYOUTS}")
    return layout


def dfg_lut_axes(NdotV, perceptual_roughness, layout="WARPED"):
    """(x, y) in [0, 1] of the table axes of ``layout`` (float64)."""
    NdotV = np.clip(_f(NdotV), 0.0, 1.0)
    if _layout(layout) == "SQRT":
        return np.sqrt(NdotV), np.clip(_f(perceptual_roughness), 0.0, 1.0)
    alpha = np.clip(_f(perceptual_roughness) ** 2, 0.0, 1.0)
    x = np.log2(1 + NdotV / DFG_LUT_C_NDOTV) / np.log2(1 + 1 / DFG_LUT_C_NDOTV)
    y = (np.log2((alpha + DFG_LUT_C_ALPHA) / (DFG_LUT_ALPHA_MIN + DFG_LUT_C_ALPHA))
         / np.log2((1 + DFG_LUT_C_ALPHA) / (DFG_LUT_ALPHA_MIN + DFG_LUT_C_ALPHA)))
    return np.clip(x, 0.0, 1.0), np.clip(y, 0.0, 1.0)


def dfg_lut_texel_coordinates(x, y, layout="WARPED"):
    """Inverse of dfg_lut_axes: the (NdotV, perceptual roughness) of table axes (x, y)."""
    if _layout(layout) == "SQRT":
        return np.clip(_f(x), 0.0, 1.0) ** 2, np.clip(_f(y), 0.0, 1.0)
    NdotV = DFG_LUT_C_NDOTV * (2.0 ** (_f(x) * np.log2(1 + 1 / DFG_LUT_C_NDOTV)) - 1)
    scale = np.log2((1 + DFG_LUT_C_ALPHA) / (DFG_LUT_ALPHA_MIN + DFG_LUT_C_ALPHA))
    alpha = (DFG_LUT_ALPHA_MIN + DFG_LUT_C_ALPHA) * 2.0 ** (_f(y) * scale) - DFG_LUT_C_ALPHA
    return np.clip(NdotV, 0.0, 1.0), np.sqrt(np.clip(alpha, 0.0, 1.0))


def dfg_lut_nodes(layout="WARPED"):
    """The axis values (xs, ys) the table's texels hold, column i and GL row j, for either
    layout: x = i / (WIDTH - 1), y = j / (HEIGHT - 1) (the first and last texels at the axis'
    ends, read at texel-centre coordinates: dfg_lut_uv)."""
    _layout(layout)
    return np.arange(DFG_LUT_WIDTH) / (DFG_LUT_WIDTH - 1), np.arange(DFG_LUT_HEIGHT) / (DFG_LUT_HEIGHT - 1)


def dfg_lut_uv(NdotV, perceptual_roughness, layout="WARPED"):
    """pbr_dfg_lut_uv: texture coordinates of the texel-centre lookup."""
    x, y = dfg_lut_axes(NdotV, perceptual_roughness, layout)
    return ((x * (DFG_LUT_WIDTH - 1) + 0.5) / DFG_LUT_WIDTH,
            (y * (DFG_LUT_HEIGHT - 1) + 0.5) / DFG_LUT_HEIGHT)


def sample_dfg_lut(table, NdotV, perceptual_roughness, layout="WARPED"):
    """What a GPU reads from ``table`` (HEIGHT x WIDTH x 2, row j = y j / (HEIGHT - 1), GL row
    order) at pbr_dfg_lut_uv: bilinear filtering, clamp to edge, in float64."""
    u, v = dfg_lut_uv(NdotV, perceptual_roughness, layout)
    h, w = table.shape[:2]
    fx, fy = u * w - 0.5, v * h - 0.5
    i0 = np.clip(np.floor(fx).astype(int), 0, w - 1)
    j0 = np.clip(np.floor(fy).astype(int), 0, h - 1)
    i1, j1 = np.minimum(i0 + 1, w - 1), np.minimum(j0 + 1, h - 1)
    tx, ty = (fx - np.floor(fx))[..., None], (fy - np.floor(fy))[..., None]
    t = _f(table)
    return ((t[j0, i0] * (1 - tx) + t[j0, i1] * tx) * (1 - ty)
            + (t[j1, i0] * (1 - tx) + t[j1, i1] * tx) * ty)


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


def specular_albedo(f0, dfg, f90=None):
    """f0 A + f90 B with F90 = f90_from_f0(f0) (Schüler 2009 / Filament, as the BRDF's F), or
    the caller's ``f90`` (pbr_specular_albedo_f90)."""
    f90 = brdf.f90_from_f0(f0)[..., None] if f90 is None else _f(f90)[..., None]
    return _f(f0) * _f(dfg)[..., 0:1] + f90 * _f(dfg)[..., 1:2]


def specular_albedo_bound(f0, dfg, specular_f="SCHLICK", f90=None):
    """pbr_specular_albedo_bound[_f90]: f0 A + f90 B + the F variant's largest distance from
    Schlick's F (shading.specular_F_deviation_bound) times A + B."""
    return specular_albedo(f0, dfg, f90) + shading.specular_F_deviation_bound(f0, specular_f, f90) * (
        _f(dfg)[..., 0:1] + _f(dfg)[..., 1:2])


def indirect_specular_albedo(f0, dfg, energy_compensated=True, f90=None):
    """Single-scattering albedo, times the compensation (at f0 alone) when it is applied."""
    albedo = specular_albedo(f0, dfg, f90)
    return albedo * energy_compensation(f0, dfg) if energy_compensated else albedo


def diffuse_albedo_from_diffuse_color(diffuse_color, coat_f0):
    """rho = diffuseColor / (1 - max(coatF0)), capped at 1: the workflow's constant
    1 - reflectivity undone (pbr/shading/energy_conservation.glsl). coat_f0 is the F0 of the
    dielectric over the diffuse: 0.04 in the metallic workflow (Unity's
    unity_ColorSpaceDielectricSpec; diffuseColor = albedo 0.96 (1 - m) gives rho =
    albedo (1 - m)), the specular colour in the specular workflow."""
    one_minus = np.maximum(1 - np.max(_f(coat_f0), axis=-1), MIN_ONE_MINUS_REFLECTIVITY)[..., None]
    return np.minimum(_f(diffuse_color) / one_minus, 1.0)


def coupled_diffuse_color(diffuse_color, coat_f0, coat_albedo):
    """rho (1 - E_coat): Fdez-Aguera 2019 section 4; Kelemen & Szirmay-Kalos 2001. The
    diffuse lies under the dielectric coat only; coat_albedo is that coat's directional
    albedo E(coat_f0), so a metallic m reflects (1 - m)[rho (1 - E_coat) + E_coat] + m E_metal."""
    return diffuse_albedo_from_diffuse_color(diffuse_color, coat_f0) * (1 - np.clip(_f(coat_albedo), 0, 1))


def energy_compensation(f0, dfg):
    """Fdez-Aguera 2019 as in Filament 5.3.4.7: 1 + f0 (1/(A+B) - 1)."""
    e = np.maximum(_f(dfg)[..., 0:1] + _f(dfg)[..., 1:2], MIN_SPECULAR_ALBEDO)
    return 1 + _f(f0) * (1 / e - 1)


def specular_occlusion(NdotV, occlusion, alpha, quality="HIGH"):
    """The tier's PBR_SPECULAR_OCCLUSION: Lagarde & de Rousiers 2014, listing 26 (HIGH, MEDIUM),
    or the ambient occlusion itself (LOW)."""
    if shading.QUALITY_SPECULAR_OCCLUSION[quality] == "AMBIENT":
        return np.broadcast_to(_f(occlusion), np.broadcast(_f(NdotV), _f(occlusion), _f(alpha)).shape)
    return np.clip((_f(NdotV) + occlusion) ** np.exp2(-16 * _f(alpha) - 1) - 1 + occlusion, 0, 1)


def indirect_specular_split_sum(prefiltered, f0, perceptual_roughness, NdotV, occlusion, dfg,
                                energy_compensated=True, f90=None, quality="HIGH"):
    """Scalars and arrays shaped like NdotV; colours with a last axis of 3."""
    return _f(prefiltered) * indirect_specular_albedo(f0, dfg, energy_compensated, f90) * specular_occlusion(
        NdotV, _f(occlusion), _f(perceptual_roughness) ** 2, quality)[..., None]


def one_minus_reflectivity_from_metallic(metallic):
    """Unity: (1 - 0.04) - metallic (1 - 0.04)."""
    return (1 - DIELECTRIC_F0) * (1 - _f(metallic))


def premultiply_alpha(diff_color, alpha, one_minus_reflectivity, transparent):
    """Unity's PreMultiplyAlpha: (diffuse, output alpha)."""
    if not transparent:
        return _f(diff_color), _f(alpha)
    return _f(diff_color) * alpha, 1 - one_minus_reflectivity + alpha * one_minus_reflectivity


def lighting_standard(diffuse_color, f0, coat_f0, perceptual_roughness, occlusion, n, v, light_dir,
                      light_color, indirect_diffuse, prefiltered, dfg, energy_compensated=True,
                      f90=None, coat_f90=None, **variants):
    """pbr_lighting_standard_dfg: direct (pbr_shade_punctual with the diffuse coupled to the
    coat's single-scattering specular albedo) + coupled indirect diffuse * occlusion +
    split-sum indirect specular (at f0, the whole surface's). ``dfg`` is the environment BRDF at (NdotV, roughness).
    Vectors and colours have a last axis of 3; roughness and occlusion have the leading
    shape (or are scalars). ``f90``, ``coat_f90``: pbr_lighting_standard_f90_dfg's explicit
    grazing reflectances of f0 and coat_f0 (None: F90 from F0)."""
    r = shading.clamp_perceptual_roughness(perceptual_roughness)
    NdotV = np.maximum(np.sum(_f(n) * v, axis=-1), shading.MIN_NDOTV)
    specular_f = variants.get("specular_f") or shading.QUALITY_DEFAULT_F[variants.get("quality", "HIGH")]
    direct_diffuse = coupled_diffuse_color(diffuse_color, coat_f0,
                                           specular_albedo_bound(coat_f0, dfg, specular_f, coat_f90))
    direct = shading.shade_punctual(n, v, light_dir, light_color, direct_diffuse, f0, r, f90=f90, **variants)
    spec = indirect_specular_split_sum(prefiltered, f0, r, NdotV, occlusion, dfg, energy_compensated, f90,
                                       variants.get("quality", "HIGH"))
    indirect_diffuse_color = coupled_diffuse_color(
        diffuse_color, coat_f0, indirect_specular_albedo(coat_f0, dfg, energy_compensated, coat_f90))
    return direct + indirect_diffuse_color * _f(indirect_diffuse) * _f(occlusion)[..., None] + spec


# glsl/pbr/surface/lighting_anisotropy.glsl PBR_ANISOTROPY_MIN_SIN: below this sine of the
# angle between the direction and n, the fallback tangent.
ANISOTROPY_MIN_SIN = 1e-3


def anisotropic_tangent(n, direction):
    """pbr_anisotropic_tangent: direction made orthogonal to n (Gram-Schmidt) and normalised;
    where it is zero or within ANISOTROPY_MIN_SIN of n, the tangent of pbr_tangent_to_world
    (cross(up, n) normalised, up = +z unless |n.z| >= 0.999, then +x)."""
    n, d = np.broadcast_arrays(_f(n), _f(direction))
    d_length = np.linalg.norm(d, axis=-1, keepdims=True)
    d = d / np.where(d_length > 0.0, d_length, 1.0)
    t = d - n * np.sum(n * d, axis=-1, keepdims=True)
    length = np.linalg.norm(t, axis=-1, keepdims=True)
    up = np.where(np.abs(n[..., 2:3]) < 0.999, np.array([0.0, 0.0, 1.0]), np.array([1.0, 0.0, 0.0]))
    fallback = np.cross(up, n)
    fallback /= np.linalg.norm(fallback, axis=-1, keepdims=True)
    in_plane = length > ANISOTROPY_MIN_SIN
    return np.where(in_plane, t / np.where(in_plane, length, 1.0), fallback)


def lighting_anisotropic(diffuse_color, f0, coat_f0, perceptual_roughness, occlusion, n, v, light_dir,
                         light_color, indirect_diffuse, prefiltered, dfg, strength, direction,
                         energy_compensated=True, f90=None, coat_f90=None, **variants):
    """pbr_lighting_anisotropic_dfg (glsl/pbr/surface/lighting_anisotropy.glsl): lighting_standard
    with the direct specular lobe replaced by KHR_materials_anisotropy's
    (anisotropy.brdf_anisotropic_specular, the exact anisotropic GGX / height-correlated Smith /
    Schlick lobe at every tier) in the frame t = anisotropic_tangent(n, direction), b = n x t.
    ``prefiltered``: the environment read along the bent normal's mirror direction (the caller's).
    The split sum and the diffuse coupling are the isotropic ones at the material's roughness.
    ``f90``, ``coat_f90``: pbr_lighting_anisotropic_f90's explicit F90s (None: F90 from F0)."""
    from . import anisotropy
    quality = variants.get("quality", "HIGH")
    r = shading.clamp_perceptual_roughness(perceptual_roughness, quality)
    n = _f(n)
    NdotV = np.maximum(np.sum(n * v, axis=-1), shading.MIN_NDOTV)
    t = anisotropic_tangent(n, direction)
    b = np.cross(n, t)
    specular_f = variants.get("specular_f") or shading.QUALITY_DEFAULT_F[quality]
    direct_diffuse = coupled_diffuse_color(diffuse_color, coat_f0,
                                           specular_albedo_bound(coat_f0, dfg, specular_f, coat_f90))
    # the diffuse half of pbr_shade_punctual: f0 = 0 has no specular (F90 follows F0)
    direct = shading.shade_punctual(n, v, light_dir, light_color, direct_diffuse, np.zeros(3), r, **variants)
    NdotL = np.clip(np.sum(n * _f(light_dir), axis=-1), 0.0, 1.0)
    lobe = anisotropy.brdf_anisotropic_specular(n, v, light_dir, t, b, f0, r, strength, quality, f90)
    direct = direct + _f(light_color) * lobe * (shading.LIGHT_UNIT_SCALE * NdotL)[..., None]
    spec = indirect_specular_split_sum(prefiltered, f0, r, NdotV, occlusion, dfg, energy_compensated, f90,
                                       variants.get("quality", "HIGH"))
    indirect_diffuse_color = coupled_diffuse_color(
        diffuse_color, coat_f0, indirect_specular_albedo(coat_f0, dfg, energy_compensated, coat_f90))
    return direct + indirect_diffuse_color * _f(indirect_diffuse) * _f(occlusion)[..., None] + spec


# glsl/pbr/surface/lighting_iridescence.glsl PBR_IRIDESCENCE_MAX_SCHLICK_WEIGHT.
IRIDESCENCE_MAX_SCHLICK_WEIGHT = 0.9999


def f0_from_schlick(F, cos_theta):
    """pbr_f0_from_schlick: Schlick 1994 with F90 = 1 solved for F0, (F - x) / (1 - x),
    x = min((1 - cos)^5, IRIDESCENCE_MAX_SCHLICK_WEIGHT), saturated; last axis RGB."""
    x = np.minimum((1.0 - np.clip(_f(cos_theta), 0.0, 1.0)) ** 5, IRIDESCENCE_MAX_SCHLICK_WEIGHT)[..., None]
    return np.clip((_f(F) - x) / (1.0 - x), 0.0, 1.0)


def iridescent_f0(f0, NdotV, factor, film_ior, thickness_nm):
    """pbr_iridescent_f0: mix(f0, f0_from_schlick(F_Iridescence(1, film_ior, NdotV, d, f0), NdotV),
    factor), the film evaluated by reference/iridescence.py's float64 twin of pbr_F_Iridescence."""
    from . import iridescence
    film = iridescence.F_Iridescence(1.0, film_ior, NdotV, thickness_nm, f0)
    t = np.clip(_f(factor), 0.0, 1.0)[..., None]
    return _f(f0) * (1.0 - t) + f0_from_schlick(film, NdotV) * t


def iridescent_f0_with_coat(f0, coat_f0, NdotV, factor, film_ior, thickness_nm):
    """pbr_iridescent_f0_with_coat: (iridescent_f0 of f0, iridescent_f0 of coat_f0), the film's
    base-independent terms shared (reference/iridescence.py thin_film)."""
    from . import iridescence
    film = iridescence.thin_film(1.0, film_ior, NdotV, thickness_nm)
    t = np.clip(_f(factor), 0.0, 1.0)[..., None]

    def fold(base):
        filmed = iridescence.F_Iridescence_thin_film(film, base)
        return _f(base) * (1.0 - t) + f0_from_schlick(filmed, NdotV) * t
    return fold(f0), fold(coat_f0)


def iridescent_diffuse_color(diffuse_color, coat_f0, film_coat_f0):
    """pbr_iridescent_diffuse_color: rho (1 - max3(film_coat_f0)) (floored as the coupling's),
    rho = diffuse_albedo_from_diffuse_color(diffuse_color, coat_f0)."""
    rho = diffuse_albedo_from_diffuse_color(diffuse_color, coat_f0)
    return rho * np.maximum(1.0 - np.max(_f(film_coat_f0), axis=-1, keepdims=True), MIN_ONE_MINUS_REFLECTIVITY)


def transmission_diffuse_color(diffuse_color, transmission):
    """pbr_transmission_diffuse_color: what the diffuse lobe keeps, diffuseColor (1 - t)."""
    return _f(diffuse_color) * (1.0 - float(np.clip(transmission, 0.0, 1.0)))


def lighting_transmission(diffuse_color, coat_f0, perceptual_roughness, occlusion, n, v, light_dir, light_radiance,
                          transmitted_indirect, dfg, factor, thickness, attenuation_color, attenuation_distance, ior,
                          quality="HIGH", specular_f="SCHLICK", energy_compensated=True, coat_f90=None):
    """pbr/surface/lighting_transmission.glsl pbr_lighting_transmission in float64, from
    KHR_materials_transmission / _volume and reference/transmission.py: t A (direct +
    indirect), A the Beer-Lambert attenuation over the thickness (1 thin-walled); direct: a
    thin wall's mirrored lobe tinted by rho (1 - E_coat) (single scattering, the direct
    diffuse's weight), or Walter's BTDF (eta = ior, its own 1 - F) tinted by rho; indirect:
    rho (1 - E_coat) (the environment's, compensated as the indirect diffuse) times the
    environment seen through, times occlusion. dfg: (A, B) at the pixel's NdotV and the
    base's clamped roughness. ``coat_f90``: pbr_lighting_transmission_f90's explicit F90 of
    coat_f0 (both E_coat = coat_f0 A + coat_f90 B; None: F90 from F0)."""
    from . import transmission as ref_transmission
    r = float(shading.clamp_perceptual_roughness(perceptual_roughness, quality))
    if thickness > 0.0:
        rho = diffuse_albedo_from_diffuse_color(diffuse_color, coat_f0)
        direct = ref_transmission.transmission_walter_punctual(n, v, light_dir, light_radiance, r * r,
                                                               np.full(len(_f(n)), ior)) * rho
        attenuation = ref_transmission.volume_attenuation(thickness, attenuation_color, attenuation_distance)
    else:
        direct_color = coupled_diffuse_color(diffuse_color, coat_f0,
                                             specular_albedo_bound(coat_f0, dfg, specular_f, coat_f90))
        direct = ref_transmission.transmission_thin_punctual(n, v, light_dir, light_radiance, direct_color, r * r)
        attenuation = np.ones(3)
    indirect = coupled_diffuse_color(diffuse_color, coat_f0,
                                     indirect_specular_albedo(coat_f0, dfg, energy_compensated, coat_f90)) \
        * _f(transmitted_indirect) * occlusion
    return float(np.clip(factor, 0.0, 1.0)) * attenuation * (direct + indirect)
