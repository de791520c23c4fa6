"""The unity BRDF model (PBR_BRDF_MODEL_UNITY, render.brdf_model "unity"): Unity's BRDF1/2/3
through LightingStandard[Specular] and the renderer, against the float64 transcription of
Unity's source (pbrlab.maths.reference.unity_brdf, written from the .cginc files, not from the GLSL).
"""

import numpy as np
import pytest

from pbrlab import evaluate, vec3
from pbrlab.foundation.errors import PbrlabError
from pbrlab.maths.reference import unity_brdf as U

from unity_inputs import lighting_inputs

UNITY = ["pbr/unity/surface_standard.glsl"]
TIERS = (("HIGH", 1), ("MEDIUM", 2), ("LOW", 3))
N = 100_000
EPS32 = 2.0 ** -24  # float32 unit roundoff

LIGHTING_STANDARD = ("LightingStandard(SurfaceOutputStandard(albedo, normal, vec3(0.0), metallic, smoothness,"
                     " occlusion, 1.0), v, UnityGI(UnityLight(light, l), UnityIndirect(idiff, ispec)))")
LIGHTING_STANDARD_SPECULAR = (
    "LightingStandardSpecular(SurfaceOutputStandardSpecular(albedo, specular, normal, vec3(0.0), smoothness,"
    " occlusion, 1.0), v, UnityGI(UnityLight(light, l), UnityIndirect(idiff, ispec)))")


def unity_defines(quality):
    return {"PBR_QUALITY": f"PBR_QUALITY_{quality}", "PBR_BRDF_MODEL": "PBR_BRDF_MODEL_UNITY"}


def _gpu(x):
    return {k: (vec3(a.astype(np.float32)) if a.ndim == 2 else a.astype(np.float32)) for k, a in x.items()}


def _as_float32(x):
    """The inputs the GPU sees, back in float64 for the reference."""
    return {k: a.astype(np.float32).astype(np.float64) for k, a in x.items()}


def grazing_sensitivity(x):
    """1/nl + 1/nv: a float32 dot product of unit vectors carries an absolute rounding error of
    about EPS32, which is a relative error EPS32 / c of a small cosine c; Unity's lobes are
    products of nl and (BRDF1's visibility) nv, so a grazing cosine passes that on."""
    nl = np.abs(np.sum(x["normal"] * x["l"], -1))
    nv = np.abs(np.sum(x["normal"] * x["v"], -1))
    return 1.0 / np.maximum(nl, EPS32) + 1.0 / np.maximum(nv, EPS32)


def peak_sensitivity(x, tier):
    """|d ln f / d c| of the tier's specular lobe to its peak cosine c, from Unity's formulas:
    a float32 rounding of c (one ulp, EPS32 relative) moves the value by S · EPS32.
      BRDF1: GGXTerm a² / (π (d² + 1e-7)), d = 1 - nh² (1 - a²): S = 4 nh (1 - a²) |d| / (d² + 1e-7)
      BRDF2: a² / (... d² ...), d = nh² (a² - 1) + 1.00001:       S = 4 nh |1 - a²| / d
      BRDF3: (R.L)^(n/4) (inside the texture's range):             S = (n/4) / |R.L|"""
    n, v, l = x["normal"], x["v"], x["l"]
    r = 1.0 - x["smoothness"]
    nh = np.clip(np.sum(n * U.safe_normalize(l + v), -1), 0.0, 1.0)
    if tier == 1:
        a2 = np.maximum(r * r, U.BRDF1_MIN_ROUGHNESS) ** 2
        d = 1.0 - nh * nh * (1.0 - a2)
        return 4.0 * nh * (1.0 - a2) * np.abs(d) / (d * d + U.GGX_EPSILON)
    if tier == 2:
        a2 = (r * r) ** 2
        return 4.0 * nh * np.abs(1.0 - a2) / (nh * nh * (a2 - 1.0) + U.BRDF2_D_OFFSET)
    rl = np.abs(np.sum((v - 2.0 * np.sum(n * v, -1, keepdims=True) * n) * l, -1))
    exponent = U.perceptual_roughness_to_spec_power(r) * 0.25
    unclamped = U.nhx_roughness(rl ** 4, r) < U.NHXROUGHNESS_LUT_RANGE
    return np.where(unclamped, exponent / np.maximum(rl, 1e-30), 0.0)


