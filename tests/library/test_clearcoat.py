"""The clear coat (pbr/shading/clearcoat.glsl, pbr/surface/lighting_clearcoat.glsl) against
its float64 reference (reference/clearcoat.py), and its energy: under a white furnace the
default layering never reflects more than 1, the specification's Fresnel layering does (by
a measured amount)."""

import numpy as np
import pytest

from library_helpers import (RTOL_WELL_CONDITIONED, as_f32, assert_close, evaluate, grid, perceptual_roughnesses,
                             seeded_rng, unit_vectors, v_cosines, vec3)
from pbrlab import vec2
from pbrlab.maths.reference import clearcoat, directional_albedo, shading, surface

INCLUDES = ["pbr/surface/lighting_clearcoat.glsl"]
N = np.array([0.0, 0.0, 1.0])


def _layering(name):
    return {"PBR_CLEARCOAT_LAYERING": f"PBR_CLEARCOAT_LAYERING_{name}"}


def test_coat_f0_is_the_fresnel_of_ior_1_5():
    assert clearcoat.CLEARCOAT_F0 == pytest.approx(0.04, abs=1e-15)
    got = evaluate("PBR_CLEARCOAT_F0 + x", INCLUDES, x=np.zeros(1, np.float32))
    assert got[0] == np.float32(0.04)


def test_coat_lobe_matches_reference():
    rng = seeded_rng("clearcoat lobe")
    count = 4096
    v = unit_vectors(rng, count, min_z=1e-3)
    l = unit_vectors(rng, count)
    r = as_f32(rng.uniform(0.0, 1.0, count))
    got = evaluate("pbr_clearcoat_punctual(vec3(0.0, 0.0, 1.0), v, l, vec3(1.0), r)", INCLUDES,
                   v=vec3(v), l=vec3(l), r=r)
    ref = clearcoat.clearcoat_punctual(np.broadcast_to(N, v.shape), v, l, np.ones(3), r)
    # the lobe is pbr_shade_punctual's (tested to float32 rounding against the same
    # reference in test_shading.py); peaks reach 1e4, so the bound is relative
    assert_close("pbr_clearcoat_punctual", got[:, :3], ref, rtol=1e-4, atol=1e-6)
    assert np.all(got[l[:, 2] <= 0, :3] == 0.0)  # a light below the coat's horizon: nothing


@pytest.mark.parametrize("layering", clearcoat.LAYERINGS)
def test_base_weight_matches_reference(layering):
    mu, r, mask = grid(v_cosines(65), perceptual_roughnesses(9), as_f32(np.linspace(0, 1, 5)))
    dfg = surface.env_brdf_approx(mu, r)
    got = evaluate("pbr_clearcoat_base_weight(mask, mu, dfg)", INCLUDES, defines=_layering(layering),
                   mask=mask, mu=mu, dfg=vec2(as_f32(dfg)))
    ref = clearcoat.clearcoat_base_weight(mask, mu, as_f32(dfg).astype(np.float64), layering)
    # 1 - mask F cancels as mask F -> 1 (grazing): the absolute error is F's own float32
    # rounding (<= 1 ulp of 1, 1.2e-7) plus the subtraction's (half an ulp): 2 ulp of 1
    assert_close(f"pbr_clearcoat_base_weight {layering}", got, ref, rtol=RTOL_WELL_CONDITIONED, atol=2 * 2.0 ** -23)
    assert np.all((got >= 0.0) & (got <= 1.0))


def test_lighting_clearcoat_matches_reference():
    rng = seeded_rng("lighting clearcoat")
    count = 2048
    nc = unit_vectors(rng, count, min_z=0.2)
    v = unit_vectors(rng, count, min_z=0.05)
    l = unit_vectors(rng, count)
    base = as_f32(rng.uniform(0, 2, (count, 3)))
    pre = as_f32(rng.uniform(0, 3, (count, 3)))
    light = as_f32(rng.uniform(0, 2, (count, 3)))
    mask, r, occ = (as_f32(rng.uniform(0, 1, count)) for _ in range(3))
    expression = ("pbr_lighting_clearcoat(base, pbr_ClearCoat(mask, r, nc), v, "
                  "pbr_GI(pbr_Light(light, l), pbr_Indirect(vec3(0.0), vec3(0.0))), pre, occ)")
    got = evaluate(expression, INCLUDES, base=vec3(base), mask=mask, r=r, nc=vec3(nc), v=vec3(v),
                   light=vec3(light), l=vec3(l), pre=vec3(pre), occ=occ)
    rc = shading.clamp_perceptual_roughness(r)
    dfg = surface.env_brdf_approx(np.maximum(np.sum(nc * v, axis=-1), shading.MIN_NDOTV), rc)
    ref = clearcoat.lighting_clearcoat(base, mask, r, nc, v, l, light, pre, occ, dfg)
    assert_close("pbr_lighting_clearcoat", got[:, :3], ref, rtol=1e-4, atol=1e-6)


# The white furnace of a coat over a base that reflects all light (albedo 1): what comes
# back is base_weight + mask E_coat, E_coat the coat's directional albedo (float64
# quadrature of the library's GGX and height-correlated Smith V, Schlick F at 0.04 / 1).
def _furnace(layering, mu, rough):
    e = directional_albedo.specular_albedo(mu, rough ** 2, clearcoat.CLEARCOAT_F0, 1.0)
    dfg = np.array(directional_albedo.split_sum_terms(mu, rough ** 2))
    return float(clearcoat.clearcoat_base_weight(1.0, mu, dfg, layering)) + float(np.squeeze(e))


FURNACE_MU = [1e-3, 0.05, 0.2, 0.5, 0.8, 1.0]
FURNACE_ROUGHNESS = [shading.MIN_PERCEPTUAL_ROUGHNESS, 0.25, 0.5, 0.75, 1.0]


def test_default_layering_conserves_energy_at_every_roughness():
    worst = max(_furnace("ALBEDO", mu, r) for mu in FURNACE_MU for r in FURNACE_ROUGHNESS)
    assert worst <= 1.0 + 1e-9, worst  # exact: the base gives up what the coat reflects


def test_fresnel_layering_of_the_specification_is_not_energy_conserving():
    """The measurement behind the default (pbr/shading/clearcoat.glsl's header): the
    specification's 1 - F(NcdotV) takes from the base what a smooth coat reflects, so a
    rough coat darkens it (91 % lost at grazing view, roughness 1) and where E_coat > F
    the pair gains 9e-4, above the renderer's furnace bound."""
    gains = {(mu, r): _furnace("FRESNEL", mu, r) - 1.0 for mu in FURNACE_MU for r in FURNACE_ROUGHNESS}
    assert 5e-4 < max(gains.values()) < 2e-3, gains
    assert gains[1e-3, 1.0] < -0.9, gains
    assert abs(gains[0.5, shading.MIN_PERCEPTUAL_ROUGHNESS]) < 1e-4  # a smooth coat: F and E agree
