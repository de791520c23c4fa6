"""F90 from F0, the split-sum albedo with it, and the diffuse-specular coupling
(pbr/brdf/f_schlick.glsl, pbr/ibl/environment_brdf.glsl, pbr/shading/energy_conservation.glsl)
against their float64 references."""

import numpy as np

from library_helpers import evaluate
from pbrlab import vec2, vec3
from pbrlab.maths.reference import brdf as ref_brdf
from pbrlab.maths.reference import shading as ref_shading
from pbrlab.maths.reference import surface as ref_surface

INCLUDES = ["pbr/pbr.glsl"]
RNG = np.random.default_rng(13)


def test_f90_follows_f0_and_zero_f0_reflects_nothing():
    f0 = np.concatenate([RNG.uniform(0, 0.05, (3000, 3)), RNG.uniform(0, 1, (1000, 3)), np.zeros((1, 3))])
    got = evaluate("pbr_f90_from_f0(f0)", INCLUDES, f0=vec3(f0))
    np.testing.assert_allclose(got, ref_brdf.f90_from_f0(f0), rtol=0, atol=1e-6)
    assert got[-1] == 0.0
    # grey F0 >= 1 / (3 * 16.5) keeps "everything has Fresnel"
    grey = evaluate("pbr_f90_from_f0(vec3(x))", INCLUDES, x=np.array([0.0203, 0.04, 1.0]))
    assert np.all(grey == 1.0)
    # through the dispatcher: F0 = 0 gives F = 0 at every angle, in every Schlick form
    VdotH = np.linspace(0, 1, 101)
    for f in ("SCHLICK", "SCHLICK_SG"):
        zero = evaluate("pbr_specular_F(vec3(0.0), VdotH)", INCLUDES, defines={"PBR_SPECULAR_F": f"PBR_SPECULAR_F_{f}"},
                        VdotH=VdotH)
        assert np.all(zero == 0.0), f


def test_schlick_sg_with_f90_matches_reference():
    f0 = RNG.uniform(0, 1, (4000, 3))
    f90 = RNG.uniform(0, 1, 4000)
    VdotH = RNG.uniform(0, 1, 4000)
    got = evaluate("pbr_F_SchlickSG(f0, f90, VdotH)", INCLUDES, f0=vec3(f0), f90=f90, VdotH=VdotH)
    np.testing.assert_allclose(got, ref_brdf.F_SchlickSG(f0, VdotH[:, None], f90[:, None]), rtol=0, atol=2e-6)


def test_specular_albedo_coupling_and_bound_match_reference():
    n = 5000
    f0 = np.concatenate([RNG.uniform(0, 0.1, (n // 2, 3)), RNG.uniform(0, 1, (n - n // 2, 3))])
    dfg = RNG.uniform(0, 0.6, (n, 2))
    diffuse = RNG.uniform(0, 1, (n, 3)) * (1 - f0.max(-1, keepdims=True))
    # the GPU sees float32 inputs: the reference takes the same (1 - max f0 near 0 is
    # ill-conditioned in the inputs, not in the formula)
    f0, dfg, diffuse = (x.astype(np.float32).astype(np.float64) for x in (f0, dfg, diffuse))
    albedo = evaluate("pbr_specular_albedo(f0, dfg)", INCLUDES, f0=vec3(f0), dfg=vec2(dfg))
    np.testing.assert_allclose(albedo, ref_surface.specular_albedo(f0, dfg), rtol=2e-6, atol=1e-7)
    for f in ("SCHLICK", "SCHLICK_SG", "NONE"):
        defines = {"PBR_SPECULAR_F": f"PBR_SPECULAR_F_{f}"}
        bound = evaluate("pbr_specular_albedo_bound(f0, dfg)", INCLUDES, f0=vec3(f0), dfg=vec2(dfg), defines=defines)
        np.testing.assert_allclose(bound, ref_surface.specular_albedo_bound(f0, dfg, f), rtol=2e-6, atol=1e-7)
        deviation = evaluate("pbr_specular_F_deviation_bound(f0)", INCLUDES, f0=vec3(f0), defines=defines)
        np.testing.assert_allclose(deviation, ref_shading.specular_F_deviation_bound(f0, f), rtol=2e-6, atol=1e-7)
        # and it is a bound: |F - Schlick(f0, f90)| over a dense VdotH sweep stays within it
        VdotH = np.linspace(0, 1, 2001)
        fg = ref_shading.specular_F(f0[:50, None, :], VdotH[None, :], f)
        fs = ref_brdf.F_Schlick(f0[:50, None, :], VdotH[None, :, None], ref_brdf.f90_from_f0(f0[:50])[:, None, None])
        assert np.all(np.abs(fg - fs).max(axis=1) <= ref_shading.specular_F_deviation_bound(f0[:50], f) + 1e-12)
    spec = RNG.uniform(0, 1, (n, 3)).astype(np.float32).astype(np.float64)
    got = evaluate("pbr_coupled_diffuse_color(d, f0, e)", INCLUDES, d=vec3(diffuse), f0=vec3(f0), e=vec3(spec))
    want = ref_surface.coupled_diffuse_color(diffuse, f0, spec)
    np.testing.assert_allclose(got, want, rtol=3e-6, atol=1e-7)
    # the promise: E + coupled <= 1 per channel for any diffuse colour, a too-bright one included
    bright = evaluate("pbr_coupled_diffuse_color(vec3(5.0), f0, e)", INCLUDES, f0=vec3(f0), e=vec3(spec))
    assert np.all(bright + spec <= 1 + 1e-6)


def test_workflow_diffuse_is_recovered_as_the_albedo():
    # Metallic 0 and the specular workflow: rho = diffuseColor / (1 - max f0) is the albedo,
    # so the coupling replaces Unity's constant (1 - reflectivity) rather than stacking on it.
    albedo = RNG.uniform(0, 1, (2000, 3))
    spec = RNG.uniform(0, 0.2, (2000, 3))
    got = evaluate("pbr_diffuse_albedo_from_diffuse_color(pbr_diffuse_from_specular(a, s), s)", INCLUDES,
                   a=vec3(albedo), s=vec3(spec))
    np.testing.assert_allclose(got, albedo, rtol=3e-6, atol=1e-7)
    got = evaluate("pbr_diffuse_albedo_from_diffuse_color(pbr_diffuse_from_metallic(a, 0.0), "
                   "pbr_f0_from_metallic(a, 0.0))", INCLUDES, a=vec3(albedo))
    np.testing.assert_allclose(got, albedo, rtol=3e-6, atol=1e-7)
    # metals have no diffuse
    metal = evaluate("pbr_diffuse_albedo_from_diffuse_color(pbr_diffuse_from_metallic(a, 1.0), "
                     "pbr_f0_from_metallic(a, 1.0))", INCLUDES, a=vec3(albedo))
    assert np.all(metal == 0.0)
