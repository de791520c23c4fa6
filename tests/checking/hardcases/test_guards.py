"""The guards of glsl/pbr/common/guards.glsl and their users: each changes nothing in the
normal domain (bit-identical or within the stated accuracy), is continuous with the float64
limit at its edge, and the cancellation-free GGX form is as accurate as its comment says.

Tolerances are relative, in the unit of the function's value, and stated per test."""

import math

import numpy as np
import pytest

from pbrlab import evaluate, vec3
from pbrlab.maths.reference import brdf, color, guards, shading, tonemap

F32 = np.float32
BELOW = lambda x: float(np.nextafter(F32(x), F32(0)))  # noqa: E731  (one float32 step below)


@pytest.mark.parametrize("term", ["V_SmithGGXCorrelated", "V_SmithGGXCorrelatedFast", "V_SmithGGX"])
def test_V_cosine_floor_is_continuous_and_exact_below(term):
    """Below PBR_MIN_NDOTV the V terms return their value at the floor, bit for bit; at the
    floor that value is the float64 formula's (rtol 1e-5: a few float32 roundings)."""
    c = np.array([0.0, 1e-45, 1e-9, BELOW(1e-4), 1e-4], F32)
    got = evaluate(f"pbr_{term}(c, c, 0.3)", c=c)
    assert (got[:-1] == got[-1]).all(), got
    np.testing.assert_allclose(got[-1], getattr(brdf, term)(F32(1e-4), F32(1e-4), F32(0.3)), rtol=1e-5)


def test_V_SchlickGGX_cosine_floor_is_continuous_and_exact_below():
    c = np.array([0.0, 1e-9, BELOW(1e-4), 1e-4], F32)
    got = evaluate("pbr_V_SchlickGGX(c, 0.5, 0.1)", c=c)
    assert (got[:-1] == got[-1]).all()
    np.testing.assert_allclose(got[-1], brdf.V_SchlickGGX(F32(1e-4), 0.5, F32(0.1)), rtol=1e-5)


def test_D_GGX_alpha_floor_is_continuous_with_the_float64_peak():
    """alpha below PBR_MIN_ALPHA gives D at the floor, exactly; at the floor D(1) = 1/(π alpha²)
    (rtol 1e-5)."""
    a = np.array([0.0, 1e-45, 1e-20, BELOW(1e-7), 1e-7], F32)
    got = evaluate("pbr_D_GGX(1.0, a)", a=a)
    assert (got[:-1] == got[-1]).all() and np.isfinite(got).all()
    np.testing.assert_allclose(got[-1], 1.0 / (math.pi * float(F32(1e-7)) ** 2), rtol=1e-5)


def test_D_GGX_cross_product_form_is_accurate_at_the_sharpest_lobe():
    """The point of pbr_D_GGX(n, h, alpha): 1e6 random unit n, h within 3 alpha of n at the
    minimum roughness (alpha = 0.045²). Against float64 on the same float32 vectors: the
    vec3 form within 5e-5 relative (measured 4.0e-5), the scalar form from dot(n, h) off by
    more than 5 % (measured 14 %: float32 n·h cancels in 1 - NdotH²)."""
    rng = np.random.default_rng(7)
    count, alpha = 1_000_000, F32(0.045 ** 2)
    n = rng.normal(size=(count, 3)); n /= np.linalg.norm(n, axis=-1, keepdims=True)
    t = rng.normal(size=(count, 3)); t -= np.sum(t * n, -1, keepdims=True) * n
    t /= np.linalg.norm(t, axis=-1, keepdims=True)
    theta = float(alpha) * rng.uniform(0.0, 3.0, count)
    h = n * np.cos(theta)[:, None] + t * np.sin(theta)[:, None]
    n32, h32 = n.astype(F32), h.astype(F32)
    n64 = n32 / np.linalg.norm(n32.astype(np.float64), axis=-1, keepdims=True)
    h64 = h32 / np.linalg.norm(h32.astype(np.float64), axis=-1, keepdims=True)
    ref = brdf.D_GGX(np.sum(n64 * h64, -1), float(alpha))
    vector = evaluate("pbr_D_GGX(n, h, a)", n=vec3(n32), h=vec3(h32), a=alpha)
    scalar = evaluate("pbr_D_GGX(dot(n, h), a)", n=vec3(n32), h=vec3(h32), a=alpha)
    assert np.abs(vector / ref - 1.0).max() <= 5e-5
    assert np.abs(scalar / ref - 1.0).max() > 0.05


