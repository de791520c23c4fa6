"""KHR_materials_specular's explicit F90 through the layers that change the base: the
anisotropic lobe (pbr_brdf_anisotropic_specular_f90), the film (pbr_iridescent_f0_f90) and the
transmission's weights (pbr_lighting_transmission_f90), against the float64 reference written
from the extensions (reference/specular_extension.py: anisotropic_lobe, iridescent_f0_f90;
reference/surface.py lighting_transmission with coat_f90), and the forms without an explicit
F90 unchanged: the _f90 forms at F90 = pbr_f90_from_f0 (or F90 = 1 for the film) bit for bit."""

import numpy as np
import pytest

from library_helpers import as_f32, assert_close, evaluate, seeded_rng, unit_vectors, vec3
from pbrlab.maths.reference import shading, specular_extension as ext, surface

N = np.array([0.0, 0.0, 1.0])
ANISOTROPY = ["pbr/shading/anisotropy.glsl"]
FILM = ["pbr/surface/lighting_iridescence.glsl"]
TRANSMISSION = ["pbr/surface/lighting_transmission.glsl"]
FRAME = "vec3(0.0, 0.0, 1.0), v, l, vec3(1.0, 0.0, 0.0), vec3(0.0, 1.0, 0.0)"


def _materials(rng, count):
    """(F0, F90) as the extension makes them: IOR 1 .. 3, colour 0 .. 2, strength 0 .. 1."""
    ior = rng.uniform(1.0, 3.0, count)
    colour = rng.uniform(0.0, 2.0, (count, 3))
    strength = rng.uniform(0.0, 1.0, count)
    return as_f32(ext.dielectric_f0(ior, colour, strength)), as_f32(ext.dielectric_f90(strength))


def test_anisotropic_lobe_with_f90_matches_the_extensions():
    """pbr_brdf_anisotropic_specular_f90 against dielectric_fresnel x D_aniso x V_aniso written
    from KHR_materials_specular and KHR_materials_anisotropy (HIGH tier), n = z, t = x, b = y.
    The lobe is the anisotropic one of tests/library/test_anisotropy.py (float32 against
    float64, peaks of 1e4 at the roughness floor): a relative bound, as the isotropic F90 lobe's;
    measured on llvmpipe 2.7e-6 relative."""
    rng = seeded_rng("specular f90 anisotropic lobe")
    count = 4096
    v = unit_vectors(rng, count, min_z=0.02)
    l = unit_vectors(rng, count, min_z=0.02)
    r = as_f32(rng.uniform(0.0, 1.0, count))
    strength = as_f32(rng.uniform(0.0, 1.0, count))
    f0, f90 = _materials(rng, count)
    got = evaluate(f"pbr_brdf_anisotropic_specular_f90({FRAME}, f0, f90, r, s)", ANISOTROPY,
                   v=vec3(v), l=vec3(l), f0=vec3(f0), f90=f90, r=r, s=strength)
    alpha = np.maximum(r.astype(np.float64), shading.MIN_PERCEPTUAL_ROUGHNESS) ** 2
    ref = ext.anisotropic_lobe(np.broadcast_to(N, v.shape), v, l, np.broadcast_to([1.0, 0, 0], v.shape),
                               np.broadcast_to([0, 1.0, 0], v.shape), f0, f90, alpha, strength)
    assert_close("pbr_brdf_anisotropic_specular_f90", got[:, :3], ref, rtol=1e-4, atol=1e-6)
    # an F90 below F90 from F0 lowers the lobe, one above raises it: the F90 is read
    plain = evaluate(f"pbr_brdf_anisotropic_specular({FRAME}, f0, r, s)", ANISOTROPY,
                     v=vec3(v), l=vec3(l), f0=vec3(f0), r=r, s=strength)
    assert np.abs(plain - got)[:, :3].max() > 1e-3


def test_anisotropic_plain_lobe_is_the_f90_form_at_f90_from_f0():
    rng = seeded_rng("specular f90 anisotropic plain")
    count = 1024
    inputs = dict(v=vec3(unit_vectors(rng, count, min_z=0.0)), l=vec3(unit_vectors(rng, count)),
                  f0=vec3(as_f32(rng.uniform(0.0, 1.0, (count, 3)))), r=as_f32(rng.uniform(0.0, 1.0, count)),
                  s=as_f32(rng.uniform(0.0, 1.0, count)))
    plain = evaluate(f"pbr_brdf_anisotropic_specular({FRAME}, f0, r, s)", ANISOTROPY, **inputs)
    explicit = evaluate(f"pbr_brdf_anisotropic_specular_f90({FRAME}, f0, pbr_f90_from_f0(f0), r, s)", ANISOTROPY,
                        **inputs)
    np.testing.assert_array_equal(plain.view(np.uint32), explicit.view(np.uint32))


def _film_inputs(rng, count):
    f0, f90 = _materials(rng, count)
    f90[:8] = [0.0, 1.0, 1.0, 0.5, 1e-6, 0.25, 0.0, 1.0]  # F90 0 (F0 0 then), 1, tiny
    f0[:8] = np.minimum(f0[:8], f90[:8, None])
    return dict(f0=f0, f90=f90, NdotV=as_f32(rng.uniform(0.02, 1.0, count)),
                factor=as_f32(rng.uniform(0.0, 1.0, count)), ior=as_f32(rng.uniform(1.0, 2.3, count)),
                thickness=as_f32(rng.uniform(0.0, 1200.0, count)))


