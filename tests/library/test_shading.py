"""The shading model and punctual lighting (glsl/pbr/shading/, glsl/pbr/lighting/) against
harness/pbrlab/maths/reference/shading.py, for the default variants and every selector value, plus
the lighting convention and the documented edges (no NaN anywhere).

Tolerance of the assembled model (relative, per colour channel; units of radiance): the
GPU forms NdotL, NdotV, NdotH from float32 unit vectors, so each carries an absolute error of
a few float32 ulps (δ = 8·2^-24 allowed). That is harmless except where the result is
steep in a cosine: ∝ NdotL (relative δ/NdotL), V and Fd in NdotV (≤ δ/NdotV), and the
distribution D at a sharp peak, |d ln D / d NdotH| = 4 NdotH (1 - alpha²) / (NdotH²(alpha² - 1) + 1)
for GGX (up to 4/alpha² ≈ 1e6 at the smallest roughness: a near-mirror lobe is
ill-conditioned in float32 whatever the formula). The allowed error is
1e-5·|ref| + δ·(1/NdotL + 1/NdotV)·|ref| + δ·κ_D·|specular ref|.
"""

import numpy as np
import pytest

from library_helpers import (seeded_rng, F32_EPS, RTOL_WELL_CONDITIONED, as_f32, assert_close, evaluate,
                             unit_vectors, vec3)
from pbrlab.foundation.errors import ShaderCompileError
from pbrlab.maths.reference import constants, shading

SHADE = "pbr_shade_punctual(n, v, l, radiance, diffuseColor, f0, roughness)"
COSINE_ERROR = 8 * F32_EPS  # δ above


def kappa_D(NdotH, alpha, variant):
    """|d ln D / d NdotH| of each distribution (float64), see the module docstring."""
    c, a2 = np.clip(NdotH, 1e-6, 1.0), alpha ** 2
    if variant == "GGX":
        return 4.0 * c * (1.0 - a2) / (c * c * (a2 - 1.0) + 1.0)
    if variant == "BECKMANN":
        return np.abs(2.0 / (a2 * c ** 3) - 4.0 / c)
    if variant == "BLINN_PHONG":
        return (2.0 / a2 - 2.0) / c
    raise ValueError(variant)


@pytest.fixture(scope="module")
def scene():
    """100k random shading configurations: arbitrary unit normals (not axis-aligned), v and
    l mostly above the surface, 5 % of each below it, random colours and roughness."""
    rng = seeded_rng("scene")
    count = 100_000
    n = unit_vectors(rng, count)
    v = unit_vectors(rng, count)
    l = unit_vectors(rng, count)
    # reflect v, l into n's hemisphere for 95 % of the samples
    for d in (v, l):
        flip = (np.sum(d * n, axis=-1) < 0) & (rng.random(count) < 0.95)
        d[flip] -= 2.0 * np.sum(d[flip] * n[flip], axis=-1, keepdims=True) * n[flip]
    return dict(n=as_f32(n), v=as_f32(v), l=as_f32(l),
                radiance=as_f32(rng.uniform(0.0, 4.0, (count, 3))),
                diffuseColor=as_f32(rng.uniform(0.0, 1.0, (count, 3))),
                f0=as_f32(rng.uniform(0.0, 1.0, (count, 3))),
                roughness=as_f32(rng.uniform(-0.1, 1.0, count)))  # includes r <= 0: clamped


def gpu_shade(scene, defines=None):
    s = scene
    return evaluate(SHADE, defines=defines, n=vec3(s["n"]), v=vec3(s["v"]), l=vec3(s["l"]),
                    radiance=vec3(s["radiance"]), diffuseColor=vec3(s["diffuseColor"]),
                    f0=vec3(s["f0"]), roughness=s["roughness"])


def reference_shade(scene, **variants):
    s = scene
    return shading.shade_punctual(s["n"], s["v"], s["l"], s["radiance"], s["diffuseColor"], s["f0"],
                                  s["roughness"], **variants)