def test_brdf_standard_uses_the_cross_product_form():
    """Near-mirror configurations through pbr_brdf_standard (F = 1, no diffuse) at the
    minimum roughness: within 3e-4 relative of float64 on the same float32 vectors
    (measured 1.0e-4: D's 4e-5 plus h = normalize(l + v) rounded to ~1e-7 rad, times
    |d ln D / dθ| <= 12/alpha ≈ 6e3 near the peak). The scalar 1 - NdotH² form fails this
    by three orders of magnitude (checked by swapping it into standard.glsl: 0.24)."""
    rng = np.random.default_rng(8)
    count = 200_000
    n = rng.normal(size=(count, 3)); n /= np.linalg.norm(n, axis=-1, keepdims=True)
    l = rng.normal(size=(count, 3)); l /= np.linalg.norm(l, axis=-1, keepdims=True)
    l[np.sum(l * n, -1) < 0.3] = n[np.sum(l * n, -1) < 0.3]
    v = 2.0 * np.sum(l * n, -1, keepdims=True) * n - l + rng.normal(0, 2e-3, (count, 3))
    v /= np.linalg.norm(v, axis=-1, keepdims=True)
    n, v, l = (x.astype(F32) for x in (n, v, l))
    defines = shading.glsl_defines(specular_f="NONE")
    got = evaluate("pbr_brdf_standard(n, v, l, vec3(0.0), vec3(1.0), 0.0)", defines=defines,
                   n=vec3(n), v=vec3(v), l=vec3(l))[:, 0]
    nn, vv, ll = (x / np.linalg.norm(x.astype(np.float64), axis=-1, keepdims=True) for x in (n, v, l))
    ref = shading.brdf_standard(nn, vv, ll, np.zeros(3), np.ones(3), 0.0, specular_f="NONE")[:, 0]
    ok = ref > 1.0  # the lobe, not its far tail
    assert np.abs(got[ok] / ref[ok] - 1.0).max() <= 3e-4


def test_roughness_clamp_is_continuous_at_the_tier_minimum():
    """Just above the tier's minimum roughness the model moves by less than 1e-3 relative
    per float32 step of roughness (D's sensitivity), and at or below it is exactly equal."""
    for quality, floor in (("HIGH", shading.MIN_PERCEPTUAL_ROUGHNESS), ("LOW", shading.MIN_PERCEPTUAL_ROUGHNESS_MEDIUMP)):
        r = np.array([-1.0, 0.0, floor, float(np.nextafter(F32(floor), F32(1)))], F32)
        got = evaluate("pbr_brdf_standard(vec3(0, 0, 1), vec3(-0.6, 0, 0.8), vec3(0.6, 0, 0.8), vec3(0.5), vec3(0.04), r)",
                       defines=shading.glsl_defines(quality=quality), r=r)
        assert (got[0] == got[2]).all() and (got[1] == got[2]).all()
        np.testing.assert_allclose(got[3], got[2], rtol=1e-3)


def test_tonemappers_at_infinity_equal_their_float64_value_at_65504():
    """+Inf is treated as 65504: each tonemapper's output there equals the float64 curve at
    65504, which is its limit at infinity within 2e-5 (display-linear units)."""
    for name in ("reinhard", "hable", "aces_fitted", "aces_narkowicz", "khronos_neutral"):
        got = evaluate(f"pbr_tonemap_{name}(vec3(x))", x=np.array([np.inf, 65504.0], F32))
        assert (got[0] == got[1]).all(), name
        limit = np.clip(getattr(tonemap, f"tonemap_{name}")(np.full(3, 65504.0)), 0, 1)
        np.testing.assert_allclose(got[0], limit, atol=2e-5, err_msg=name)