def test_film_with_f90_matches_the_float64_reference():
    """pbr_iridescent_f0_f90 (the film over F0 / F90, scaled by F90) against
    ext.iridescent_f0_f90. The film is pbr_iridescent_f0's (worst 1.0e-5 absolute against its
    float64 twin, tests/surface/test_lighting_iridescence.py: float32 phase rounding, the
    inversion near grazing); F90 <= 1 scales it and F0 / F90 adds one rounding: the same 5e-5.
    F0' never exceeds F90 (the precondition of every F90 form the base then calls)."""
    rng = seeded_rng("specular f90 film")
    x = _film_inputs(rng, 8192)
    got = evaluate("pbr_iridescent_f0_f90(f0, f90, NdotV, pbr_Iridescence(factor, ior, thickness))", FILM,
                   f0=vec3(x["f0"]), f90=x["f90"], NdotV=x["NdotV"], factor=x["factor"], ior=x["ior"],
                   thickness=x["thickness"])[:, :3]
    want = ext.iridescent_f0_f90(x["f0"], x["f90"], x["NdotV"], x["factor"], x["ior"], x["thickness"])
    err = np.abs(got - want)
    assert err.max() < 5e-5, err.max()
    assert np.all(got <= x["f90"][:, None] * (1 + 2.0 ** -23)) and np.all(got >= 0.0)
    np.testing.assert_array_equal(got[[0, 6]], 0.0)  # F90 0: no reflection, film or not


def test_film_with_f90_one_is_the_plain_film_exactly():
    rng = seeded_rng("specular f90 film one")
    x = _film_inputs(rng, 2048)
    film = "pbr_Iridescence(factor, ior, thickness)"
    inputs = dict(f0=vec3(as_f32(np.minimum(x["f0"], 1.0))), NdotV=x["NdotV"], factor=x["factor"], ior=x["ior"],
                  thickness=x["thickness"])
    plain = evaluate(f"pbr_iridescent_f0(f0, NdotV, {film})", FILM, **inputs)
    explicit = evaluate(f"pbr_iridescent_f0_f90(f0, 1.0, NdotV, {film})", FILM, **inputs)
    np.testing.assert_array_equal(plain.view(np.uint32), explicit.view(np.uint32))


@pytest.mark.parametrize("roughness", [0.3, 0.9])
@pytest.mark.parametrize("thickness", [0.0, 0.8], ids=["thin", "volume"])
def test_transmission_with_f90_matches_the_float64_reference(thickness, roughness):
    """pbr_lighting_transmission_f90 (its weights rho (1 - E_coat), E_coat = coatF0 A + coatF90
    B) against reference/surface.py lighting_transmission with coat_f90, one light behind the
    surface and an environment seen through, at the HIGH tier. Float32 sums of float32 terms
    against float64: 1e-4 relative asked, measured on llvmpipe 2.5e-5 (the volume's BTDF peaks)."""
    rng = seeded_rng(f"specular f90 transmission {thickness}")
    count = 2048
    v = unit_vectors(rng, count, min_z=0.05)
    l = -unit_vectors(rng, count, min_z=0.05)  # behind the surface
    r = np.float32(roughness)
    f0, f90 = _materials(rng, count)
    diffuse = as_f32(rng.uniform(0.0, 1.0, (count, 3)) * (1.0 - f0.max(axis=1, keepdims=True)))
    behind = as_f32(rng.uniform(0.0, 2.0, (count, 3)))
    expression = (f"pbr_lighting_transmission_f90(d, f0, f90, {roughness}, 1.0, vec3(0.0, 0.0, 1.0), v, "
                  "pbr_GI(pbr_Light(vec3(1.0), l), pbr_Indirect(vec3(0.0), vec3(0.0))), behind, "
                  f"pbr_Transmission(0.9, {thickness}, vec3(0.8, 0.6, 0.4), 2.0, 1.4))")
    got = evaluate(expression, TRANSMISSION, d=vec3(diffuse), f0=vec3(f0), f90=f90, v=vec3(v), l=vec3(l),
                   behind=vec3(behind))
    # the evaluator has no table hook: pbr_env_brdf is the analytic fit, env_brdf_approx's twin
    dfg = surface.env_brdf_approx(np.maximum(v[:, 2], shading.MIN_NDOTV), np.full(count, float(r)))
    terms = (diffuse, f0, float(r), 1.0, np.broadcast_to(N, v.shape), v, l, np.ones((count, 3)), behind, dfg, 0.9,
             thickness, np.array([0.8, 0.6, 0.4]), 2.0, 1.4)
    want = surface.lighting_transmission(*terms, coat_f90=f90)
    assert_close("pbr_lighting_transmission_f90", got[:, :3], want, rtol=1e-4, atol=1e-6)
    assert np.abs(surface.lighting_transmission(*terms) - want).max() > 1e-3  # the F90 is read
