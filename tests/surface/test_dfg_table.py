"""The DFG (environment BRDF) table: the float64 reference of the integral, the table's own
quadrature, the shipped file, the texel-centre lookup, and the table as the GPU samples it
(bilinear at pbr_dfg_lut_uv) against the reference: within 1e-3 everywhere the renderer
reads, NdotV -> 0 and alpha = 1 included."""

import numpy as np
import pytest
from scipy import integrate

from pbrlab import evaluate
from pbrlab.gpu import ibl
from pbrlab.maths.reference import directional_albedo as ref_albedo
from pbrlab.maths.reference import shading as ref_shading
from pbrlab.maths.reference import surface as ref_surface

INCLUDES = ["pbr/ibl/environment_brdf.glsl"]
# The bound on the table as sampled, absolute in A and B (and in A + B).
TABLE_TOLERANCE = 1e-3

# The domain the renderer reads: NdotV clamped to PBR_MIN_NDOTV, roughness to the tier's
# minimum (0.045 at HIGH and MEDIUM).
MU = np.unique(np.concatenate([np.geomspace(ref_shading.MIN_NDOTV, 1.0, 23),
                               np.linspace(0.0, 1.0, 21)[1:], [0.9999]]))
ROUGH = np.unique(np.concatenate([np.linspace(ref_shading.MIN_PERCEPTUAL_ROUGHNESS, 1.0, 14), [0.06, 0.089, 0.12]]))


@pytest.fixture(scope="module")
def reference_grid():
    mu, rough = np.meshgrid(MU, ROUGH, indexing="ij")
    return mu, rough, ref_albedo.split_sum_terms_grid(mu, rough ** 2)


def _scipy_terms(mu, alpha):
    """(A, B) by scipy's adaptive quadrature over the light hemisphere (theta_l, phi_l): a
    third formulation (no half-vector change of variables), from the integrand
    D V F NdotL with Walter 2007's D and Heitz 2014's height-correlated V."""
    v = np.array([np.sqrt(1 - mu * mu), 0.0, mu])
    a2 = alpha * alpha

    def f(phi, theta, which):
        l = np.array([np.sin(theta) * np.cos(phi), np.sin(theta) * np.sin(phi), np.cos(theta)])
        h = (l + v) / np.linalg.norm(l + v)
        D = a2 / (np.pi * (h[2] ** 2 * (a2 - 1) + 1) ** 2)
        V = 0.5 / (l[2] * np.sqrt(mu * mu * (1 - a2) + a2) + mu * np.sqrt(l[2] ** 2 * (1 - a2) + a2))
        fc = (1 - v @ h) ** 5
        return D * V * (fc if which else 1 - fc) * l[2] * np.sin(theta)

    return [integrate.dblquad(lambda p, t: f(p, t, k), 0, np.pi / 2, 0, 2 * np.pi,
                              epsabs=1e-11, epsrel=1e-11)[0] for k in (0, 1)]


@pytest.mark.parametrize("mu, rough", [(1.0, 1.0), (0.3, 0.7), (0.05, 1.0), (0.5, 0.5)])
def test_reference_agrees_with_adaptive_quadrature_over_light_directions(mu, rough):
    # Measured: 2e-15 .. 6e-12 apart (scipy's adaptive rule on rough lobes, where it converges).
    np.testing.assert_allclose(ref_albedo.split_sum_terms(mu, rough ** 2), _scipy_terms(mu, rough ** 2),
                               rtol=0, atol=1e-9)


def test_reference_is_converged_to_1e_9():
    # Doubling every node count moves no value by more than 6.7e-11 (measured on this grid).
    for mu in (1e-4, 1e-3, 0.01, 0.3, 1.0):
        for rough in (0.045, 0.2, 1.0):
            coarse = np.array(ref_albedo.split_sum_terms(mu, rough ** 2))
            fine = np.array(ref_albedo.split_sum_terms(mu, rough ** 2, theta_nodes=64, phi_nodes=96))
            assert np.abs(coarse - fine).max() < 1e-9, (mu, rough)


def test_reference_limits():
    # At normal incidence and alpha -> 0 the lobe is a mirror with no masking: A + B -> 1 and
    # B -> (1 - NdotV)^5 = 0; at alpha = 1, grazing, the height-correlated albedo tends to 1.
    a, b = ref_albedo.split_sum_terms(1.0, 1e-4)
    assert abs(a + b - 1) < 1e-6 and b < 1e-10  # B ~ (1 - v.h)^5, v.h within ~alpha^2 of 1
    a, b = ref_albedo.split_sum_terms(0.5, 1e-4)  # mirror: B = (1 - 0.5)^5, A = 1 - B
    assert abs(b - 0.5 ** 5) < 1e-5 and abs(a + b - 1) < 1e-4
    assert ref_albedo.split_sum_terms(1e-4, 1.0)[0] + ref_albedo.split_sum_terms(1e-4, 1.0)[1] > 0.99
    with pytest.raises(ValueError):
        ref_albedo.split_sum_terms(0.0, 0.5)


