"""PBR_ENV_BRDF (issue 25): the DFG table as the accurate environment BRDF, Karis's analytic
fit (Karis 2014, "Physically Based Shading on Mobile", EnvBRDFApprox; float64 twin
reference.surface.env_brdf_approx) as the table-free option, both against the float64
integral of pbrlab's own lobe (reference.directional_albedo: GGX, height-correlated Smith,
Schlick's F0/F90 split), and what the fit does to energy.

Measured on the grid below (NdotV log-spaced over [1e-4, 1] x perceptual roughness over
[0.045, 1], what the renderer reads):
* the fit (the GLSL through the selector): A and B within 0.499 of the integral, mean 0.115
  (the fit was made for UE4's separable Schlick-GGX V, which masks more than the exact
  height-correlated one); the table, bilinear at its texel centres: within 4.0e-5.
* Environment furnace with the fit (a uniform white environment through
  pbr_prepare_surface + pbr_lighting_standard_add_environment, the renderer's path without
  lights): <= 1 for the white dielectric, white metal and white half-metal (measured
  1 + 6e-8: the split sum and the coupling read the same fitted albedo, so what the specular
  does not reflect goes to the diffuse, whatever the fit's error).
* Direct light with the fit: the coupling gives the diffuse 1 - E_fit of the coat, while the
  direct lobe reflects its true albedo; where the fit is below it, a white dielectric
  reflects E_true + (1 - E_fit): up to 1.084 (NdotV 0.12, roughness 0.13). No constant bound
  scale fixes that usefully: E_true / E_fit reaches 5.45 (near grazing at roughness 1, where
  the fit's A + B is 0.45 and the integral's ~1), so a scale large enough would darken every
  diffuse; the table is the option that holds energy under direct light.
"""

import numpy as np
import pytest

from pbrlab import evaluate, vec3
from pbrlab.gpu import ibl
from pbrlab.foundation.errors import ShaderCompileError
from pbrlab.maths.reference import brdf as ref_brdf
from pbrlab.maths.reference import directional_albedo as ref_albedo
from pbrlab.maths.reference import surface as ref_surface

ANALYTIC = {"PBR_ENV_BRDF": "PBR_ENV_BRDF_ANALYTIC"}
MARKER_TABLE = "vec2(-7.0, -5.0)"  # a table hook no fit can return


@pytest.fixture(scope="module")
def grid():
    mu, r = np.meshgrid(np.geomspace(1e-4, 1.0, 40), np.linspace(0.045, 1.0, 24), indexing="ij")
    mu, r = mu.ravel().astype(np.float32), r.ravel().astype(np.float32)
    integral = ref_albedo.split_sum_terms_grid(mu.astype(np.float64), r.astype(np.float64) ** 2,
                                               theta_nodes=20, phi_nodes=24)
    return mu, r, integral


def test_the_analytic_selector_ignores_a_given_table_and_the_default_reads_it():
    mu = np.linspace(0.01, 1.0, 64, dtype=np.float32)
    r = np.linspace(0.05, 1.0, 64, dtype=np.float32)
    hook = {"PBR_DFG_LUT_LOOKUP(NdotV, perceptualRoughness)": MARKER_TABLE}
    table = np.asarray(evaluate("pbr_env_brdf(NdotV, r)", defines=hook, NdotV=mu, r=r))[:, :2]
    assert np.all(table == np.array([-7.0, -5.0], np.float32))
    fit = np.asarray(evaluate("pbr_env_brdf(NdotV, r)", defines=dict(hook, **ANALYTIC), NdotV=mu, r=r))[:, :2]
    np.testing.assert_allclose(fit, ref_surface.env_brdf_approx(mu, r), atol=2e-6)


def test_an_unknown_selector_value_is_an_error():
    with pytest.raises(ShaderCompileError, match="PBR_ENV_BRDF: unknown value"):
        evaluate("pbr_env_brdf(x, x)", defines={"PBR_ENV_BRDF": "PBR_ENV_BRDF_TYPO"}, x=np.zeros(1, np.float32))


def test_fit_and_table_errors_against_the_float64_integral(grid):
    mu, r, integral = grid
    fit = np.asarray(evaluate("pbr_env_brdf(NdotV, r)", defines=ANALYTIC, NdotV=mu, r=r), np.float64)[:, :2]
    table = ref_surface.sample_dfg_lut(ibl.dfg_lut()[::-1], mu.astype(np.float64), r.astype(np.float64))
    fit_err, table_err = np.abs(fit - integral), np.abs(table - integral)
    print(f"fit: max {fit_err.max():.4g}, mean {fit_err.mean():.4g}; table: max {table_err.max():.3g}, "
          f"mean {table_err.mean():.3g}")
    assert 0.45 < fit_err.max() < 0.55 and 0.09 < fit_err.mean() < 0.14
    assert table_err.max() <= 4.0e-5


def _furnace(defines, diffuse, f0, mu, r):
    v = np.stack([np.sqrt(1.0 - mu.astype(np.float64) ** 2), np.zeros_like(mu, np.float64), mu], -1)
    got = evaluate("pbr_lighting_standard_add_environment(pbr_prepare_surface(vec3(d), vec3(f), "
                   "vec3(0.04), r, 1.0, vec3(0.0, 0.0, 1.0), v), "
                   "pbr_Indirect(vec3(1.0), vec3(1.0)), vec3(0.0))",
                   ["pbr/surface/lighting_standard.glsl"], defines=defines,
                   d=np.full_like(mu, diffuse), f=np.full_like(mu, f0), r=r, v=vec3(v.astype(np.float32)))
    return np.asarray(got, np.float64)[:, :3]


@pytest.mark.parametrize("material, diffuse, f0", [("white dielectric", 0.96, 0.04), ("white metal", 0.0, 1.0),
                                                   ("white half-metal", 0.48, 0.52)])
def test_environment_furnace_with_the_fit_stays_at_most_one(grid, material, diffuse, f0):
    mu, r, _ = grid
    got = _furnace(ANALYTIC, diffuse, f0, mu, r)
    print(f"{material}: max {got.max():.8f}")
    assert got.max() <= 1.0 + 1e-4


def test_direct_light_with_the_fit_gains_energy_where_it_underestimates_the_lobe(grid):
    """The measured overshoot (see the module docstring), so the docs' figure stays true."""
    mu, r, integral = grid
    fit = np.asarray(evaluate("pbr_env_brdf(NdotV, r)", defines=ANALYTIC, NdotV=mu, r=r), np.float64)[:, :2]
    f0 = np.full((len(mu), 3), 0.04)
    f90 = ref_brdf.f90_from_f0(f0)
    true_albedo = 0.04 * integral[:, 0] + f90 * integral[:, 1]
    fit_albedo = 0.04 * fit[:, 0] + f90 * fit[:, 1]
    reflectance = true_albedo + (1.0 - np.clip(fit_albedo, 0.0, 1.0))
    print(f"white dielectric under direct light with the fit: max {reflectance.max():.4f}; "
          f"scale needed {np.max(true_albedo / fit_albedo):.3g}")
    assert 1.07 < reflectance.max() < 1.10
    assert np.max(true_albedo / fit_albedo) > 5.0