def test_srgb_encode_of_infinity_is_the_encode_of_one():
    got = evaluate("pbr_linear_to_srgb(vec3(x))", x=np.array([np.inf, 1.0, 1e30], F32))
    assert (got == got[1]).all()
    np.testing.assert_allclose(got[1], color.linear_to_srgb(1.0), atol=2e-7)


def test_safe_normalize_matches_float64_normalize_over_every_scale():
    """1e-30 .. 1e37 (where dot(v, v) under- or overflows in normalize(); smaller scales give
    denormal components, which the GPU flushes on input): within 4 float32
    ulps of the float64 unit vector, and exactly 0 for the zero vector."""
    rng = np.random.default_rng(3)
    d = rng.normal(size=(10_000, 3)) * (10.0 ** rng.uniform(-30, 37, 10_000))[:, None]
    d = d.astype(F32)
    got = evaluate("pbr_safe_normalize(d)", d=vec3(d))
    np.testing.assert_allclose(got, guards.safe_normalize(d.astype(np.float64)), atol=4 * 2.0 ** -24)
    assert (evaluate("pbr_safe_normalize(vec3(0.0))", x=0.0) == 0.0).all()


# pbr_safe_normalize before it was made branch-free (the zero vector was an early return; now
# it is selected at the end, so a program inlining it more than once can share one evaluation:
# benchmarks/whole_program_cost.py). Kept here to show the change is image-neutral.
_BRANCHING_SAFE_NORMALIZE = """
#include "pbr/common/guards.glsl"
vec3 branching_safe_normalize(vec3 v) {
    float m = pbr_max3(abs(v));
    if (!(m >= PBR_FLT_MIN)) return vec3(0.0);
    float k = m > PBR_SAFE_NORMALIZE_HUGE ? 0.0625 : 1.0;
    vec3 s = (v * k) / (m * k);
    return s * inversesqrt(dot(s, s));
}
"""


def test_safe_normalize_equals_its_branching_form_bit_for_bit(tmp_path):
    """Every scale of test_safe_normalize_matches_float64_normalize_over_every_scale plus the
    zero vector, denormal, infinite and NaN components: the same bits, no tolerance."""
    (tmp_path / "branching.glsl").write_text(_BRANCHING_SAFE_NORMALIZE)
    rng = np.random.default_rng(5)
    d = rng.normal(size=(10_000, 3)) * (10.0 ** rng.uniform(-45, 38, 10_000))[:, None]
    edges = [[0, 0, 0], [-0.0, 0, 0], [1e-40, 0, 0], [1e-39, -1e-39, 0], [np.inf, 1, 0], [np.nan, 1, 0],
             [3e38, 3e38, -3e38], [1, 0, 0]]
    d = np.concatenate([d, np.array(edges)]).astype(F32)
    new = evaluate("pbr_safe_normalize(d)", ("pbr/common/guards.glsl",), d=vec3(d))
    old = evaluate("branching_safe_normalize(d)", ("branching.glsl",), include_dirs=(str(tmp_path),), d=vec3(d))
    np.testing.assert_array_equal(new, old)
    # control: the comparison sees a changed zero case
    (tmp_path / "changed.glsl").write_text(_BRANCHING_SAFE_NORMALIZE.replace("return vec3(0.0);", "return vec3(1.0);"))
    changed = evaluate("branching_safe_normalize(d)", ("changed.glsl",), include_dirs=(str(tmp_path),),
                       d=vec3(np.zeros((1, 3), F32)))
    assert not np.array_equal(changed, evaluate("pbr_safe_normalize(d)", ("pbr/common/guards.glsl",),
                                                d=vec3(np.zeros((1, 3), F32))))

def test_Kelemen_VdotH_floor_is_the_shading_models_smallest_VdotH():
    got = evaluate("pbr_V_Kelemen(x)", x=np.array([0.0, 1e-9, guards.MIN_VDOTH], F32))
    assert (got == got[-1]).all()
    assert guards.MIN_VDOTH == pytest.approx(0.5 * math.sqrt(guards.MIN_HALF_VECTOR_LENGTH_SQUARED))
