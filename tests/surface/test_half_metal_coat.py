"""The diffuse of a partly metallic surface lies under the dielectric coat only
(pbr/shading/energy_conservation.glsl, coatF0): LightingStandard couples it to E(0.04), not to
E(f0) of f0 = mix(0.04, albedo, m); LightingStandardSpecular to E(s.Specular). Checked against
the float64 reference (reference/surface.py) and against Unity's uncoupled diffColor
(reference/unity_brdf.py, a transcription of UnityStandardUtils.cginc)."""

import numpy as np

from pbrlab import evaluate, vec3
from pbrlab.maths.reference import directional_albedo as ref_albedo
from pbrlab.maths.reference import material as ref_material
from pbrlab.maths.reference import shading as ref_shading
from pbrlab.maths.reference import surface as ref_surface
from pbrlab.maths.reference import unity_brdf

UNITY = ["pbr/unity/surface_standard.glsl"]
RNG = np.random.default_rng(29)
# environment diffuse only: no light, no environment specular, white irradiance / pi, occlusion 1
ENV_DIFFUSE = ("LightingStandard(SurfaceOutputStandard(albedo, n, vec3(0.0), metallic, smoothness, 1.0, 1.0),"
               " v, UnityGI(UnityLight(vec3(0.0), n), UnityIndirect(vec3(1.0), vec3(0.0))))")


def _reference(albedo, metallic, coat_f0, rough, n, v, specular_f0=None):
    diffuse = ref_material.diffuse_from_metallic(albedo, metallic)
    f0 = ref_material.f0_from_metallic(albedo, metallic) if specular_f0 is None else specular_f0
    r = ref_shading.clamp_perceptual_roughness(rough)
    dfg = ref_surface.env_brdf_approx(np.maximum(np.sum(n * v, axis=-1), ref_shading.MIN_NDOTV), r)
    count = len(n)
    return ref_surface.lighting_standard(diffuse, f0, coat_f0, rough, np.ones(count), n, v, n,
                                         np.zeros((count, 3)), np.ones((count, 3)), np.zeros((count, 3)), dfg)


def test_half_metal_diffuse_is_unitys_diffcolor_within_the_coats_coupling():
    albedo, metallic = np.array([[0.9, 0.45, 0.2]]), np.array([0.5])
    n = v = np.array([[0.0, 0.0, 1.0]])  # head-on
    got = evaluate(ENV_DIFFUSE, UNITY, albedo=vec3(albedo), n=vec3(n), v=vec3(v), metallic=metallic,
                   smoothness=np.array([0.0]))[:, :3]
    want = _reference(albedo, metallic, np.full(3, ref_material.DIELECTRIC_F0), 1.0, n, v)
    # float32 products of the analytic DFG fit: measured 5e-9; 1e-6 absolute is float32 eps x 8
    np.testing.assert_allclose(got, want, rtol=0, atol=1e-6)
    # Unity's diffColor = albedo (1 - 0.04)(1 - m) = (0.432, 0.216, 0.096); pbrlab replaces the
    # constant 1 - 0.04 by 1 - E_coat, E_coat the compensated albedo of F0 = 0.04 at this point.
    # With E_coat from the float64 integral (not the DFG fit): got = diffColor (1 - E_coat) / 0.96,
    # up to the fit's error of E there (measured 0.0031 at mu = 1, alpha = 1; bound 0.005).
    diff_color, _, _ = unity_brdf.diffuse_and_specular_from_metallic(albedo, metallic)
    A, B = ref_albedo.split_sum_terms_at_alpha(np.array([1.0]), 1.0)[0]
    e_coat = (0.04 * A + B) * (1 + 0.04 * (1 / (A + B) - 1))  # Karis 2013; Fdez-Aguera 2019 (F90 = 1)
    expected = diff_color * (1 - e_coat) / (1 - unity_brdf.DIELECTRIC_SPEC)
    assert np.all(np.abs(got - expected) <= 0.005 * diff_color / (1 - unity_brdf.DIELECTRIC_SPEC)), (got, expected)
    # the bracket: never above the dielectric's whole albedo share, never below what the coat leaves
    assert np.all(got <= diff_color / (1 - unity_brdf.DIELECTRIC_SPEC))
    assert np.all(got >= diff_color * (1 - e_coat - 0.005) / (1 - unity_brdf.DIELECTRIC_SPEC))
    # the coupling to E(f0) of the mixed f0 gave (0.55, 0.35, 0.17) here, 26-77 % over Unity;
    # the coat gives (0.443, 0.221, 0.098), 2.5 % over (E_coat 0.013 < 0.04)
    assert np.all(np.abs(got / diff_color - 1) < 0.05)


def test_partly_metallic_lighting_matches_the_reference_with_the_dielectric_coat():
    count = 4000
    n = np.tile([0.0, 0.0, 1.0], (count, 1))
    v = RNG.normal(size=(count, 3))
    v[:, 2] = np.abs(v[:, 2]) + 0.05
    v /= np.linalg.norm(v, axis=1, keepdims=True)
    albedo, metallic, smoothness = RNG.uniform(0, 1, (count, 3)), RNG.uniform(0.2, 0.8, count), RNG.uniform(0, 1, count)
    got = evaluate(ENV_DIFFUSE, UNITY, albedo=vec3(albedo), n=vec3(n), v=vec3(v), metallic=metallic,
                   smoothness=smoothness)[:, :3]
    want = _reference(albedo, metallic, np.full(3, ref_material.DIELECTRIC_F0), 1 - smoothness, n, v)
    # float32 products and a division by 0.96; measured 1.3e-7 absolute on values <= 1
    np.testing.assert_allclose(got, want, rtol=0, atol=1e-6)
    # the coat is the dielectric's: coupling to the mixed f0 would give another answer
    old = _reference(albedo, metallic, ref_material.f0_from_metallic(albedo, metallic), 1 - smoothness, n, v)
    assert np.abs(old - want).max() > 0.1


def test_specular_workflow_coat_is_the_specular_colour():
    count = 4000
    n = np.tile([0.0, 0.0, 1.0], (count, 1))
    v = np.tile([0.0, 0.6, 0.8], (count, 1))
    albedo, spec, smoothness = RNG.uniform(0, 1, (count, 3)), RNG.uniform(0, 0.6, (count, 3)), RNG.uniform(0, 1, count)
    got = evaluate("LightingStandardSpecular(SurfaceOutputStandardSpecular(albedo, spec, n, vec3(0.0), smoothness,"
                   " 1.0, 1.0), v, UnityGI(UnityLight(vec3(0.0), n), UnityIndirect(vec3(1.0), vec3(0.0))))",
                   UNITY, albedo=vec3(albedo), spec=vec3(spec), n=vec3(n), v=vec3(v), smoothness=smoothness)[:, :3]
    diffuse = ref_material.diffuse_from_specular(albedo, spec)
    r = ref_shading.clamp_perceptual_roughness(1 - smoothness)
    dfg = ref_surface.env_brdf_approx(np.full(count, 0.8), r)
    want = ref_surface.lighting_standard(diffuse, spec, spec, 1 - smoothness, np.ones(count), n, v, n,
                                         np.zeros((count, 3)), np.ones((count, 3)), np.zeros((count, 3)), dfg)
    # float32 division by 1 - max(spec) >= 0.4: measured 1.4e-7 absolute; 1e-6 = 8 float32 eps
    np.testing.assert_allclose(got, want, rtol=0, atol=1e-6)
