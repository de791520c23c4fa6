"""The anisotropic specular of KHR_materials_anisotropy (glsl/pbr/brdf/d_ggx_anisotropic.glsl,
v_smith_ggx_correlated_anisotropic.glsl, glsl/pbr/shading/anisotropy.glsl) against the float64
references of harness/pbrlab/maths/reference/anisotropy.py.

Tolerances are ``atol + rtol·|ref|`` in the unit of the value (1/sr for D, V and the lobe;
unitless for alphas and directions). The terms are sums of positive squares (no cancellation),
so RTOL_WELL_CONDITIONED (1e-5, library_helpers) holds for them on the float32 inputs the GPU
receives; the lobe from directions is bounded by D's conditioning in float32 directions, as
written next to its test.
"""

import itertools
import math

import numpy as np
import pytest

from library_helpers import (RTOL_WELL_CONDITIONED, as_f32, assert_close, evaluate, perceptual_roughnesses, record,
                             seeded_rng, unit_vectors, vec3)
from pbrlab.maths.reference import anisotropy, directional_albedo, shading

INCLUDE = ("pbr/shading/anisotropy.glsl",)
N, T, B = (0.0, 0.0, 1.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0)
FRAME = "vec3(0.0, 0.0, 1.0), v, l, vec3(1.0, 0.0, 0.0), vec3(0.0, 1.0, 0.0)"
STRENGTHS = (0.0, 0.25, 0.5, 0.75, 0.9, 1.0)


def _alpha_pairs():
    """(alphaT, alphaB) over the shading model's alphas and every strength (float32-exact)."""
    alpha = np.geomspace(shading.MIN_PERCEPTUAL_ROUGHNESS ** 2, 1.0, 9)
    pairs = anisotropy.anisotropic_alphas(alpha[:, None], np.asarray(STRENGTHS)[None, :]).reshape(-1, 2)
    pairs = np.concatenate([pairs, pairs[:, ::-1]])  # the stretch along b as well
    return as_f32(pairs)


def _hemisphere_directions(rng, count, min_z=1e-3):
    return unit_vectors(rng, count, min_z=min_z)


# ---- the terms ------------------------------------------------------------------------

def test_D_GGX_Anisotropic_matches_reference():
    rng = seeded_rng("D_GGX_Anisotropic")
    h = np.concatenate([_hemisphere_directions(rng, 4000, min_z=0.0), [N],  # peak and near-peak
                        as_f32(np.stack([1e-3 * np.cos(np.arange(64)), 1e-3 * np.sin(np.arange(64)),
                                         np.ones(64)], -1))])
    pairs = _alpha_pairs()
    NdotH, TdotH, BdotH = (h[:, None, i] for i in (2, 0, 1))
    at, ab = pairs[None, :, 0], pairs[None, :, 1]
    got = evaluate("pbr_D_GGX_Anisotropic(NdotH, TdotH, BdotH, at, ab)", INCLUDE,
                   NdotH=NdotH, TdotH=TdotH, BdotH=BdotH, at=at, ab=ab)
    assert_close("pbr_D_GGX_Anisotropic", got, anisotropy.D_GGX_Anisotropic(NdotH, TdotH, BdotH, at, ab),
                 rtol=RTOL_WELL_CONDITIONED)


def test_V_SmithGGXCorrelated_Anisotropic_matches_reference():
    rng = seeded_rng("V_SmithGGXCorrelated_Anisotropic")
    v = _hemisphere_directions(rng, 1500, min_z=shading.MIN_NDOTV)
    l = _hemisphere_directions(rng, 1500, min_z=shading.MIN_NDOTV)
    pairs = _alpha_pairs()
    args = {"NdotL": l[:, None, 2], "NdotV": v[:, None, 2], "TdotV": v[:, None, 0], "BdotV": v[:, None, 1],
            "TdotL": l[:, None, 0], "BdotL": l[:, None, 1], "at": pairs[None, :, 0], "ab": pairs[None, :, 1]}
    got = evaluate("pbr_V_SmithGGXCorrelated_Anisotropic(NdotL, NdotV, TdotV, BdotV, TdotL, BdotL, at, ab)",
                   INCLUDE, **args)
    assert_close("pbr_V_SmithGGXCorrelated_Anisotropic", got,
                 anisotropy.V_SmithGGXCorrelated_Anisotropic(*args.values()), rtol=RTOL_WELL_CONDITIONED)