def test_table_quadrature_agrees_with_the_reference(reference_grid):
    # ibl.integrate_dfg (GGX sampling variables, other panels) against the reference:
    # measured worst 6.4e-8 on random points; 1e-6 leaves room and is 40x below the table's
    # interpolation error.
    mu, rough, want = reference_grid
    np.testing.assert_allclose(ibl.integrate_dfg(mu, rough), want, rtol=0, atol=1e-6)


def test_shipped_table_is_what_the_quadrature_computes():
    table = ibl.dfg_lut()[::-1]  # GL row order: row j is y = j / (HEIGHT - 1)
    assert table.shape == (ref_surface.DFG_LUT_HEIGHT, ref_surface.DFG_LUT_WIDTH, 2)
    assert table.dtype == np.float32 and np.isfinite(table).all()
    xs = np.arange(ref_surface.DFG_LUT_WIDTH) / (ref_surface.DFG_LUT_WIDTH - 1)
    for j in (0, 1, 57, ref_surface.DFG_LUT_HEIGHT - 1):
        y = np.full_like(xs, j / (ref_surface.DFG_LUT_HEIGHT - 1))
        mu, rough = ref_surface.dfg_lut_texel_coordinates(xs, y)
        np.testing.assert_array_equal(table[j], ibl.integrate_dfg(mu, rough).astype(np.float32))


def test_texel_centre_uv_matches_reference_and_hits_the_edge_texels():
    NdotV, rough = np.meshgrid(np.linspace(0, 1, 101), np.linspace(0, 1, 101), indexing="ij")
    got = evaluate("pbr_dfg_lut_uv(NdotV, r)", INCLUDES, NdotV=NdotV, r=rough)
    u, v = ref_surface.dfg_lut_uv(NdotV, rough)
    # float32 log2 of the warp: measured 2.4e-7 in uv, 1/64 of a texel width (3.9e-3)
    np.testing.assert_allclose(got, np.stack([u, v], -1), rtol=0, atol=1e-6)
    w, h = ref_surface.DFG_LUT_WIDTH, ref_surface.DFG_LUT_HEIGHT
    corners = evaluate("pbr_dfg_lut_uv(NdotV, r)", INCLUDES, NdotV=np.array([0.0, 1.0]), r=np.array([0.045, 1.0]))
    np.testing.assert_allclose(corners, [[0.5 / w, 0.5 / h], [1 - 0.5 / w, 1 - 0.5 / h]], atol=1e-6)


def test_table_as_sampled_is_within_1e_3_of_the_reference_everywhere(reference_grid):
    # What the GPU reads: bilinear at pbr_dfg_lut_uv of the float32 table, in float64.
    # Measured: max 4.0e-5 in A or B (random points and this grid), worst near NdotV ~ 1e-4
    # at small roughness, so 1e-3 holds with a 25x margin.
    mu, rough, want = reference_grid
    got = ref_surface.sample_dfg_lut(ibl.dfg_lut()[::-1], mu, rough)
    err = np.abs(got - want)
    assert err.max() < TABLE_TOLERANCE, (err.max(), mu.flat[err.max(-1).argmax()], rough.flat[err.max(-1).argmax()])
    assert np.abs(got.sum(-1) - want.sum(-1)).max() < TABLE_TOLERANCE


def test_a_lookup_without_the_texel_centre_remap_would_fail(reference_grid):
    # The defect the remap fixes: reading the same table at the raw axes (x, y) instead of
    # the texel centres shifts every lookup by up to half a texel; at the NdotV -> 0 dip
    # that is measured far above the tolerance, so the test above can see it.
    mu, rough, want = reference_grid
    table = ibl.dfg_lut()[::-1].astype(np.float64)
    x, y = ref_surface.dfg_lut_axes(mu, rough)
    h, w = table.shape[:2]
    fx, fy = x * w - 0.5, y * h - 0.5
    i0, j0 = np.clip(np.floor(fx).astype(int), 0, w - 1), np.clip(np.floor(fy).astype(int), 0, h - 1)
    i1, j1 = np.minimum(i0 + 1, w - 1), np.minimum(j0 + 1, h - 1)
    tx, ty = np.clip(fx - i0, 0, 1)[..., None], np.clip(fy - j0, 0, 1)[..., None]
    raw = ((table[j0, i0] * (1 - tx) + table[j0, i1] * tx) * (1 - ty)
           + (table[j1, i0] * (1 - tx) + table[j1, i1] * tx) * ty)
    assert np.abs(raw - want).max() > TABLE_TOLERANCE


# ---- the LOW tier's table (PBR_DFG_LUT_LAYOUT_SQRT: x = sqrt(NdotV), y = perceptual roughness) ----

LOW = {"PBR_QUALITY": "PBR_QUALITY_LOW"}  # the tier selects the layout (pbr/shading/dispatch.glsl)
# LOW's domain: NdotV from PBR_MIN_NDOTV, roughness from the tier's floor 0.089
ROUGH_LOW = np.unique(np.concatenate([np.linspace(ref_shading.MIN_PERCEPTUAL_ROUGHNESS_MEDIUMP, 1.0, 14),
                                      [0.1, 0.12, 0.2]]))


