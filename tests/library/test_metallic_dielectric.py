"""The metallic workflow with the dielectric's own F0 and F90 (KHR_materials_ior /
KHR_materials_specular on partly metallic materials): pbr_f0_from_metallic_dielectric,
pbr_diffuse_from_metallic_dielectric and pbr_f90_from_metallic (pbr/material/workflow.glsl)
against their float64 twins (reference/material.py), those against the extension's own
formulas (reference/specular_extension.py), and the plain forms as the special cases they are,
bit for bit: the dielectric F0 0.04 is pbr_f0_from_metallic / pbr_diffuse_from_metallic,
metallic 0 is the specular workflow."""

import numpy as np

from library_helpers import RTOL_WELL_CONDITIONED, as_f32, assert_close, evaluate, seeded_rng, vec3
from pbrlab.maths.reference import material, specular_extension as ext


def _materials(rng, count):
    """Base colour, metallic, and the extension's dielectric F0 / F90 drawn over their range:
    IOR 1 .. 3, colour factor 0 .. 2 (the spec allows > 1: the clamp), strength 0 .. 1."""
    albedo = as_f32(rng.uniform(0.0, 1.0, (count, 3)))
    metallic = as_f32(rng.uniform(0.0, 1.0, count))
    metallic[:3] = [0.0, 0.5, 1.0]
    strength = rng.uniform(0.0, 1.0, count)
    f0 = as_f32(ext.dielectric_f0(rng.uniform(1.0, 3.0, count), rng.uniform(0.0, 2.0, (count, 3)), strength))
    return albedo, metallic, f0, as_f32(ext.dielectric_f90(strength))


def test_the_twins_are_the_extensions_mix():
    rng = seeded_rng("metallic dielectric twins")
    albedo, metallic, f0, f90 = _materials(rng, 4096)
    np.testing.assert_allclose(material.f0_from_metallic_dielectric(albedo, metallic, f0),
                               ext.metallic_f0(f0, albedo, metallic), rtol=1e-15, atol=1e-17)
    np.testing.assert_allclose(material.f90_from_metallic(f90, metallic), ext.metallic_f90(f90, metallic),
                               rtol=1e-15, atol=1e-17)
    # the defaults (ior 1.5, no KHR_materials_specular) are Unity's metallic setup
    default_f0 = ext.dielectric_f0(np.array(1.5), np.ones(3), np.array(1.0))
    np.testing.assert_allclose(default_f0, material.DIELECTRIC_F0, rtol=1e-15)
    np.testing.assert_allclose(material.diffuse_from_metallic_dielectric(albedo, metallic, default_f0),
                               material.diffuse_from_metallic(albedo, metallic), rtol=1e-15)


def test_metallic_dielectric_setup_matches_the_float64_reference():
    rng = seeded_rng("metallic dielectric setup")
    albedo, metallic, f0, f90 = _materials(rng, 4096)
    inputs = dict(albedo=vec3(albedo), m=metallic, d=vec3(f0))
    got = evaluate("pbr_f0_from_metallic_dielectric(albedo, m, d)", **inputs)
    assert_close("pbr_f0_from_metallic_dielectric", got, ext.metallic_f0(f0, albedo, metallic),
                 rtol=RTOL_WELL_CONDITIONED, atol=1e-7)
    got = evaluate("pbr_diffuse_from_metallic_dielectric(albedo, m, d)", **inputs)
    assert_close("pbr_diffuse_from_metallic_dielectric", got,
                 material.diffuse_from_metallic_dielectric(albedo, metallic, f0), rtol=RTOL_WELL_CONDITIONED,
                 atol=1e-7)
    got = evaluate("pbr_f90_from_metallic(f90, m)", f90=f90, m=metallic)
    assert_close("pbr_f90_from_metallic", got, ext.metallic_f90(f90, metallic),
                 rtol=RTOL_WELL_CONDITIONED, atol=1e-7)


def test_the_plain_forms_are_the_dielectric_f0_of_004_bit_for_bit():
    rng = seeded_rng("metallic dielectric plain")
    albedo, metallic, _, _ = _materials(rng, 4096)
    for plain, general in (("pbr_f0_from_metallic(a, m)", "pbr_f0_from_metallic_dielectric(a, m, vec3(0.04))"),
                           ("pbr_diffuse_from_metallic(a, m)",
                            "pbr_diffuse_from_metallic_dielectric(a, m, vec3(0.04))")):
        assert np.array_equal(evaluate(plain, a=vec3(albedo), m=metallic),
                              evaluate(general, a=vec3(albedo), m=metallic)), plain


def test_metallic_zero_is_the_specular_workflow_bit_for_bit():
    """F0 = the dielectric's F0 and the diffuse = pbr_diffuse_from_specular(albedo, F0): the
    glTF importer's specular workflow for metallicFactor 0 is the same material."""
    rng = seeded_rng("metallic dielectric zero")
    albedo, _, f0, _ = _materials(rng, 4096)
    inputs = dict(a=vec3(albedo), d=vec3(f0))
    assert np.array_equal(evaluate("pbr_diffuse_from_metallic_dielectric(a, 0.0, d)", **inputs),
                          evaluate("pbr_diffuse_from_specular(a, d)", **inputs))
    assert np.array_equal(evaluate("pbr_f0_from_metallic_dielectric(a, 0.0, d)", **inputs), f0)
    # metallic 1: the base colour, no diffuse, F90 1, whatever the dielectric
    assert np.array_equal(evaluate("pbr_f0_from_metallic_dielectric(a, 1.0, d)", **inputs), albedo)
    assert (evaluate("pbr_diffuse_from_metallic_dielectric(a, 1.0, d)", **inputs) == 0.0).all()
    assert (evaluate("pbr_f90_from_metallic(d.x, 1.0)", **inputs) == 1.0).all()