def test_strength_0_terms_equal_the_isotropic_D_and_V():
    """alphaT = alphaB: D is pbr_D_GGX(n, h, alpha) (its |n × h|² = TdotH² + BdotH²) and V is
    pbr_V_SmithGGXCorrelated, to float32 rounding of two formulations (rtol 1e-5)."""
    rng = seeded_rng("anisotropy strength 0")
    h = _hemisphere_directions(rng, 20000, min_z=0.0)
    alpha = as_f32(np.geomspace(shading.MIN_PERCEPTUAL_ROUGHNESS ** 2, 1.0, 17))[None, :]
    iso = evaluate("pbr_D_GGX(vec3(0.0, 0.0, 1.0), h, alpha)", INCLUDE, h=vec3(h[:, None, :]), alpha=alpha)
    an = evaluate("pbr_D_GGX_Anisotropic(h.z, h.x, h.y, alpha, alpha)", INCLUDE, h=vec3(h[:, None, :]), alpha=alpha)
    assert_close("pbr_D_GGX_Anisotropic(strength 0) vs pbr_D_GGX", an, iso, rtol=RTOL_WELL_CONDITIONED)
    v = _hemisphere_directions(rng, 20000, min_z=shading.MIN_NDOTV)[:, None, :]
    l = _hemisphere_directions(rng, 20000, min_z=shading.MIN_NDOTV)[:, None, :]
    iso = evaluate("pbr_V_SmithGGXCorrelated(l.z, v.z, alpha)", INCLUDE, v=vec3(v), l=vec3(l), alpha=alpha)
    an = evaluate("pbr_V_SmithGGXCorrelated_Anisotropic(l.z, v.z, v.x, v.y, l.x, l.y, alpha, alpha)", INCLUDE,
                  v=vec3(v), l=vec3(l), alpha=alpha)
    assert_close("pbr_V_SmithGGXCorrelated_Anisotropic(strength 0) vs pbr_V_SmithGGXCorrelated", an, iso,
                 rtol=RTOL_WELL_CONDITIONED)


def test_D_GGX_Anisotropic_is_normalised():
    """∫ D (n·h) dω_h = 1, float64 by an independent (θ, φ) midpoint-free Gauss rule."""
    x, w = np.polynomial.legendre.leggauss(400)
    for at, ab in ((0.5, 0.1), (1.0, 0.05), (0.3, 0.3)):
        # θ in [0, π/2] on panels clustered at 0 (the lobe), φ trapezoid
        edges = np.concatenate([[0.0], np.geomspace(1e-3, math.pi / 2, 12)])
        a, c = edges[:-1, None], edges[1:, None]
        theta, wt = (0.5 * (c - a) * x + 0.5 * (c + a)).ravel(), (0.5 * (c - a) * w).ravel()
        phi = np.arange(512) * (2 * math.pi / 512)
        th, ph = theta[:, None], phi[None, :]
        D = anisotropy.D_GGX_Anisotropic(np.cos(th), np.sin(th) * np.cos(ph), np.sin(th) * np.sin(ph), at, ab)
        total = np.sum(D * np.cos(th) * np.sin(th) * wt[:, None]) * (2 * math.pi / 512)
        assert abs(total - 1.0) < 1e-6, (at, ab, total)


# ---- the mapping --------------------------------------------------------------------------

def test_anisotropic_alphas_follow_the_extension():
    alpha, strength = np.meshgrid(as_f32(np.linspace(0.0, 1.0, 65)), as_f32(np.linspace(-1.0, 1.0, 65)))
    got = evaluate("vec3(pbr_anisotropic_alphas(alpha, strength), 0.0)", INCLUDE, alpha=alpha, strength=strength)
    ref = anisotropy.anisotropic_alphas(alpha, strength)
    assert_close("pbr_anisotropic_alphas", got[..., :2], ref, rtol=RTOL_WELL_CONDITIONED, atol=1e-7)
    assert (got[..., 1] == alpha).all()  # alphaB is the material's alpha, exactly