def check_against_reference(label, scene, specular_d="GGX", **variants):
    defines = shading.glsl_defines(specular_d=specular_d, **variants)
    got = gpu_shade(scene, defines)
    ref = reference_shade(scene, specular_d=specular_d, **variants)
    s = scene
    specular = shading.shade_punctual(s["n"], s["v"], s["l"], s["radiance"], 0.0 * s["diffuseColor"],
                                      s["f0"], s["roughness"], specular_d=specular_d, **variants)
    NdotL = np.clip(np.sum(s["n"] * s["l"], -1), 1e-6, 1.0)
    NdotV = np.clip(np.sum(s["n"] * s["v"], -1), shading.MIN_NDOTV, 1.0)
    h = s["l"] + s["v"]
    h /= np.maximum(np.linalg.norm(h, axis=-1, keepdims=True), 1e-30)
    alpha = shading.clamp_perceptual_roughness(s["roughness"]) ** 2
    kappa = kappa_D(np.sum(s["n"] * h, -1), alpha, specular_d)
    rtol = RTOL_WELL_CONDITIONED + COSINE_ERROR * (1.0 / NdotL + 1.0 / NdotV)
    atol = COSINE_ERROR * (kappa[:, None] * np.abs(specular))
    assert_close(label, got, ref, rtol=rtol[:, None], atol=atol + 1e-30)


def test_shade_punctual_matches_reference_default_variants(scene):
    check_against_reference("pbr_shade_punctual (default variants)", scene)


@pytest.mark.parametrize("selector, value", [("specular_d", v) for v in shading.SPECULAR_D[1:]]
                         + [("specular_v", v) for v in shading.SPECULAR_V[1:]]
                         + [("specular_f", v) for v in shading.SPECULAR_F[1:]]
                         + [("diffuse", v) for v in shading.DIFFUSE[1:]])
def test_shade_punctual_variant_matches_reference(scene, selector, value):
    """Each selector value in turn (the others at their defaults) against the reference."""
    subset = {k: v[:20_000] for k, v in scene.items()}
    check_against_reference(f"pbr_shade_punctual {selector}={value}", subset, **{selector: value})


def test_quality_tier_selects_visibility_and_explicit_selector_wins(scene):
    """MEDIUM = HIGH with the fast V; LOW = its own lobe (V -> SMITH_GGX_BOUND, Schlick's F as
    every tier since issue 35, the 0.089 roughness floor; dispatch.glsl): bit for bit the explicit selectors at that floor,
    and against the float64 reference; an explicit selector wins over the tier's default."""
    subset = {k: v[:5_000] for k, v in scene.items()}
    medium = gpu_shade(subset, {"PBR_QUALITY": "PBR_QUALITY_MEDIUM"})
    fast = gpu_shade(subset, shading.glsl_defines(specular_v="SMITH_GGX_CORRELATED_FAST"))
    np.testing.assert_array_equal(medium, fast)
    low = gpu_shade(subset, {"PBR_QUALITY": "PBR_QUALITY_LOW"})
    rough = subset["roughness"] >= shading.MIN_PERCEPTUAL_ROUGHNESS_MEDIUMP
    bound = gpu_shade(subset, shading.glsl_defines(specular_v="SMITH_GGX_BOUND"))
    np.testing.assert_array_equal(low[rough], bound[rough])
    assert not np.array_equal(low[~rough], bound[~rough])  # the LOW floor acts below 0.089
    check_against_reference("pbr_shade_punctual quality=LOW", subset, quality="LOW")
    explicit = gpu_shade(subset, {"PBR_QUALITY": "PBR_QUALITY_LOW", **shading.glsl_defines(specular_v="KELEMEN")})
    kelemen = gpu_shade(subset, shading.glsl_defines(specular_v="KELEMEN"))
    np.testing.assert_array_equal(explicit[rough], kelemen[rough])  # the tier's floor still applies
    assert not np.array_equal(low, gpu_shade(subset))


@pytest.mark.parametrize("macro", ["PBR_SPECULAR_D", "PBR_SPECULAR_V", "PBR_SPECULAR_F", "PBR_DIFFUSE", "PBR_QUALITY"])
def test_unknown_selector_value_fails_to_compile(macro):
    with pytest.raises(ShaderCompileError, match="unknown value"):
        evaluate(SHADE, defines={macro: 99}, n=vec3([0, 0, 1]), v=vec3([0, 0, 1]), l=vec3([0, 0, 1]),
                 radiance=vec3([1, 1, 1]), diffuseColor=vec3([1, 1, 1]), f0=vec3([0, 0, 0]), roughness=0.5)


# ---- the lighting convention ------------------------------------------------------------

def test_light_unit_scale_is_pi():
    assert evaluate("PBR_LIGHT_UNIT_SCALE", x=0.0) == np.float32(np.pi)
    assert constants.LIGHT_UNIT_SCALE == np.pi


