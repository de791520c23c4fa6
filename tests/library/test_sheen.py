"""The sheen layer (KHR_materials_sheen): pbr/brdf/d_charlie.glsl, pbr/brdf/v_charlie.glsl and
pbr/shading/sheen.glsl against the float64 references of harness/pbrlab/maths/reference/sheen.py, the
albedo table (harness/pbrlab/gpu/sheen_table.py) against an independent finer quadrature, and the
energy statements the headers make.

Tolerances are atol + rtol·|ref| in the unit of the term (1/sr for D, V and the lobe).
"""

import numpy as np
import pytest

from library_helpers import (RTOL_WELL_CONDITIONED, as_f32, assert_close, cosines, evaluate, grid,
                             phi_quadrature, theta_quadrature, v_cosines, vec3)
from pbrlab.gpu import sheen_table
from pbrlab.maths.reference import sheen

# alpha from 0 (clamped to the floor) over the floor to 1
ALPHAS = as_f32(np.concatenate([[0.0, 1e-3], np.geomspace(sheen.SHEEN_MIN_ALPHA, 1.0, 17)]))
ROUGHNESSES = as_f32(np.concatenate([[0.0, 0.03], np.linspace(sheen.SHEEN_MIN_PERCEPTUAL_ROUGHNESS, 1.0, 13)]))


def pow_rtol(exponent):
    """GLSL pow inherits log2's absolute error 2^-21 times the exponent (GLSL 4.60 §4.7.1): relative
    error ln2 · s · 2^-21 near a base of 1; plus the well-conditioned allowance."""
    return RTOL_WELL_CONDITIONED + np.log(2.0) * exponent * 2.0 ** -21


def test_shared_constants_are_equal():
    pairs = [("PBR_SHEEN_MIN_PERCEPTUAL_ROUGHNESS", sheen.SHEEN_MIN_PERCEPTUAL_ROUGHNESS),
             ("PBR_SHEEN_MIN_ALPHA", sheen.SHEEN_MIN_ALPHA),
             ("PBR_SHEEN_LUT_WIDTH", sheen_table.LUT_WIDTH), ("PBR_SHEEN_LUT_HEIGHT", sheen_table.LUT_HEIGHT),
             ("PBR_SHEEN_LUT_NDOTV_LOG_NORM", 1.0 / np.log2(1.0 / sheen_table.LUT_MIN_NDOTV)),
             ("PBR_SHEEN_LUT_ROUGHNESS_LOG_NORM", 1.0 / np.log2(1.0 / sheen.SHEEN_MIN_PERCEPTUAL_ROUGHNESS)),
             ("PBR_SHEEN_ALBEDO_APPROX_OFFSET", sheen.SHEEN_ALBEDO_APPROX_OFFSET)]
    pairs += [(f"PBR_SHEEN_LAMBDA_R1_{k}", v) for k, v in zip("ABCDE", sheen.LAMBDA_AT_R1)]
    pairs += [(f"PBR_SHEEN_LAMBDA_R0_{k}", v) for k, v in zip("ABCDE", sheen.LAMBDA_AT_R0)]
    pairs += [(f"PBR_SHEEN_ALBEDO_APPROX_C{i}", row) for i, row in enumerate(sheen.SHEEN_ALBEDO_APPROX)]
    for macro, value in pairs:
        got = evaluate(macro, ("pbr/shading/sheen.glsl",), x=0.0)
        np.testing.assert_allclose(got, np.float32(value) if np.ndim(value) == 0 else np.asarray(value, np.float32),
                                   rtol=6e-8, err_msg=macro)  # float32 rounding of a decimal literal


def test_D_Charlie_matches_reference():
    NdotH, alpha = grid(cosines(513), ALPHAS)
    got = evaluate("pbr_D_Charlie(NdotH, alpha)", ("pbr/brdf/d_charlie.glsl",), NdotH=NdotH, alpha=alpha)
    a = np.maximum(alpha, sheen.SHEEN_MIN_ALPHA)
    ref = sheen.D_Charlie(NdotH, a)
    assert np.isfinite(got).all()
    assert_close("pbr_D_Charlie", got, ref, rtol=pow_rtol(0.5 / a), atol=1e-30)