def test_anisotropy_direction_rotates_counter_clockwise_from_the_tangent():
    rng = seeded_rng("anisotropy direction")
    sample = as_f32(rng.uniform(-1.0, 1.0, (4096, 2)))
    rotation = as_f32(rng.uniform(-math.pi, math.pi, 4096))
    got = evaluate("pbr_anisotropy_direction(vec3(1.0, 0.0, 0.0), vec3(0.0, 1.0, 0.0), d.xy, r)", INCLUDE,
                   d=vec3(np.concatenate([sample, np.zeros((4096, 1))], -1)), r=rotation)
    ref = anisotropy.anisotropy_direction(T, B, sample, rotation)
    assert_close("pbr_anisotropy_direction", got, ref, rtol=0.0, atol=1e-6)  # unit vector: 1e-6 ~ 8 ulp
    quarter = evaluate("pbr_anisotropy_direction(vec3(1.0, 0.0, 0.0), vec3(0.0, 1.0, 0.0), vec2(1.0, 0.0), r)",
                       INCLUDE, r=np.float32(math.pi / 2))
    assert np.allclose(quarter, (0.0, 1.0, 0.0), atol=1e-7)  # t rotated a quarter turn is b
    zero = evaluate("pbr_anisotropy_direction(vec3(1.0, 0.0, 0.0), vec3(0.0, 1.0, 0.0), vec2(0.0), 0.0)", INCLUDE,
                    x=0.0)
    assert (zero == (1.0, 0.0, 0.0)).all()  # decided: a zero sample is the untextured (1, 0)


# ---- the lobe ------------------------------------------------------------------------------

def _lobe(v, l, roughness, strength, f0=0.04):
    return evaluate(f"pbr_brdf_anisotropic_specular({FRAME}, vec3(f0), r, s)", INCLUDE,
                    v=vec3(v), l=vec3(l), f0=f0, r=roughness, s=strength)


@pytest.fixture(scope="module")
def lobe_geometry():
    rng = seeded_rng("anisotropic lobe geometry")
    v = _hemisphere_directions(rng, 30000, min_z=shading.MIN_NDOTV)
    l = _hemisphere_directions(rng, 30000, min_z=shading.MIN_NDOTV)
    return v, l


def test_brdf_anisotropic_specular_matches_reference(lobe_geometry):
    """Through directions, D is ill-conditioned in float32 near the peak of sharp lobes (a
    direction carries ~2^-24 absolute error, the lobe's width is alpha, so D moves by ~2^-24 /
    alpha relative): the bound is RTOL_WELL_CONDITIONED plus 4 · 2^-24 / min(alphaT, alphaB)
    (measured: see the error table)."""
    v, l = lobe_geometry
    r = as_f32(perceptual_roughnesses(9))[None, :, None]
    s = as_f32(np.asarray((0.0, 0.5, 1.0)))[None, None, :]
    got = _lobe(v[:, None, None, :], l[:, None, None, :], r, s)
    ref = anisotropy.brdf_anisotropic_specular(N, v[:, None, None, :], l[:, None, None, :], T, B, np.full(3, 0.04),
                                               r, s)
    alpha_b = np.maximum(r, shading.MIN_PERCEPTUAL_ROUGHNESS) ** 2
    rtol = RTOL_WELL_CONDITIONED + 4 * 2.0 ** -24 / alpha_b
    assert_close("pbr_brdf_anisotropic_specular", got, ref, rtol=np.broadcast_to(rtol[..., None], ref.shape))


def test_strength_0_lobe_equals_the_standard_specular(lobe_geometry):
    """strength 0 is pbr_brdf_standard's GGX / correlated Smith / Schlick specular (no diffuse),
    to float32 rounding of two formulations of D from directions (same bound as above)."""
    v, l = lobe_geometry
    r = as_f32(perceptual_roughnesses(9))[None, :]
    an = _lobe(v[:, None, :], l[:, None, :], r, 0.0)
    std = evaluate("pbr_brdf_standard(vec3(0.0, 0.0, 1.0), v, l, vec3(0.0), vec3(0.04), r)", INCLUDE,
                   v=vec3(v[:, None, :]), l=vec3(l[:, None, :]), r=r)
    alpha = np.maximum(r, shading.MIN_PERCEPTUAL_ROUGHNESS) ** 2
    rtol = RTOL_WELL_CONDITIONED + 4 * 2.0 ** -24 / alpha
    assert_close("pbr_brdf_anisotropic_specular(strength 0) vs pbr_brdf_standard", an, std,
                 rtol=np.broadcast_to(rtol[..., None], std.shape))


def test_lobe_is_reciprocal(lobe_geometry):
    """Swapping l and v gives the same bits (both cosines >= PBR_MIN_NDOTV: no clamp differs)."""
    v, l = lobe_geometry
    for r, s in itertools.product((0.0, 0.3, 1.0), (-1.0, 0.0, 0.6, 1.0)):
        assert np.array_equal(_lobe(v, l, r, s), _lobe(l, v, r, s)), (r, s)