@pytest.mark.parametrize("normal", [(0, 0, 1), (1, 0, 0), (0, -1, 0)])
def test_white_lambert_lit_along_normal_returns_exactly_one(normal):
    """The lecture's convention: white diffuse, no specular (f0 = 0), intensity-1 light
    along the normal -> exactly 1, for every roughness and any view direction."""
    r = np.linspace(0.0, 1.0, 11)
    got = evaluate("pbr_shade_punctual(n, n, n, vec3(1.0), vec3(1.0), vec3(0.0), r)", n=vec3(normal), r=r)
    assert (got == 1.0).all(), got
    ref = shading.shade_punctual(np.array(normal, float), np.array(normal, float), np.array(normal, float),
                                 np.ones(3), np.ones(3), np.zeros(3), r)
    np.testing.assert_allclose(ref, 1.0, rtol=1e-15)


# ---- edges ---------------------------------------------------------------------------

def shade_points(n, v, l, roughness=0.5, f0=(0.04, 0.04, 0.04), diffuse=(0.5, 0.5, 0.5), defines=None):
    return evaluate(SHADE, defines=defines, n=vec3(n), v=vec3(v), l=vec3(l), radiance=vec3(np.ones(3)),
                    diffuseColor=vec3(np.asarray(diffuse)), f0=vec3(np.asarray(f0)), roughness=roughness)


def test_light_below_horizon_returns_zero(rng):
    n = np.array([0.0, 0.0, 1.0])
    l = unit_vectors(rng, 10_000)
    l[:, 2] = -np.abs(l[:, 2])
    l[:100, 2] = 0.0  # exactly grazing light: NdotL = 0
    l[:100] /= np.linalg.norm(l[:100], axis=-1, keepdims=True)
    v = unit_vectors(rng, 10_000, min_z=0.0)
    for d, v_ in (("default", None), ("cook-torrance", shading.glsl_defines(specular_v="COOK_TORRANCE"))):
        got = shade_points(n, v, as_f32(l), defines=v_)
        assert (got == 0.0).all(), d


def test_opposite_view_and_light_defines_zero_specular():
    """v = -l: no half vector; the specular lobe is 0 and the diffuse part remains."""
    n = np.array([0.0, 0.0, 1.0])
    l = as_f32(np.array([[0.6, 0.0, 0.8], [0.0, 0.0, 1.0], [0.28, 0.96, 0.0]]))
    got = shade_points(n, -l, l, f0=(1.0, 1.0, 1.0), diffuse=(0.5, 0.5, 0.5))
    assert np.isfinite(got).all()
    ref = shading.shade_punctual(n, -l, l, np.ones(3), np.full(3, 0.5), np.ones(3), 0.5)
    np.testing.assert_allclose(got, ref, rtol=1e-6)
    np.testing.assert_allclose(got[:, 0], 0.5 * np.clip(l[:, 2], 0, 1), rtol=1e-6)  # = diffuse · π · (1/π) · NdotL


@pytest.mark.parametrize("specular_v", shading.SPECULAR_V)
@pytest.mark.parametrize("specular_d", shading.SPECULAR_D)
def test_no_nan_at_roughness_zero_grazing_view_and_mirror_direction(specular_d, specular_v):
    """Smoothness 1 (perceptualRoughness 0 and below), views at and below the horizon and
    the exact mirror configuration stay finite for every D x V combination."""
    n = np.array([0.0, 0.0, 1.0])
    l = as_f32(np.array([[0.0, 0.0, 1.0], [0.6, 0.0, 0.8], [1.0, 0.0, 0.0], [0.999, 0.0, 0.0447], [0.0, 0.6, 0.8]]))
    v_mirror = l * np.array([-1.0, -1.0, 1.0])
    v_grazing = as_f32(np.array([[1.0, 0.0, 0.0]] * len(l)))
    v_below = as_f32(np.array([[0.8, 0.0, -0.6]] * len(l)))
    v = np.concatenate([v_mirror, v_grazing, v_below, -l])
    l = np.concatenate([l, l, l, l])
    r = np.array([-0.5, 0.0, 1e-4, 0.045, 1.0])[:, None]
    got = shade_points(n, v[None], l[None], roughness=r,
                       defines=shading.glsl_defines(specular_d=specular_d, specular_v=specular_v))
    assert np.isfinite(got).all()
    assert (got >= 0.0).all()
    # roughness at or below the minimum is the minimum, exactly
    np.testing.assert_array_equal(got[0], got[3])
    np.testing.assert_array_equal(got[1], got[3])