def test_D_Charlie_is_normalised():
    """∫ D (n·h) dω_h = 1 (d_charlie.glsl), float64, at the floor and at 1."""
    theta, w = theta_quadrature(1.0, panels=64)
    for alpha in (sheen.SHEEN_MIN_ALPHA, 0.1, 1.0):
        total = np.sum(sheen.D_Charlie(np.cos(theta), alpha) * np.cos(theta) * np.sin(theta) * w) * 2 * np.pi
        assert abs(total - 1.0) < 1e-9, alpha


@pytest.mark.parametrize("term", ["V_Charlie", "V_Neubelt"])
def test_sheen_V_matches_reference(term):
    c = np.concatenate([[0.0, 1e-7], v_cosines(129)])
    NdotL, NdotV, alpha = grid(c, c, ALPHAS[::2])
    args = "NdotL, NdotV, alpha" if term == "V_Charlie" else "NdotL, NdotV"
    got = evaluate(f"pbr_{term}({args})", ("pbr/brdf/v_charlie.glsl",), NdotL=NdotL, NdotV=NdotV, alpha=alpha)
    cl, cv = np.maximum(NdotL, sheen.MIN_NDOTV), np.maximum(NdotV, sheen.MIN_NDOTV)
    a = np.maximum(alpha, sheen.SHEEN_MIN_ALPHA)
    ref = sheen.V_Charlie(cl, cv, a) if term == "V_Charlie" else np.broadcast_to(sheen.V_Neubelt(cl, cv), got.shape)
    assert np.isfinite(got).all()
    # Charlie: exp(L) with |L| <= 10 turns L's few-ulp error into ~|L|·4 ulp ≈ 2.4e-6 relative;
    # 2e-5 leaves headroom (a wrong fit parameter is >= 1e-3 off)
    assert_close(f"pbr_{term}", got, ref, rtol=2e-5)


def test_sheen_lobe_matches_reference():
    c = np.concatenate([[-0.5, 0.0, 1e-7], v_cosines(33)])
    NdotL, NdotV, NdotH, r = grid(c, c, cosines(17), ROUGHNESSES[::2])
    color = np.array([1.0, 0.5, 0.25])
    got = evaluate("pbr_sheen_lobe(NdotL, NdotV, NdotH, c, r)", ("pbr/shading/sheen.glsl",), NdotL=NdotL, NdotV=NdotV,
                   NdotH=NdotH, r=r, c=vec3(np.broadcast_to(color, NdotL.shape[:3] + (1, 3))))
    ref = sheen.sheen_lobe(NdotL, NdotV, NdotH, color, r)
    assert np.isfinite(got).all() and (got[NdotL[..., 0, 0, 0] <= 0] == 0).all()
    a = sheen.sheen_alpha(r)[..., None]
    assert_close("pbr_sheen_lobe", got, ref, rtol=pow_rtol(0.5 / a) + 2e-5, atol=1e-30)


def _independent_albedo(mu, rough):
    """E by a different, much finer scheme: Gauss-Legendre panels in θ_l crowded at the horizon
    (library_helpers.theta_quadrature, mirrored), trapezoid in φ over [0, 2π)."""
    theta, tw = theta_quadrature(0.05, panels=64, order=16)
    theta = np.pi / 2 - theta                    # crowd the nodes at the horizon
    phi, pw = phi_quadrature(256)
    out = []
    for m, r in zip(np.atleast_1d(mu), np.atleast_1d(rough)):
        u = np.cos(theta)[:, None]
        m_c = max(m, sheen.MIN_NDOTV)
        ldv = m_c * u + np.sqrt(1 - m_c ** 2) * np.sin(theta)[:, None] * np.cos(phi)[None, :]
        NdotH = (u + m_c) / np.sqrt(np.maximum(2 + 2 * ldv, 1e-300))
        f = sheen.sheen_lobe(u, m, NdotH, np.ones(3), r)[..., 0] * u
        out.append(np.sum(f * np.sin(theta)[:, None] * tw[:, None] * pw[None, :]))
    return np.array(out)