HARD_GEOMETRY = {
    "V = -L": ((-0.6, 0.0, -0.8), (0.6, 0.0, 0.8)),
    "mirror": ((-0.6, 0.0, 0.8), (0.6, 0.0, 0.8)),
    "mirror along b": ((0.0, -0.6, 0.8), (0.0, 0.6, 0.8)),
    "grazing mirror": ((-0.9999995, 0.0, 1e-3), (0.9999995, 0.0, 1e-3)),
    "grazing view": ((1.0, 0.0, 0.0), (0.6, 0.0, 0.8)),
    "grazing light": ((0.6, 0.0, 0.8), (0.0, 1.0, 0.0)),
    "l = v": ((0.6, 0.0, 0.8), (0.6, 0.0, 0.8)),
    "back-facing view": ((0.8, 0.0, -0.6), (0.6, 0.0, 0.8)),
    "light below": ((0.6, 0.0, 0.8), (0.6, 0.0, -0.8)),
}


def test_lobe_hard_cases_are_finite_and_non_negative():
    names = list(HARD_GEOMETRY)
    v = as_f32([HARD_GEOMETRY[k][0] for k in names])[:, None, None, :]
    l = as_f32([HARD_GEOMETRY[k][1] for k in names])[:, None, None, :]
    r = as_f32([0.0, -0.5, 1e-10, 0.045, 1.0])[None, :, None]
    s = as_f32([-1.0, -0.5, 0.0, 0.5, 1.0, 2.0])[None, None, :]
    got = _lobe(v, l, r, s, f0=1.0)
    assert np.isfinite(got).all() and (got >= 0.0).all()
    for name in ("V = -L", "light below"):  # decided / the horizon: exactly 0
        assert (got[names.index(name)] == 0.0).all(), name
    # roughness below the floor is the floor, exactly; strength -1 is strength 1
    assert np.array_equal(got[:, 0], got[:, 3]) and np.array_equal(got[:, 1], got[:, 3])
    assert np.array_equal(got[..., 0, :], got[..., 4, :])


# ---- the white furnace -----------------------------------------------------------------------

FURNACE_VIEWS = ((0.0, 0.0), (60.0, 30.0), (85.0, 75.0))  # polar, azimuth from t (degrees)


def _view(theta_deg, phi_deg):
    th, ph = math.radians(theta_deg), math.radians(phi_deg)
    return np.array([math.sin(th) * math.cos(ph), math.sin(th) * math.sin(ph), math.cos(th)])


def test_quadrature_is_converged_and_matches_the_isotropic_albedo():
    """The quadrature of reference/anisotropy.py against reference/directional_albedo.py's
    independent one at strength 0, and against itself with every node count doubled."""
    for mu, alpha in itertools.product((1.0, 0.5, 0.1), (0.045 ** 2, 0.04, 0.25, 1.0)):
        v = np.array([math.sqrt(1.0 - mu * mu), 0.0, mu])
        e = anisotropy.directional_albedo(v, alpha, alpha)
        assert abs(e - float(np.sum(directional_albedo.split_sum_terms(mu, alpha)))) < 1e-5, (mu, alpha)
    for (theta, phi), (at, ab) in itertools.product(FURNACE_VIEWS, ((0.6, 0.05), (1.0, 0.002))):
        v = _view(theta, phi)
        e = anisotropy.directional_albedo(v, at, ab)
        e2 = anisotropy.directional_albedo(v, at, ab, u_nodes=2 * anisotropy.U_NODES,
                                           phi_nodes=2 * anisotropy.PHI_NODES)
        assert abs(e - e2) < 1e-5, (theta, phi, at, ab, e, e2)


