"""Half precision (issue 5): the numpy float16 model and the in-shader emulation
(unpackHalf2x16(packHalf2x16(x)) after every operation) agree; which formulations stay
finite and accurate in half; the LOW tier is half-safe. Figures: glsl/README.md, "Half
precision". Errors are relative to the float64 value of the same formulation on the same
half-rounded inputs (the formulation's own half-precision error, not its modelling error)."""

import math

import numpy as np
import pytest

from pbrlab import evaluate, vec3
from pbrlab.checking.hardcases import half
from pbrlab.maths.reference import shading


def test_in_shader_rounding_is_numpy_float16_bit_for_bit():
    """H(x) on the GPU == numpy float16, denormals, overflow to Inf, NaN and ties included."""
    rng = np.random.default_rng(1)
    x = np.concatenate([rng.normal(0, 1, 100_000) * 10.0 ** rng.uniform(-9, 6, 100_000),
                        [0.0, -0.0, 2 ** -24, 2 ** -25, 3 * 2 ** -26, 65504, 65519.99, 65520, 1 + 2 ** -11,
                         np.inf, -np.inf, np.nan]]).astype(np.float32)
    got = evaluate("H(x)", ("pbr/common/math.glsl",), defines=half.HALF_ROUND,
                   extensions=half.HALF_EXTENSIONS, x=x)
    with np.errstate(over="ignore"):
        expected = x.astype(np.float16).astype(np.float32)
    np.testing.assert_array_equal(got.view(np.uint32)[~np.isnan(expected)],
                                  expected.view(np.uint32)[~np.isnan(expected)])
    assert np.isnan(got[np.isnan(expected)]).all()


FORMULATIONS = {
    "D_GGX textbook": (half.d_ggx_textbook, "peak", {"alpha": 0.089 ** 2}),
    "D_GGX factored": (half.d_ggx_factored, "peak", {"alpha": 0.089 ** 2}),
    "D_GGX cross": (half.d_ggx_cross, "peak", {"alpha": 0.089 ** 2}),
    "Blinn-Phong pow 8192": (half.blinn_phong_pow, "lobe", {"s": 8192.0}),
    "Blinn-Phong cross 8192": (half.blinn_phong_cross, "lobe", {"s": 8192.0}),
    "Reinhard": (half.tonemap_reinhard, "hdr", {}),
    "Hable": (half.tonemap_hable, "hdr", {}),
    "ACES Narkowicz": (half.tonemap_narkowicz, "hdr", {}),
    "LOW-tier BRDF": (half.brdf_low, "shading", {}),
}


def inputs_for(kind, count=100_000):
    rng = np.random.default_rng(11)
    if kind == "peak":    # GGX at perceptual roughness 0.089, NdotH within 1e-4 of 1
        return half.near_peak_geometry(rng, count, 1e-4)
    if kind == "lobe":    # Blinn-Phong s = 8192: the lobe spans 1 - NdotH < ~1e-3
        return half.near_peak_geometry(rng, count, 2e-3)
    if kind == "hdr":     # 1e-4 .. 65504, above it, and +Inf
        return {"x": np.concatenate([np.geomspace(1e-4, 65504.0, count), [70000.0, 1e30, np.inf]])}
    return half.shading_configurations(rng, count)


@pytest.fixture(scope="module")
def runs():
    cache = {}

    def get(name):
        if name not in cache:
            formulation, kind, fixed = FORMULATIONS[name]
            cache[name] = half.run_three_ways(formulation, inputs_for(kind), **fixed)
        return cache[name]
    return get


@pytest.mark.parametrize("name", FORMULATIONS)
def test_numpy_half_model_and_shader_emulation_agree(name, runs):
    """Bit for bit: +, -, *, / and sqrt are correctly rounded in both (float32 then one
    rounding to half); the pow/exp2 forms happen to agree too on llvmpipe (allowed: 1 ulp)."""
    _, model, gpu = runs(name)
    same = (model == gpu) | (np.isnan(model) & np.isnan(gpu))
    if "Blinn" in name:
        same |= np.abs(model - gpu) <= 2.0 ** -10 * np.abs(model)
    assert same.all(), (name, int((~same).sum()))


def test_GGX_at_roughness_0089_near_the_peak_needs_the_cross_product_in_half(runs):
    """1 - NdotH <= 1e-4 at alpha = 0.089²: the textbook form overflows (most values Inf or
    NaN: 1 + NdotH²(alpha² - 1) rounds to 0), the (1 - NdotH)(1 + NdotH) form is finite but
    quantised (NdotH's half step 4.9e-4 is wider than the lobe: errors of 10^4 %), the
    |n x h|² form keeps 9.2 % (measured; bound 12 %: half-rounded cross products)."""
    exact, textbook, _ = runs("D_GGX textbook")
    assert np.mean(~np.isfinite(textbook)) > 0.5
    exact, factored, _ = runs("D_GGX factored")
    assert np.isfinite(factored).all() and half.relative_error(factored, exact, 0.0) > 10.0
    exact, cross, _ = runs("D_GGX cross")
    assert np.isfinite(cross).all() and half.relative_error(cross, exact, 0.0) <= 0.12