# The bound (float32 rounding): |gpu - ref| <= K · EPS32 · (1 + S) · (|ref| + 1e-7) per channel,
# S = peak_sensitivity + grazing_sensitivity: how far one float32 rounding of the cosines the
# value hangs on moves it. Away from sharp peaks and the horizon (S < 10) this is ~1e-5
# relative; at the mirror peak of a smooth BRDF2 surface S reaches 4e5 (Unity's
# d = 1.00001 - nh² is 1e-5 there), so one rounding of nh moves the value by 2.4 %, as in
# Unity's own float32 shader. Measured on llvmpipe (N = 1e5; metallic / specular workflow):
# worst K 4.0 / 15.0 (BRDF1), 3.4 / 27.5 (BRDF2), 7.2 / 7.0 (BRDF3); plain relative error
# 8.2e-4, 5.2e-2, 4.0e-4 at worst, 1.6e-5, 1.9e-5, 2.7e-6 where S < 10. K = 64: the measured
# 27.5 with a 2.3x margin for the ~50 rounded operations of a lobe that S does not model.
K = 64
# 1e-7 absolute: black outputs (albedo 0 and no specular) must stay black within 1e-7.
ATOL = 1e-7


def assert_within_float32_rounding(got, want, sensitivity):
    got = np.asarray(got, np.float64)
    assert np.isfinite(got).all()
    bound = K * EPS32 * (1.0 + sensitivity[:, None]) * (np.abs(want) + ATOL)
    excess = np.abs(got - want) / bound
    assert excess.max() <= 1.0, (excess.max(), np.unravel_index(np.argmax(excess), excess.shape))


@pytest.mark.parametrize("quality,tier", TIERS)
def test_lighting_standard_unity_model_matches_unity_transcription(quality, tier):
    x = lighting_inputs(np.random.default_rng(5), N)
    got = evaluate(LIGHTING_STANDARD, UNITY, defines=unity_defines(quality), **_gpu(x))
    f = _as_float32(x)
    want = U.lighting_standard(f["albedo"], f["metallic"], f["smoothness"], f["normal"], f["v"], f["light"],
                               f["l"], f["idiff"], f["ispec"], tier=tier)
    assert_within_float32_rounding(got[:, :3], want, peak_sensitivity(f, tier) + grazing_sensitivity(f))
    assert np.all(got[:, 3] == 1.0)


