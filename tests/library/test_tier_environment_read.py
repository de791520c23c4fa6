"""What each quality tier reads of the environment (issue 35, the whole lit pixel): the tier
block of pbr/shading/dispatch.glsl sets PBR_ENERGY_COMPENSATION, PBR_IBL_DOMINANT_DIRECTION,
PBR_IBL_HORIZON_OCCLUSION and PBR_SPECULAR_OCCLUSION, the float64 twin
(pbrlab.maths.reference.shading QUALITY_ENERGY_COMPENSATION, QUALITY_SPECULAR_OCCLUSION) says the
same, an explicit value wins over the tier, and pbr_specular_occlusion computes the chosen form
against its float64 twin (reference/surface.py specular_occlusion)."""

import numpy as np
import pytest

from pbrlab import evaluate
from pbrlab.maths.reference import shading as ref_shading
from pbrlab.maths.reference import surface as ref_surface

TIERS = ("HIGH", "MEDIUM", "LOW")
SPECULAR_OCCLUSION_VALUES = {"LAGARDE": 1, "AMBIENT": 2}  # dispatch.glsl's PBR_SPECULAR_OCCLUSION_*
MACROS = ("float(PBR_ENERGY_COMPENSATION), float(PBR_IBL_DOMINANT_DIRECTION), "
          "float(PBR_IBL_HORIZON_OCCLUSION), float(PBR_SPECULAR_OCCLUSION)) + x * 0.0")


def _macros(language, **defines):
    vector = "vec4(" if language == "glsl" else "float4("
    got = evaluate(vector + MACROS, [f"pbr/pbr.{language}"], language=language, x=np.zeros(1, np.float32),
                   defines=defines)
    return tuple(int(round(float(value))) for value in np.asarray(got).reshape(-1)[:4])


@pytest.mark.parametrize("language", ["glsl", "hlsl"])
@pytest.mark.parametrize("tier", TIERS)
def test_each_tier_reads_the_environment_as_its_float64_twin_says(tier, language):
    compensation, dominant, horizon, occlusion = _macros(language, PBR_QUALITY=f"PBR_QUALITY_{tier}")
    assert compensation == int(ref_shading.QUALITY_ENERGY_COMPENSATION[tier])
    assert occlusion == SPECULAR_OCCLUSION_VALUES[ref_shading.QUALITY_SPECULAR_OCCLUSION[tier]]
    # LOW drops the two corrections of the read; HIGH and MEDIUM keep them
    assert (dominant, horizon) == ((0, 0) if tier == "LOW" else (1, 1))


def test_an_explicit_value_wins_over_the_tier():
    # the control: the values above come from the tier block, not from fixed defaults
    assert _macros("glsl", PBR_QUALITY="PBR_QUALITY_LOW", PBR_ENERGY_COMPENSATION="1",
                   PBR_IBL_DOMINANT_DIRECTION="1", PBR_IBL_HORIZON_OCCLUSION="1",
                   PBR_SPECULAR_OCCLUSION="PBR_SPECULAR_OCCLUSION_LAGARDE") == (1, 1, 1, 1)
    assert _macros("glsl", PBR_QUALITY="PBR_QUALITY_HIGH", PBR_ENERGY_COMPENSATION="0",
                   PBR_SPECULAR_OCCLUSION="PBR_SPECULAR_OCCLUSION_AMBIENT")[::3] == (0, 2)


@pytest.mark.parametrize("tier", TIERS)
def test_specular_occlusion_of_each_tier_matches_its_float64_twin(tier):
    # Float32 against float64 over NdotV, AO in [0, 1], alpha in [0.089², 1]: Lagarde's
    # pow(NdotV + ao, e) - 1 + ao rounds each of its few operations (pow as exp2(e log2 x):
    # a few ulp relative of a value <= 2^0.5, then a subtraction of 1), so 1e-5 absolute is
    # ~100 ulp of the pow's magnitude; the LOW form is the AO itself, exact. Measured on
    # llvmpipe: 2.6e-7 (HIGH, MEDIUM), 0 (LOW).
    rng = np.random.default_rng(35)
    n = 4096
    NdotV, ao = rng.uniform(0, 1, n).astype(np.float32), rng.uniform(0, 1, n).astype(np.float32)
    alpha = rng.uniform(0.089 ** 2, 1, n).astype(np.float32)
    got = np.asarray(evaluate("vec4(pbr_specular_occlusion(x, y, z))", ["pbr/pbr.glsl"], x=NdotV, y=ao, z=alpha,
                              defines={"PBR_QUALITY": f"PBR_QUALITY_{tier}"}))[..., 0].reshape(-1)
    want = ref_surface.specular_occlusion(NdotV.astype(np.float64), ao.astype(np.float64),
                                          alpha.astype(np.float64), tier)
    assert np.abs(got - want).max() <= 1e-5
    # the control: against the other form the same values are far outside the 1e-5 bound, so
    # the comparison saw the tier's choice (the forms differ by up to ~0.5 where AO is small)
    other = "HIGH" if tier == "LOW" else "LOW"
    assert np.abs(got - ref_surface.specular_occlusion(NdotV.astype(np.float64), ao.astype(np.float64),
                                                       alpha.astype(np.float64), other)).max() > 0.1
