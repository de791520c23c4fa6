"""Material layer (glsl/pbr/material/): roughness remaps, metallic/specular workflows, the
lecture's F0 tables and F0 <-> IOR, against harness/pbrlab/maths/reference/{remap,material}.py."""

import numpy as np
import pytest

from library_helpers import (seeded_rng, RTOL_WELL_CONDITIONED, alphas, as_f32, assert_close, evaluate,
                             perceptual_roughnesses, vec3)
from pbrlab.maths.reference import brdf, material, remap

GLOSS = as_f32(np.linspace(0.0, 1.0, 4097))


@pytest.mark.parametrize("name, data", [
    ("perceptual_roughness_from_smoothness", GLOSS),
    ("alpha_from_perceptual_roughness", GLOSS),
    ("perceptual_roughness_from_alpha", GLOSS),
    ("alpha_from_smoothness", GLOSS),
    ("alpha_from_gloss_Crytek", GLOSS),
    ("alpha_from_gloss_Unreal", GLOSS),
    ("specPower_from_alpha", alphas(257)),
    ("alpha_from_specPower", as_f32(np.geomspace(1e-3, 1e6, 257))),
])
def test_remap_matches_reference(name, data):
    # atol 1e-7: these are O(1) values that reach exactly 0 (e.g. 1 - smoothness at 1)
    got = evaluate(f"pbr_{name}(x)", x=data)
    assert_close(f"pbr_{name}", got, getattr(remap, name)(data), rtol=RTOL_WELL_CONDITIONED, atol=1e-7)


def test_specPower_from_gloss_CallOfDuty_matches_reference():
    """s = 8192^g = 2^(13 g): exp2 carries (3 + 2|13 g|) ulp per the GLSL spec; 1e-5 covers it."""
    got = evaluate("pbr_specPower_from_gloss_CallOfDuty(g)", g=GLOSS)
    assert_close("pbr_specPower_from_gloss_CallOfDuty", got, remap.specPower_from_gloss_CallOfDuty(GLOSS),
                 rtol=RTOL_WELL_CONDITIONED)
    assert got[0] == 1.0 and got[-1] == 8192.0


def test_roughness_vocabulary_chain():
    """smoothness -> perceptualRoughness -> alpha, and the remaps that must coincide."""
    s = GLOSS
    np.testing.assert_allclose(remap.alpha_from_smoothness(s), remap.alpha_from_gloss_Unreal(s))
    np.testing.assert_allclose(remap.alpha_from_specPower(remap.specPower_from_alpha(alphas())), alphas(), rtol=1e-12)
    assert remap.alpha_from_gloss_Crytek(1.0) == pytest.approx(0.09)


@pytest.fixture(scope="module")
def albedo_grid():
    rng = seeded_rng("albedo_grid")
    albedo = as_f32(rng.uniform(0.0, 1.0, (4096, 3)))
    metallic = as_f32(np.linspace(0.0, 1.0, 17))[:, None]
    return albedo[None], metallic


def test_metallic_workflow_matches_reference(albedo_grid):
    albedo, metallic = albedo_grid
    got = evaluate("pbr_f0_from_metallic(albedo, m)", albedo=vec3(albedo), m=metallic)
    assert_close("pbr_f0_from_metallic", got, material.f0_from_metallic(albedo, metallic),
                 rtol=RTOL_WELL_CONDITIONED, atol=1e-7)
    got = evaluate("pbr_diffuse_from_metallic(albedo, m)", albedo=vec3(albedo), m=metallic)
    assert_close("pbr_diffuse_from_metallic", got, material.diffuse_from_metallic(albedo, metallic),
                 rtol=RTOL_WELL_CONDITIONED, atol=1e-7)


def test_metallic_extremes():
    """metallic 0: grey F0 = 0.04 and diffuse = 0.96 albedo; metallic 1: F0 = albedo, no diffuse."""
    gold = np.array(material.F0_METALS["GOLD"])
    f0 = evaluate("vec3(pbr_f0_from_metallic(a, 0.0).x, pbr_f0_from_metallic(a, 1.0).yz)", a=vec3(gold))
    np.testing.assert_allclose(f0, [0.04, gold[1], gold[2]], rtol=1e-7)
    assert (evaluate("pbr_diffuse_from_metallic(a, 1.0)", a=vec3(gold)) == 0.0).all()


