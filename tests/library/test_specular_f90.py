"""KHR_materials_specular's explicit F90 (pbr_specular_F_f90, pbr_brdf_standard_f90,
pbr_specular_albedo_f90, pbr_lighting_standard_f90) against the float64 reference written
from the extension (reference/specular_extension.py), and the plain forms unchanged: they are
the _f90 forms at F90 = pbr_f90_from_f0(f0), bit for bit."""

import numpy as np
import pytest

from library_helpers import (as_f32, assert_close, evaluate, perceptual_roughnesses, seeded_rng,
                             unit_vectors, v_cosines, vec3)
from pbrlab import vec2
from pbrlab.maths.reference import shading, specular_extension as ext

N = np.array([0.0, 0.0, 1.0])
BRDF = ["pbr/shading/standard.glsl"]
LIGHTING = ["pbr/surface/lighting_standard.glsl"]


def _materials(rng, count):
    """The extension's parameters drawn over their range: IOR 1 .. 3 (KHR_materials_ior; 0.0
    and large IORs reach F0 = 1), colour factor 0 .. 2 (the spec allows > 1: the clamp), strength
    0 .. 1; returned as (F0, F90) float32, F0 on a last axis of 3."""
    ior = rng.uniform(1.0, 3.0, count)
    colour = rng.uniform(0.0, 2.0, (count, 3))
    strength = rng.uniform(0.0, 1.0, count)
    return as_f32(ext.dielectric_f0(ior, colour, strength)), as_f32(ext.dielectric_f90(strength))


def test_dielectric_f0_clamps_before_the_strength_and_f90_is_the_strength():
    # README, "Implementation": min(0.04 x specularColor, 1) x specular, and dielectric_f90 = specular
    f0 = ext.dielectric_f0(np.array([1.5, 1.5, 0.0]), np.array([[1, 1, 1], [50, 0, 0.5], [1, 0, 0]]),
                           np.array([0.5, 0.5, 0.25]))
    np.testing.assert_allclose(f0, [[0.02] * 3, [0.5, 0.0, 0.01], [0.25, 0, 0]], rtol=1e-15, atol=1e-17)
    assert ext.dielectric_f90(0.3) == 0.3
    # a zero colour keeps F90: the rim of SpecularTest's first column
    assert ext.dielectric_fresnel(np.zeros(3), np.array(0.8), np.array(0.0)).tolist() == [0.8] * 3


def test_direct_lobe_with_f90_matches_the_extension():
    """The specular lobe (diffuse 0) of pbr_brdf_standard_f90 against dielectric_fresnel x
    D_GGX x V_GGX written from the extension and glTF's Appendix B, at the HIGH tier."""
    rng = seeded_rng("specular f90 lobe")
    count = 4096
    v = unit_vectors(rng, count, min_z=0.02)
    l = unit_vectors(rng, count, min_z=0.02)
    r = as_f32(rng.uniform(0.0, 1.0, count))
    f0, f90 = _materials(rng, count)
    got = evaluate("pbr_brdf_standard_f90(vec3(0.0, 0.0, 1.0), v, l, vec3(0.0), f0, f90, r)", BRDF,
                   v=vec3(v), l=vec3(l), f0=vec3(f0), f90=f90, r=r)
    alpha = np.maximum(r.astype(np.float64), shading.MIN_PERCEPTUAL_ROUGHNESS) ** 2
    ref = ext.specular_lobe(np.broadcast_to(N, v.shape), v, l, f0, f90, alpha)
    # the lobe is pbr_brdf_standard's (float32 against float64 in test_shading.py); peaks reach
    # 1e4 at the roughness floor, so the bound is relative, as the clear coat's lobe
    assert_close("pbr_brdf_standard_f90 specular", got[:, :3], ref, rtol=1e-4, atol=1e-6)


def test_f90_below_one_never_reflects_more_than_f90_one():
    """An F90 < 1 only lowers the lobe: Schlick is linear in F90 with weight (1 - VdotH)^5 >= 0."""
    rng = seeded_rng("specular f90 monotone")
    count = 2048
    v = unit_vectors(rng, count, min_z=0.02)
    l = unit_vectors(rng, count, min_z=0.02)
    r = as_f32(rng.uniform(0.0, 1.0, count))
    f0, f90 = _materials(rng, count)
    expression = "pbr_brdf_standard_f90(vec3(0.0, 0.0, 1.0), v, l, vec3(0.0), f0, f90, r)"
    low = evaluate(expression, BRDF, v=vec3(v), l=vec3(l), f0=vec3(f0), f90=f90, r=r)[:, :3]
    one = evaluate(expression, BRDF, v=vec3(v), l=vec3(l), f0=vec3(f0), f90=np.ones_like(f90), r=r)[:, :3]
    assert np.all(low <= one)