@pytest.mark.parametrize("quality,tier", TIERS)
def test_lighting_standard_specular_unity_model_with_black_specular(quality, tier):
    """Specular workflow over the full range, a fifth of it with Specular = 0 exactly."""
    rng = np.random.default_rng(6)
    x = lighting_inputs(rng, N)
    specular = rng.uniform(0.0, 1.0, (N, 3))
    specular[: N // 5] = 0.0
    x["specular"] = specular
    del x["metallic"]
    got = evaluate(LIGHTING_STANDARD_SPECULAR, UNITY, defines=unity_defines(quality), **_gpu(x))
    f = _as_float32(x)
    want = U.lighting_standard_specular(f["albedo"], f["specular"], f["smoothness"], f["normal"], f["v"],
                                        f["light"], f["l"], f["idiff"], f["ispec"], tier=tier)
    assert_within_float32_rounding(got[:, :3], want, peak_sensitivity(f, tier) + grazing_sensitivity(f))


def test_black_specular_has_no_direct_highlight_in_either_model():
    """Unity multiplies BRDF1's direct specular by any(specColor); pbrlab's F90 follows F0
    (pbr_f90_from_f0), so F0 = 0 has no Fresnel rise either. Black albedo, no indirect
    light: nothing is left in either model (a grazing highlight of 9.6 before F90 followed F0)."""
    n = 2000
    rng = np.random.default_rng(7)
    x = lighting_inputs(rng, n)
    x.update(albedo=np.zeros((n, 3)), specular=np.zeros((n, 3)), idiff=np.zeros((n, 3)), ispec=np.zeros((n, 3)),
             light=np.ones((n, 3)))
    del x["metallic"]
    unity = evaluate(LIGHTING_STANDARD_SPECULAR, UNITY, defines=unity_defines("HIGH"), **_gpu(x))
    pbrlab = evaluate(LIGHTING_STANDARD_SPECULAR, UNITY, **_gpu(x))
    assert np.all(unity[:, :3] == 0.0)
    assert np.all(pbrlab[:, :3] == 0.0)


def test_ggx_peak_at_smoothness_1_carries_unity_epsilon():
    """GGXTerm at NdotH = 1: a² / (π (a⁴ + 1e-7)), with BRDF1's roughness floor 0.002."""
    got = evaluate("GGXTerm(1.0, r)", ["pbr/unity/brdf_unity.glsl"], r=np.array([0.002, 0.01, 0.1, 1.0], np.float32))
    want = U.ggx_term(1.0, np.array([0.002, 0.01, 0.1, 1.0], np.float64))
    np.testing.assert_allclose(got, want, rtol=4 * EPS32 * 8)
    assert abs(want[0] - 0.002 ** 2 / (np.pi * (0.002 ** 4 + 1e-7))) < 1e-9 * want[0]


def _generic(got, want, a, r):
    # a few float32 roundings: measured worst 3.9e-7 relative (DisneyDiffuse); 16 ulp
    return np.abs(got - want) <= 16 * EPS32 * np.abs(want)


def _ggx(got, want, a, r):
    # the peak's conditioning (peak_sensitivity, BRDF1 form): measured worst 4.2e-5 relative at
    # NdotH 0.9992, roughness 0.0021, i.e. 4.1 ulp-equivalents of (1 + S); bound 16
    a2 = r * r
    d = 1.0 - a * a * (1.0 - a2)
    sensitivity = 4.0 * a * (1.0 - a2) * np.abs(d) / (d * d + U.GGX_EPSILON)
    return np.abs(got - want) <= 16 * EPS32 * (1.0 + sensitivity) * np.abs(want)


def _spec_power(got, want, a, r):
    # n = 2 / m² - 2 cancels near perceptual roughness 1 (n -> 0): the float32 error is absolute,
    # a few ulps of 2 / m²; measured 2.6e-4 relative where n = 5.5e-4; bound 4 ulp of 2/m² + 2
    m2 = np.maximum(U.SPEC_POWER_MIN_M2, (r * r) ** 2)
    return np.abs(got - want) <= 4 * EPS32 * (2.0 / m2 + 2.0)


def _nhx(got, want, a, r):
    # pow(x, y) = exp2(y log2 x), y = n/16 up to 1250: log2 x carries an absolute float32
    # error (~EPS32, also near x = 1 where log2 x -> 0) and so does the product y · log2 x:
    # absolute errors of the exponent, i.e. relative errors of the value of about
    # EPS32 · (1 + y) · (1 + |log2 x|). Measured worst 3.9 ulp-equivalents of that; bound 16,
    # which also holds GLSL's own allowance for log2 near 1 (2^-21 absolute = 8 of these units)
    y = U.perceptual_roughness_to_spec_power(r) * 0.25 / U.NHXROUGHNESS_WARP_EXPONENT
    scale = (1.0 + y) * (1.0 + np.abs(np.log2(np.maximum(a, 1e-38))))
    return np.abs(got - want) <= 16 * EPS32 * scale * np.abs(want) + 1e-30


TERMS = [
    ("SmithJointGGXVisibilityTerm(a, b, r)", lambda a, b, c, r: U.smith_joint_ggx_visibility_term(a, b, r), _generic),
    ("GGXTerm(a, r)", lambda a, b, c, r: U.ggx_term(a, r), _ggx),
    ("DisneyDiffuse(a, b, c, r)", U.disney_diffuse, _generic),
    ("PerceptualRoughnessToSpecPower(r)", lambda a, b, c, r: U.perceptual_roughness_to_spec_power(r), _spec_power),
    ("pbr_unity_NHxRoughness(a, r)", lambda a, b, c, r: U.nhx_roughness(a, r), _nhx),
    ("pbr_unity_glossy_environment_perceptual_roughness(r)",
     lambda a, b, c, r: U.glossy_environment_perceptual_roughness(r), _generic),
]


@pytest.mark.parametrize("expression,reference,within", TERMS, ids=[t[0].split("(")[0] for t in TERMS])
def test_unity_terms_match_transcription(expression, reference, within):
    rng = np.random.default_rng(8)
    a, b, c, r = (rng.uniform(0.0, 1.0, 50_000).astype(np.float32) for _ in range(4))
    a[:4], r[:4] = [0.0, 1.0, 1.0, 0.5], [0.0, 0.0, 1.0, 1.0]
    got = evaluate(expression, ["pbr/unity/brdf_unity.glsl"], a=a, b=b, c=c, r=r).astype(np.float64)
    a64, b64, c64, r64 = (t.astype(np.float64) for t in (a, b, c, r))
    want = reference(a64, b64, c64, r64)
    ok = within(got, want, a64, r64)
    assert ok.all(), (expression, got[~ok][:3], want[~ok][:3])


def test_environment_lod_follows_unity_glossy_environment_remap():
    r = np.linspace(0.0, 1.0, 101, dtype=np.float32)
    got = evaluate("pbr_unity_environment_lod(r, 7.0)", UNITY, r=r, defines=unity_defines("HIGH"))
    np.testing.assert_allclose(got, U.glossy_environment_mip(r.astype(np.float64)), rtol=4 * EPS32, atol=4 * EPS32)
    occlusion = np.linspace(0.0, 1.0, 11, dtype=np.float32)
    assert np.array_equal(evaluate("pbr_unity_gi_occlusion(o)", UNITY, o=occlusion, defines=unity_defines("LOW")),
                          occlusion)
    assert np.all(evaluate("pbr_unity_gi_occlusion(o)", UNITY, o=occlusion) == 1.0)


def test_nhxroughness_baked_into_a_texture_stays_close_to_the_analytic_function():
    """The difference between evaluating the analytic NHxRoughness and sampling it from a
    baked 64x64 table with bilinear filtering (what a texture lookup does; Unity's own
    resolution is not public), in units of the returned specular value (0..16): docs/unity.md figure."""
    size = 64
    grid = (np.arange(size) + 0.5) / size  # texel centres
    table = U.nhx_roughness(grid[None, :], grid[:, None])  # rows: roughness, columns: rlPow4
    rng = np.random.default_rng(9)
    x, y = rng.uniform(0, 1, 200_000), rng.uniform(0, 1, 200_000)
    fx, fy = np.clip(x * size - 0.5, 0, size - 1), np.clip(y * size - 0.5, 0, size - 1)
    i0, j0 = np.minimum(fx.astype(int), size - 2), np.minimum(fy.astype(int), size - 2)
    tx, ty = fx - i0, fy - j0
    baked = ((table[j0, i0] * (1 - tx) + table[j0, i0 + 1] * tx) * (1 - ty)
             + (table[j0 + 1, i0] * (1 - tx) + table[j0 + 1, i0 + 1] * tx) * ty)
    diff = np.abs(baked - U.nhx_roughness(x, y))
    # docs/unity.md, "Unity BRDF model": measured median 1.6e-5, p99 0.017, mean 0.014; the largest
    # differences (up to the full range 16) are the sharpest lobes, narrower than a texel, so
    # only the median, p99 and mean are bounded (3x-6x the measured values).
    assert np.median(diff) < 1e-4 and np.quantile(diff, 0.99) < 0.05 and diff.mean() < 0.05


def test_unknown_brdf_model_is_a_compile_error_naming_the_selector():
    with pytest.raises(PbrlabError, match="PBR_BRDF_MODEL"):
        evaluate("pbr_unity_gi_occlusion(x)", UNITY, x=np.zeros(1, np.float32), defines={"PBR_BRDF_MODEL": "7"})
    with pytest.raises(PbrlabError, match="PBR_BRDF_MODEL"):  # an undefined name reads as 0
        evaluate("pbr_unity_gi_occlusion(x)", UNITY, x=np.zeros(1, np.float32),
                 defines={"PBR_BRDF_MODEL": "PBR_BRDF_MODEL_UNREAL"})


@pytest.mark.parametrize("macro,value", [
    ("PBR_UNITY_GGX_EPSILON", U.GGX_EPSILON), ("PBR_UNITY_SMITH_JOINT_EPSILON", U.SMITH_JOINT_EPSILON),
    ("PBR_UNITY_BRDF1_MIN_ROUGHNESS", U.BRDF1_MIN_ROUGHNESS),
    ("PBR_UNITY_SAFE_NORMALIZE_MIN_LENGTH2", U.SAFE_NORMALIZE_MIN_LENGTH2),
    ("PBR_UNITY_BRDF2_D_OFFSET", U.BRDF2_D_OFFSET), ("PBR_UNITY_BRDF2_MIN_LH2", U.BRDF2_MIN_LH2),
    ("PBR_UNITY_SPEC_POWER_MIN_M2", U.SPEC_POWER_MIN_M2), ("PBR_UNITY_SPEC_POWER_MIN", U.SPEC_POWER_MIN),
    ("PBR_UNITY_NHXROUGHNESS_LUT_RANGE", U.NHXROUGHNESS_LUT_RANGE),
    ("PBR_UNITY_NHXROUGHNESS_WARP_EXPONENT", U.NHXROUGHNESS_WARP_EXPONENT),
    ("PBR_UNITY_TWO_PI_SQUARED", 2.0 * np.pi ** 2),
    ("unity_ColorSpaceDielectricSpec.r", U.DIELECTRIC_SPEC),
])
def test_unity_constants_equal_the_transcription(macro, value):
    got = evaluate(macro, UNITY, x=np.zeros(1, np.float32))
    assert got[0] == np.float32(value), macro


def test_tiers_select_unity_brdfs_through_the_tier_block():
    for quality, tier in TIERS:
        got = evaluate("float(PBR_UNITY_BRDF)", UNITY, x=np.zeros(1, np.float32),
                       defines={"PBR_QUALITY": f"PBR_QUALITY_{quality}"})
        assert got[0] == U.TIER_BRDF[quality] == tier


@pytest.mark.parametrize("shaded_with", ["PBRLAB", "neighbour tier"])
def test_the_bound_rejects_a_different_brdf(shaded_with):
    """The comparison can fail: the pbrlab model, or Unity's BRDF of another tier, against the
    BRDF1 transcription is far outside the float32 bound."""
    x = lighting_inputs(np.random.default_rng(5), 20_000)
    defines = ({"PBR_BRDF_MODEL": "PBR_BRDF_MODEL_PBRLAB"} if shaded_with == "PBRLAB"
               else dict(unity_defines("HIGH"), PBR_UNITY_BRDF="PBR_UNITY_BRDF_2"))
    got = evaluate(LIGHTING_STANDARD, UNITY, defines=defines, **_gpu(x))
    f = _as_float32(x)
    want = U.lighting_standard(f["albedo"], f["metallic"], f["smoothness"], f["normal"], f["v"], f["light"],
                               f["l"], f["idiff"], f["ispec"], tier=1)
    with pytest.raises(AssertionError):
        assert_within_float32_rounding(got[:, :3], want, peak_sensitivity(f, 1) + grazing_sensitivity(f))