def test_specular_workflow_matches_reference(rng):
    albedo = as_f32(rng.uniform(0.0, 1.0, (20000, 3)))
    specular = as_f32(rng.uniform(0.0, 1.0, (20000, 3)))
    for name in ("diffuse_from_specular", "diffuse_from_specular_per_channel"):
        got = evaluate(f"pbr_{name}(a, s)", a=vec3(albedo), s=vec3(specular))
        assert_close(f"pbr_{name}", got, getattr(material, name)(albedo, specular),
                     rtol=RTOL_WELL_CONDITIONED, atol=1e-7)
        # energy conservation: diffuse + specular <= 1 per channel (albedo, specular <= 1)
        assert (got + specular <= 1.0 + 1e-6).all(), name


def test_metallic_zero_equals_specular_workflow_with_dielectric_f0(rng):
    albedo = as_f32(rng.uniform(0.0, 1.0, (4096, 3)))
    a = evaluate("pbr_diffuse_from_metallic(a, 0.0)", a=vec3(albedo))
    b = evaluate("pbr_diffuse_from_specular(a, vec3(PBR_DIELECTRIC_F0))", a=vec3(albedo))
    np.testing.assert_allclose(a, b, rtol=1e-6)


def test_monochrome_form_keeps_diffuse_hue_per_channel_form_shifts_it():
    albedo = np.array([0.8, 0.4, 0.2])
    specular = np.array(material.F0_METALS["COPPER"])
    mono = evaluate("pbr_diffuse_from_specular(a, s)", a=vec3(albedo), s=vec3(specular))
    per = evaluate("pbr_diffuse_from_specular_per_channel(a, s)", a=vec3(albedo), s=vec3(specular))
    np.testing.assert_allclose(mono / mono[0], albedo / albedo[0], rtol=1e-6)
    assert not np.allclose(per / per[0], albedo / albedo[0], rtol=1e-2)


def test_F0_tables_match_reference_and_the_lecture():
    """Every PBR_F0_* macro equals the float32 rounding of the lecture's table
    (reference.material, copied from the slides); dielectrics are grey scalars, metals RGB."""
    for name, value in material.F0_DIELECTRICS.items():
        assert evaluate(f"float(PBR_F0_{name})", x=0.0) == np.float32(value), name
    for name, rgb in material.F0_METALS.items():
        np.testing.assert_array_equal(evaluate(f"PBR_F0_{name}", x=0.0), np.float32(rgb), err_msg=name)
    assert len(material.F0_DIELECTRICS) == 10 and len(material.F0_METALS) == 9
    assert material.F0_DIELECTRICS["GLASS"] == material.DIELECTRIC_F0
    assert float(evaluate("PBR_DIELECTRIC_F0", x=0.0)) == np.float32(0.04)


def test_ior_helpers_match_reference_and_invert():
    eta = as_f32(np.linspace(1.0, 3.0, 2001))
    got = evaluate("pbr_f0_from_ior(eta)", eta=eta)
    assert_close("pbr_f0_from_ior", got, material.f0_from_ior(eta), rtol=RTOL_WELL_CONDITIONED, atol=1e-9)
    f0 = as_f32(np.linspace(0.0, 0.9, 2001))
    got = evaluate("pbr_ior_from_f0(f0)", f0=f0)
    # d eta / d F0 = 1/(sqrt F0 (1 - sqrt F0)²): float32 rounding of F0 near 0.9 (and of
    # sqrt) is amplified ~40x; rtol 1e-5 still holds with margin (measured below 1e-6)
    assert_close("pbr_ior_from_f0", got, material.ior_from_f0(f0), rtol=RTOL_WELL_CONDITIONED)
    # glass: 0.04 <-> 1.5; the dielectric table maps to plausible IORs (1.3 .. 2.5)
    assert material.ior_from_f0(0.04) == pytest.approx(1.5)
    iors = material.ior_from_f0(np.array(list(material.F0_DIELECTRICS.values())))
    assert ((iors > 1.3) & (iors < 2.5)).all()


def test_f0_from_ior_equals_exact_fresnel_at_normal_incidence():
    eta = as_f32(np.linspace(1.05, 3.0, 400))
    got = evaluate("pbr_F_Dielectric(1.0, eta) - pbr_f0_from_ior(eta)", eta=eta)
    assert np.abs(got).max() <= 1e-7
    np.testing.assert_allclose(brdf.F_Dielectric(1.0, eta), material.f0_from_ior(eta), rtol=1e-12)