@pytest.fixture(scope="module")
def off_grid():
    """Points between texels of both axes (worst for bilinear), plus the grazing floor."""
    rng = np.random.default_rng(20170730)  # fixed points; the quadratures themselves are deterministic
    x = (rng.integers(0, sheen_table.LUT_WIDTH - 1, 160) + rng.uniform(0.2, 0.8, 160)) / (sheen_table.LUT_WIDTH - 1)
    y = (rng.integers(0, sheen_table.LUT_HEIGHT - 1, 160) + rng.uniform(0.2, 0.8, 160)) / (sheen_table.LUT_HEIGHT - 1)
    mu, r = sheen_table.lut_texel_coordinates(x, y)
    mu = np.concatenate([mu, [0.0, 1e-4, 1.0, 1.7e-3]])
    r = np.concatenate([r, [0.0, 0.07, 1.0, 0.07]])
    return as_f32(mu), as_f32(r), _independent_albedo(as_f32(mu), as_f32(r))


def test_table_quadrature_agrees_with_an_independent_finer_quadrature(off_grid):
    mu, r, ref = off_grid
    got = sheen_table.integrate_sheen_albedo(mu, r)
    # measured 5.2e-5 worst (the two schemes differ most at the grazing peak of the smoothest
    # sheen); 1e-4 is a tenth of the table's 1e-3 budget
    assert np.abs(got - ref).max() < 1e-4


def test_shipped_table_is_what_the_quadrature_computes():
    table = sheen_table.sheen_lut()
    assert table.dtype == np.float32 and table.shape == (sheen_table.LUT_HEIGHT, sheen_table.LUT_WIDTH)
    rows = [0, 40, sheen_table.LUT_HEIGHT - 1]
    fresh = sheen_table.compute_sheen_lut()[rows] if False else None  # the full rebuild takes 30 s
    xs = np.arange(0, sheen_table.LUT_WIDTH, 9) / (sheen_table.LUT_WIDTH - 1)
    for j in rows:
        y = 1.0 - j / (sheen_table.LUT_HEIGHT - 1)   # image order: row 0 is y = 1
        mu, r = sheen_table.lut_texel_coordinates(xs, np.full_like(xs, y))
        np.testing.assert_allclose(table[j, ::9], sheen_table.integrate_sheen_albedo(mu, r), atol=1e-6)
    assert fresh is None


def test_table_as_sampled_is_within_1e_3_of_the_independent_quadrature(off_grid):
    mu, r, ref = off_grid
    got = sheen_table.sample_sheen_lut(sheen_table.sheen_lut(), mu, r)
    err = np.abs(got - ref)
    assert err.max() < 1e-3, f"worst {err.max():.3g} at NdotV {mu[err.argmax()]}, r {r[err.argmax()]}"


def test_lut_uv_matches_reference_and_hits_the_edge_texels():
    mu, r = grid(np.concatenate([[0.0, 5e-5], cosines(65)]), ROUGHNESSES)
    got = evaluate("pbr_sheen_lut_uv(NdotV, r)", ("pbr/shading/sheen.glsl",), NdotV=mu, r=r)
    u, v = sheen_table.lut_uv(mu, r)
    np.testing.assert_allclose(got[..., 0], np.broadcast_to(u, got.shape[:-1]), atol=4e-7)
    np.testing.assert_allclose(got[..., 1], np.broadcast_to(v, got.shape[:-1]), atol=4e-7)
    w, h = sheen_table.LUT_WIDTH, sheen_table.LUT_HEIGHT
    assert abs(got[..., 0].min() - 0.5 / w) < 1e-7 and abs(got[..., 0].max() - (w - 0.5) / w) < 1e-6
    assert abs(got[..., 1].min() - 0.5 / h) < 1e-7 and abs(got[..., 1].max() - (h - 0.5) / h) < 1e-6


def test_albedo_approx_matches_reference_and_its_stated_error():
    mu, r = grid(np.concatenate([[0.0], cosines(129)]), ROUGHNESSES)
    got = evaluate("pbr_sheen_albedo_approx(NdotV, r)", ("pbr/shading/sheen.glsl",), NdotV=mu, r=r)
    assert_close("pbr_sheen_albedo_approx", got, sheen.sheen_albedo_approx(mu, r), rtol=2e-5, atol=1e-6)
    table = sheen_table.sheen_lut()
    err = np.abs(sheen.sheen_albedo_approx(mu, r) - sheen_table.sample_sheen_lut(table, mu, r))
    assert err.max() <= 0.165  # stated: worst 0.16 absolute (sheen.glsl)