def test_blinn_phong_power_8192_in_half_needs_the_cross_product_form(runs):
    """pow(NdotH, 8192) with NdotH in half steps of 4.9e-4 loses the lobe (error ~100 % of
    the peak); exp2 of -(s/2)(s2 + s2²/2)/ln2 from |n x h|² keeps it within 2 % of the peak
    (measured 1.7 %)."""
    exact, pow_form, _ = runs("Blinn-Phong pow 8192")
    assert np.abs(pow_form - exact).max() / exact.max() > 0.5
    exact, cross, _ = runs("Blinn-Phong cross 8192")
    assert np.abs(cross - exact).max() / exact.max() <= 0.02


@pytest.mark.parametrize("name, max_error", [("Reinhard", 1e-3), ("Hable", 3e-3), ("ACES Narkowicz", 3e-3)])
def test_tonemappers_finite_in_half_for_hdr_above_65504(name, max_error, runs):
    """Inputs up to 65504, 70000, 1e30 and +Inf (Inf after the half cast): finite and in
    [0, 1]; absolute error (display-linear) within max_error (measured 7.0e-4, 2.5e-3,
    2.1e-3: a few half ulps of values near 1). Hable and Narkowicz are half-safe only
    thanks to their input caps (W = 11.2, 16): uncapped Narkowicz overflows."""
    exact, model, _ = runs(name)
    assert np.isfinite(model).all() and (model >= 0).all() and (model <= 1).all()
    assert np.abs(model - exact).max() <= max_error
    uncapped = half.run_three_ways(lambda m, x: half.tonemap_narkowicz(m, x, cap=half.HALF_MAX),
                                   inputs_for("hdr", 1000))[1]
    assert not np.isfinite(uncapped).all()


def test_LOW_tier_formulation_is_the_librarys():
    """The half study's formulation, run in float64 on unit vectors with the library's
    selection (no threshold on |l + v|², min_half = 0) and no D · V cap (half's range, which
    float32 GLSL does not apply), where its floor on the lambda sum is idle, is pbr_brdf_standard at the LOW tier's guards with Hammon's V and
    Schlick's F (the lobe that runs in half's range) as modelled by the reference (rtol 1e-9:
    float64 rounding)."""
    cfg = inputs_for("shading", 20_000)
    vec = lambda s: np.stack([cfg[f"{s}{i}"] for i in range(3)], -1)  # noqa: E731
    split = lambda s: [vec(s)[:, i] for i in range(3)]  # noqa: E731
    m = half.Float64()
    with np.errstate(divide="ignore", invalid="ignore"):  # l = -v: a NaN lobe, not selected
        ours = half.brdf_low(m, split("n"), split("v"), split("l"), cfg["diffuse"], cfg["specular"], cfg["roughness"],
                             min_half=0.0, lobe_cap=None)
    ref = shading.brdf_standard(vec("n"), vec("v"), vec("l"), cfg["diffuse"][:, None] * np.ones(3),
                                cfg["specular"][:, None] * np.ones(3), cfg["roughness"], quality="LOW",
                                specular_v="SMITH_GGX_CORRELATED_FAST", specular_f="SCHLICK")[:, 0]
    # where the study's floor on Hammon's lambda sum (half's smallest normal) is idle
    NdotL = (vec("n") * vec("l")).sum(-1)
    NdotV = np.clip((vec("n") * vec("v")).sum(-1), half.MIN_NDOTV, 1.0)
    alpha = np.clip(cfg["roughness"], half.LOW_MIN_PERCEPTUAL_ROUGHNESS, 1.0) ** 2
    idle = 2 * NdotL * NdotV * (1 - alpha) + (NdotL + NdotV) * alpha >= half.HALF_MIN_NORMAL
    assert idle.mean() > 0.99
    np.testing.assert_allclose(ours[idle], ref[idle], rtol=1e-9, atol=1e-12)


def test_LOW_tier_is_half_safe_and_HIGH_is_not(runs):
    """The LOW formulation in half: every value finite, lit result (BRDF · NdotL) within
    25 % relative where it is above 1e-2 (measured for the fused lobe of
    pbr_DV_GGX_SmithCorrelatedFast_half: median 4.7e-4, 99th 5.4e-3, 99.9th 1.6e-2, worst
    0.160, at l within a degree of -v at grazing, where half's rounding of l + v moves the
    half vector by ~2 %; the unfused form measured 0.107 there); the HIGH formulation (roughness 0.045,
    scalar 1 - NdotH², no lobe cap, threshold 1e-12) run in half produces Inf/NaN."""
    exact, model, _ = runs("LOW-tier BRDF")
    assert np.isfinite(model).all()
    cfg = inputs_for("shading")
    NdotL = np.clip(sum(np.asarray(cfg[f"n{i}"], np.float16).astype(np.float64)
                        * np.asarray(cfg[f"l{i}"], np.float16).astype(np.float64) for i in range(3)), 0, 1)
    lit_exact, lit_half = exact * NdotL, model * NdotL
    keep = lit_exact > 1e-2
    assert (np.abs(lit_half - lit_exact)[keep] / lit_exact[keep]).max() <= 0.25
    high = half.run_three_ways(lambda m, **a: half.brdf_low(
        m, **a, min_roughness=0.045, d_form=half.d_ggx_factored, lobe_cap=None, min_half=1e-12), cfg)[1]
    assert not np.isfinite(high).all()