def test_white_furnace_anisotropic_lobe_reflects_at_most_the_light():
    """E(v) = ∫ f (n·l) dω_l with F = 1 (f0 = 1 gives F = 1 exactly) <= 1 for every
    roughness and strength: the GPU lobe at the quadrature's light directions, weighted by the
    float64 quadrature (weights for D (n·h) dω_h, so f (n·l) 4 (v·h) / (D_ref (n·h)))."""
    worst = 0.0
    for r, s in itertools.product(perceptual_roughnesses(9), (0.0, 0.5, 0.9, 1.0)):
        at, ab = anisotropy.anisotropic_alphas(max(r, shading.MIN_PERCEPTUAL_ROUGHNESS) ** 2, s)
        for theta, phi in FURNACE_VIEWS:
            v = _view(theta, phi)
            h, w = anisotropy.half_vector_quadrature(at, ab, v, u_nodes=12, phi_nodes=128)
            VdotH = h @ v
            l = 2.0 * VdotH[:, None] * h - v
            f = _lobe(as_f32(v), as_f32(l), float(r), float(s), f0=1.0)[:, 0].astype(np.float64)
            D = anisotropy.D_GGX_Anisotropic(h[:, 2], h[:, 0], h[:, 1], at, ab)
            e_gpu = float(np.sum(w * f * np.maximum(l[:, 2], 0.0) * 4.0 * VdotH / (D * h[:, 2])))
            e_ref = anisotropy.directional_albedo(v, at, ab)
            # 1e-4: the GPU's float32 D near sharp peaks (see the lobe test) and the coarser
            # quadrature used for it; the float64 albedo must hold the bound to 1e-6
            assert e_ref <= 1.0 + 1e-6 and e_gpu <= 1.0 + 1e-4, (r, s, theta, phi, e_ref, e_gpu)
            worst = max(worst, e_gpu)
    record("anisotropic lobe white furnace (max E; rel = 1 - max E)", worst, 1.0 - worst, "E <= 1 + 1e-4")


# ---- the image-based counterpart ---------------------------------------------------------------

def test_bent_normal_matches_reference():
    rng = seeded_rng("anisotropic bent normal")
    v = _hemisphere_directions(rng, 4096)
    s = as_f32(rng.uniform(-1.2, 1.2, 4096))
    r = as_f32(rng.uniform(0.0, 1.0, 4096))
    got = evaluate("pbr_anisotropic_bent_normal(vec3(0.0, 0.0, 1.0), v, vec3(0.0, 1.0, 0.0), s, r)", INCLUDE,
                   v=vec3(v), s=s, r=r)
    ref = anisotropy.anisotropic_bent_normal(N, v, B, s, r)
    assert_close("pbr_anisotropic_bent_normal", got, ref, rtol=0.0, atol=1e-6)  # unit vector: ~8 ulp
    degenerate = evaluate("pbr_anisotropic_bent_normal(vec3(0.0, 0.0, 1.0), vec3(0.0, 1.0, 0.0), "
                          "vec3(0.0, 1.0, 0.0), 1.0, 0.0)", INCLUDE, x=0.0)
    assert (degenerate == (0.0, 0.0, 1.0)).all()  # decided: v along d at strength 1, roughness 0 -> n


def test_bent_normal_error_against_exact_integral():
    """The sample viewer's image-based anisotropic specular (prefiltered environment at
    reflect(-v, bentNormal), isotropic alpha, times the exact anisotropic albedo) against the
    exact anisotropic specular integral under reference/anisotropy.test_environment, float64
    integrals around the GPU's bent normal. The figure is recorded and bounded by the shared
    constant; the unbent reflection is measured beside it."""
    grid = anisotropy.BENT_NORMAL_GRID
    configs = list(itertools.product(grid["roughness"], grid["strength"], grid["theta_v"], grid["phi_v"]))
    views = np.array([_view(theta, phi) for _, _, theta, phi in configs])
    bent = evaluate("pbr_anisotropic_bent_normal(vec3(0.0, 0.0, 1.0), v, vec3(0.0, 1.0, 0.0), s, r)", INCLUDE,
                    v=vec3(as_f32(views)), s=as_f32([c[1] for c in configs]), r=as_f32([c[0] for c in configs]))
    errors, unbent = [], []
    for (r, s, _, _), v, normal in zip(configs, views, bent.astype(np.float64)):
        at, ab = anisotropy.anisotropic_alphas(r * r, s)
        exact = anisotropy.specular_integral(v, at, ab, anisotropy.test_environment)
        errors.append(anisotropy.image_based_specular(v, normal, r, s) / exact - 1.0)
        unbent.append(anisotropy.image_based_specular(v, N, r, s) / exact - 1.0)
    errors, unbent = np.abs(errors), np.abs(unbent)
    record("pbr_anisotropic_bent_normal IBL vs exact integral", float(errors.max()), float(errors.mean()),
           "max | mean relative error (max rel column = mean)")
    record("reflect(-v, n) IBL vs exact anisotropic integral", float(unbent.max()), float(unbent.mean()),
           "max | mean relative error (max rel column = mean)")
    assert errors.max() <= anisotropy.BENT_NORMAL_MAX_REL_ERROR, errors.max()
    shared = evaluate("PBR_ANISOTROPIC_BENT_NORMAL_MAX_REL_ERROR", INCLUDE, x=0.0)
    assert shared == np.float32(anisotropy.BENT_NORMAL_MAX_REL_ERROR)
