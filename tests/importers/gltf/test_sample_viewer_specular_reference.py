"""reference/sample_viewer_specular.py (the glTF Sample Renderer's getIBLGGXFresnel and its
image-based mix) against what its sources say it must be, and the prediction's refusal of
materials it does not model. No browser: the as-rendered comparison that reports it is
test_khronos_models.py::test_specular_test_within_the_bound_and_the_viewers_environment_fresnel."""

from __future__ import annotations

import numpy as np
import pytest

from pbrlab.foundation.errors import PbrlabError
from pbrlab.importers.gltf import load_gltf
from pbrlab.checking.golden_scenes import GLTF_DIR
from pbrlab.maths.reference import sample_viewer_specular as viewer
from pbrlab.checking.sample_viewer_prediction import viewer_minus_pbrlab
from pbrlab.scene.model import Environment

NDOTV = np.linspace(0.001, 1.0, 200)
ROUGHNESS = (0.0, 0.1, 0.3, 0.6, 1.0)


@pytest.mark.parametrize("roughness", ROUGHNESS)
def test_a_perfect_reflector_reflects_the_whole_white_furnace(roughness):
    """Fdez-Aguera 2019, section 2: with F0 = 1 the single scattering A + B and the multiple
    scattering 1 - (A + B) add up to 1 at every n.v and roughness (a slip in the series or the
    roughness-dependent k_S breaks it)."""
    assert np.abs(viewer.ibl_ggx_fresnel(NDOTV, roughness, 1.0) - 1.0).max() <= 1e-12


@pytest.mark.parametrize("f0, weight", [(0.04, 1.0), (0.02, 0.5), ((0.04, 0.036, 0.0), 0.9)])
def test_the_smooth_limit_is_schlick_weighted_by_the_split_sum(f0, weight):
    """Roughness 0: k_S is Schlick's F0 + (1 - F0)(1 - n.v)^5, A = 1 - (1 - n.v)^5, B = (1 -
    n.v)^5 (a mirror's split sum), no multiple scattering, all times the specular weight:
    E = w (k_S A + B). 1e-6: the viewer's table row it reads is roughness 1/256, not 0
    (measured 7e-8 for n.v >= 0.05; its masking reaches 1e-4 only at grazing n.v 0.001)."""
    mu = NDOTV[NDOTV >= 0.05]
    f0 = np.asarray(f0, float)
    x5 = (1.0 - mu) ** 5
    if f0.ndim:
        x5 = x5[:, None]
    expected = weight * ((f0 + (1.0 - f0) * x5) * (1.0 - x5) + x5)
    assert np.abs(viewer.ibl_ggx_fresnel(mu, 0.0, f0, weight) - expected).max() <= 1e-6


@pytest.mark.parametrize("roughness", ROUGHNESS)
def test_the_viewers_mix_of_diffuse_dielectric_and_metal(roughness):
    """pbr.frag: a white dielectric under a white sky returns the sky (the diffuse takes what
    the Fresnel leaves); a black one its Fresnel; a metal E(baseColor, 1); metallic 0.5 the mean."""
    sky = np.ones((NDOTV.size, 3))
    white = viewer.environment_radiance(NDOTV, roughness, np.ones(3), 0.0, 0.04, 0.7, sky, sky)
    assert np.abs(white - 1.0).max() <= 1e-12
    black = viewer.environment_radiance(NDOTV, roughness, np.zeros(3), 0.0, (0.04, 0.02, 0.0), 0.7, sky, sky)
    assert np.array_equal(black, viewer.ibl_ggx_fresnel(NDOTV, roughness, np.array([0.04, 0.02, 0.0]), 0.7))
    gold = np.array([1.0, 0.78, 0.34])
    metal = viewer.environment_radiance(NDOTV, roughness, gold, 1.0, 0.04, 0.7, sky, sky)
    assert np.array_equal(metal, viewer.ibl_ggx_fresnel(NDOTV, roughness, np.broadcast_to(gold, sky.shape)))
    half = viewer.environment_radiance(NDOTV, roughness, gold, 0.5, 0.04, 1.0, sky, sky)
    dielectric = viewer.environment_radiance(NDOTV, roughness, gold, 0.0, 0.04, 1.0, sky, sky)
    assert np.allclose(half, 0.5 * (dielectric + metal), rtol=0, atol=1e-15)


def test_the_dielectric_f0_is_the_ior_s_times_the_colour_clamped():
    """getIorInfo, getSpecularInfo: min(((ior - 1)/(ior + 1))^2 x colour, 1), the strength apart."""
    assert np.allclose(viewer.dielectric_f0(1.5, (1.0, 0.5, 100.0)), (0.04, 0.02, 1.0), rtol=1e-12, atol=0)


def test_the_prediction_refuses_a_material_it_does_not_model():
    """A coated material's viewer formulas are not these: a PbrlabError names the material."""
    scene = load_gltf(GLTF_DIR / "clearcoat.gltf", size=(64, 32), emit_warnings=False,
                      environment=Environment(color=np.array([0.25, 0.3, 0.35]))).scene
    with pytest.raises(PbrlabError, match="material .*coat"):
        viewer_minus_pbrlab(scene)