def test_albedo_reads_the_hook_when_defined():
    got = evaluate("pbr_sheen_albedo(0.3, 0.5)", ("pbr/shading/sheen.glsl",),
                   defines={"PBR_SHEEN_LUT_LOOKUP(NdotV, r)": "(NdotV + 10.0 * r)"}, x=0.0)
    assert got == np.float32(5.3)


def test_albedo_scaling_is_the_spec_formula_clamped_to_0_1():
    colors = np.array([[0.2, 0.9, 0.4], [1.0, 1.0, 1.0], [0.0, 0.0, 0.0], [0.5, 0.1, 0.3]])
    E = np.array([0.5, 2.94, 2.0, 0.7])
    got = evaluate("pbr_sheen_albedo_scaling(c, E)", ("pbr/shading/sheen.glsl",), c=vec3(colors), E=E)
    ref = np.clip(sheen.sheen_albedo_scaling(colors, E), 0.0, 1.0)
    np.testing.assert_allclose(got, ref, atol=1e-7)


def test_punctual_scaling_is_the_min_over_view_and_light():
    NdotV, NdotL, r = grid(np.array([0.01, 0.3, 0.9]), np.array([0.05, 0.5, 1.0]), np.array([0.3, 0.8]))
    color = np.array([0.3, 0.6, 0.2])
    got = evaluate("pbr_sheen_albedo_scaling_punctual(c, NdotV, NdotL, r)", ("pbr/shading/sheen.glsl",),
                   c=vec3(np.broadcast_to(color, NdotV.shape + (3,))), NdotV=NdotV, NdotL=NdotL, r=r)
    ref = np.clip(sheen.sheen_albedo_scaling_punctual(color, sheen.sheen_albedo_approx(NdotV, r),
                                                      sheen.sheen_albedo_approx(NdotL, r)), 0, 1)
    np.testing.assert_allclose(got, ref, atol=2e-5)


# ---- energy -----------------------------------------------------------------------------
# The spec's fitted Λ masks too little at grazing for smooth sheens (v_charlie.glsl): E > 1 there.
# Measured (table, float64): E <= 1 for every NdotV at perceptual roughness >= ENERGY_SAFE_ROUGHNESS;
# the worst E at the floor is 2.94 (NdotV 1.7e-3). Pinned so a change of V or of the floor shows.
ENERGY_SAFE_ROUGHNESS = 0.27
WORST_E = 2.94


def test_white_sheen_furnace_and_energy_bound():
    table = sheen_table.sheen_lut().astype(np.float64)[::-1]
    xs = np.arange(sheen_table.LUT_WIDTH) / (sheen_table.LUT_WIDTH - 1)
    ys = np.arange(sheen_table.LUT_HEIGHT) / (sheen_table.LUT_HEIGHT - 1)
    _, r = sheen_table.lut_texel_coordinates(xs[:1], ys)
    worst = table.max(axis=1)
    assert (worst[r >= ENERGY_SAFE_ROUGHNESS] <= 1.0).all()
    assert worst[r < ENERGY_SAFE_ROUGHNESS - 0.01].min() > 1.0          # the limit is where stated
    assert abs(table.max() - WORST_E) < 0.005
    # independent check of the furnace at the safe roughness and above, all views
    mu = as_f32(np.concatenate([[1e-4], np.geomspace(1e-3, 1, 12)]))
    for rough in (ENERGY_SAFE_ROUGHNESS, 0.5, 1.0):
        assert (_independent_albedo(mu, np.full_like(mu, rough)) <= 1.0).all(), rough


def test_albedo_scaling_keeps_the_base_in_0_1_and_the_layer_bounded():
    """With E <= 1 (r >= 0.27) the spec's layering gives sheen + scaled base <= 1 for a white
    base (E_base = 1): max3(c) E + (1 - max3(c) E) = 1; below, the clamp keeps the base >= 0."""
    table = sheen_table.sheen_lut()
    for cmax in (0.0, 0.5, 1.0):
        s = np.clip(1.0 - cmax * table, 0.0, 1.0)
        assert (s >= 0).all() and (s <= 1).all()