@pytest.fixture(scope="module")
def reference_grid_low():
    mu, rough = np.meshgrid(MU, ROUGH_LOW, indexing="ij")
    return mu, rough, ref_albedo.split_sum_terms_grid(mu, rough ** 2)


def test_low_tier_selects_the_square_root_layout_and_the_renderer_binds_its_table():
    assert ref_shading.QUALITY_DFG_LUT_LAYOUT == {"LOW": "SQRT", "MEDIUM": "WARPED", "HIGH": "WARPED"}
    NdotV, rough = np.array([0.0, 0.25, 1.0]), np.array([0.5, 0.3, 1.0])
    for quality, layout in ref_shading.QUALITY_DFG_LUT_LAYOUT.items():
        got = evaluate("pbr_dfg_lut_uv(NdotV, r)", INCLUDES, defines={"PBR_QUALITY": f"PBR_QUALITY_{quality}"},
                       NdotV=NdotV, r=rough)
        np.testing.assert_allclose(got, np.stack(ref_surface.dfg_lut_uv(NdotV, rough, layout), -1), rtol=0, atol=1e-6)


def test_square_root_uv_matches_reference_and_hits_the_edge_texels():
    NdotV, rough = np.meshgrid(np.linspace(0, 1, 101), np.linspace(0, 1, 101), indexing="ij")
    got = evaluate("pbr_dfg_lut_uv(NdotV, r)", INCLUDES, defines=LOW, NdotV=NdotV, r=rough)
    u, v = ref_surface.dfg_lut_uv(NdotV, rough, "SQRT")
    # float32 sqrt (within 1 ulp, 6e-8) and one multiply-add: 1e-6 is 1/256 of a texel
    np.testing.assert_allclose(got, np.stack([u, v], -1), rtol=0, atol=1e-6)
    w, h = ref_surface.DFG_LUT_WIDTH, ref_surface.DFG_LUT_HEIGHT
    corners = evaluate("pbr_dfg_lut_uv(NdotV, r)", INCLUDES, defines=LOW, NdotV=np.array([0.0, 1.0]),
                       r=np.array([0.0, 1.0]))
    np.testing.assert_allclose(corners, [[0.5 / w, 0.5 / h], [1 - 0.5 / w, 1 - 0.5 / h]], atol=1e-6)


def test_shipped_square_root_table_is_what_the_quadrature_computes():
    table = ibl.dfg_lut("SQRT")[::-1]
    assert table.shape == (ref_surface.DFG_LUT_HEIGHT, ref_surface.DFG_LUT_WIDTH, 2)
    assert table.dtype == np.float32 and np.isfinite(table).all()
    xs, ys = ref_surface.dfg_lut_nodes("SQRT")
    for j in (0, 11, 22, 23, 130, ref_surface.DFG_LUT_HEIGHT - 1):
        y = np.full_like(xs, ys[j])
        mu, rough = ref_surface.dfg_lut_texel_coordinates(xs, y, "SQRT")
        rough = np.maximum(rough, ref_shading.MIN_PERCEPTUAL_ROUGHNESS)  # rows no tier reads: 0.045's
        np.testing.assert_array_equal(table[j], ibl.integrate_dfg(mu, rough).astype(np.float32))


def test_square_root_table_as_sampled_is_within_1e_3_of_the_reference_on_low_domain(reference_grid_low):
    # The same bound as the warped table's (the 1e-3, absolute in A and B and in A + B).
    # Measured: max 1.3e-4 in A or B, 2.1e-4 in A + B (at NdotV = 1e-2, roughness 0.089, the
    # sharpest dip LOW reads; a denser 400 x 120 grid gives the same 1.3e-4), 7x inside it;
    # the warped table on this grid 4.0e-5.
    mu, rough, want = reference_grid_low
    got = ref_surface.sample_dfg_lut(ibl.dfg_lut("SQRT")[::-1], mu, rough, "SQRT")
    err = np.abs(got - want)
    assert err.max() < TABLE_TOLERANCE, (err.max(), mu.flat[err.max(-1).argmax()], rough.flat[err.max(-1).argmax()])
    assert np.abs(got.sum(-1) - want.sum(-1)).max() < TABLE_TOLERANCE
    # node values are integrals of a lobe that reflects at most what arrives, so a bilinear
    # blend of them cannot exceed 1 (the white furnace of the environment stays <= 1)
    assert got.sum(-1).max() <= 1.0


def test_each_table_read_in_the_other_layout_fails_the_bound(reference_grid_low):
    """Control: the layouts are not interchangeable (a renderer binding the wrong table for
    the tier would be caught by the bound above): measured 0.53 and 0.52 off."""
    mu, rough, want = reference_grid_low
    swapped = ref_surface.sample_dfg_lut(ibl.dfg_lut("WARPED")[::-1], mu, rough, "SQRT")
    assert np.abs(swapped - want).max() > 10 * TABLE_TOLERANCE
    swapped = ref_surface.sample_dfg_lut(ibl.dfg_lut("SQRT")[::-1], mu, rough, "WARPED")
    assert np.abs(swapped - want).max() > 10 * TABLE_TOLERANCE