def test_specular_albedo_with_f90_matches_the_extensions_integral():
    """E = F0 A + F90 B (pbr_specular_albedo_f90) given the float64 quadrature's A, B (rounded to
    float32), against the extension's lobe integrated by reference/directional_albedo.py."""
    rng = seeded_rng("specular f90 albedo")
    mu, r = (as_f32(x.ravel()) for x in np.meshgrid(v_cosines(17), perceptual_roughnesses(9)))
    f0, f90 = _materials(rng, mu.size)
    alpha = np.maximum(r.astype(np.float64), shading.MIN_PERCEPTUAL_ROUGHNESS) ** 2
    from pbrlab.maths.reference import directional_albedo
    ab = directional_albedo.split_sum_terms_grid(mu.astype(np.float64), alpha)
    got = evaluate("pbr_specular_albedo_f90(f0, f90, dfg)", ["pbr/ibl/environment_brdf.glsl"],
                   f0=vec3(f0), f90=f90, dfg=vec2(as_f32(ab)))
    ref = ext.environment_albedo(mu.astype(np.float64), alpha, f0, f90)
    # two products and a sum of float32 values below 1, and the float32 rounding of A and B
    assert_close("pbr_specular_albedo_f90", got[:, :3], ref, rtol=1e-6, atol=3 * 2.0 ** -24)
    assert np.all(ref <= 1.0 + 1e-9)  # an F90 <= 1 keeps E <= A + B <= 1


@pytest.mark.parametrize("expression, f90_expression", [
    ("pbr_brdf_standard(n, v, l, d, f0, r)", "pbr_brdf_standard_f90(n, v, l, d, f0, pbr_f90_from_f0(f0), r)"),
    ("pbr_shade_punctual(n, v, l, vec3(1.0), d, f0, r)",
     "pbr_shade_punctual_f90(n, v, l, vec3(1.0), d, f0, pbr_f90_from_f0(f0), r)"),
], ids=["brdf", "punctual"])
@pytest.mark.parametrize("quality", ["HIGH", "MEDIUM", "LOW"])
def test_plain_forms_are_the_f90_forms_at_f90_from_f0(expression, f90_expression, quality):
    rng = seeded_rng("specular f90 plain " + expression)
    count = 1024
    inputs = dict(n=vec3(np.broadcast_to(N, (count, 3))), v=vec3(unit_vectors(rng, count, min_z=0.0)),
                  l=vec3(unit_vectors(rng, count)), d=vec3(as_f32(rng.uniform(0, 1, (count, 3)))),
                  f0=vec3(as_f32(rng.uniform(0, 0.3, (count, 3)))), r=as_f32(rng.uniform(0, 1, count)))
    defines = {"PBR_QUALITY": f"PBR_QUALITY_{quality}"}
    plain = evaluate(expression, ["pbr/lighting/punctual.glsl"], defines=defines, **inputs)
    explicit = evaluate(f90_expression, ["pbr/lighting/punctual.glsl"], defines=defines, **inputs)
    np.testing.assert_array_equal(plain.view(np.uint32), explicit.view(np.uint32))


def test_lighting_with_f90_couples_the_diffuse_to_the_f90_albedo():
    """pbr_lighting_standard_f90_dfg in a white furnace (environment 1 everywhere, irradiance /
    pi 1, no light), with the float64 quadrature's A, B as the DFG values: a white
    specular-workflow dielectric reflects E + (1 - E) = 1 whatever its F90 (the diffuse takes
    what the F90 lobe leaves), a black one E = (F0 A + F90 B) x the compensation at F0, < 1."""
    from pbrlab.maths.reference import directional_albedo, surface
    rng = seeded_rng("specular f90 furnace")
    count = 512
    v = unit_vectors(rng, count, min_z=0.05)
    r = as_f32(rng.uniform(0.0, 1.0, count))
    f90 = as_f32(rng.uniform(0.0, 1.0, count))
    f0 = as_f32(np.minimum(rng.uniform(0.0, 0.1, (count, 3)), f90[:, None]))
    white = as_f32(1.0 - f0.max(axis=1, keepdims=True)) * np.ones((1, 3), np.float32)  # Unity's albedo (1 - max F0)
    rr = np.maximum(r.astype(np.float64), shading.MIN_PERCEPTUAL_ROUGHNESS)
    dfg = as_f32(directional_albedo.split_sum_terms_grid(np.maximum(v[:, 2], shading.MIN_NDOTV), rr ** 2))
    expression = ("pbr_lighting_standard_f90_dfg(d, f0, f90, f0, f90, r, 1.0, vec3(0.0, 0.0, 1.0), v, "
                  "pbr_GI(pbr_Light(vec3(0.0), vec3(0.0, 0.0, 1.0)), pbr_Indirect(vec3(1.0), vec3(1.0))), dfg)")
    inputs = dict(f0=vec3(f0), f90=f90, r=r, v=vec3(v), dfg=vec2(dfg))
    got = evaluate(expression, LIGHTING, d=vec3(white), **inputs)
    np.testing.assert_allclose(got[:, :3], 1.0, atol=1e-6)  # measured: float32 sums of terms <= 1
    black = evaluate(expression, LIGHTING, d=vec3(np.zeros_like(f0)), **inputs)
    want = surface.indirect_specular_albedo(f0, dfg.astype(np.float64), True, f90)
    assert_close("pbr_lighting_standard_f90 black furnace", black[:, :3], want, rtol=1e-5, atol=1e-6)
    assert np.all(black[:, :3] <= 1.0 + 1e-6)
