"""pbr/surface/lighting_iridescence.glsl (the film folded into the base's F0) against its
float64 twin (reference/surface.py iridescent_f0, f0_from_schlick), and what the fold keeps:
Schlick's curve through the film's reflectance at the view, mask 0 = the base's F0."""

import numpy as np

from pbrlab import evaluate, vec3
from pbrlab.maths.reference import iridescence as ref_iridescence
from pbrlab.maths.reference import surface as ref_surface

INCLUDES = ["pbr/surface/lighting_iridescence.glsl"]
RNG = np.random.default_rng(29)
N = 8192


def _film_inputs(n):
    return dict(f0=RNG.uniform(0.0, 1.0, (n, 3)), NdotV=RNG.uniform(0.02, 1.0, n), factor=RNG.uniform(0.0, 1.0, n),
                ior=RNG.uniform(1.0, 2.3, n), thickness=RNG.uniform(0.0, 1200.0, n))


def test_iridescent_f0_matches_the_float64_reference():
    """Against the float64 twin of the same method. The film itself carries float32 phase
    rounding (pbr/brdf/f_iridescence.glsl: tens of radians of phase), and the inversion divides
    by 1 - (1 - NdotV)^5, so near grazing views the F0 differs more; measured on llvmpipe
    worst 1.0e-5 absolute (NdotV 0.054, a 1167 nm film), p99.9 1.6e-6; 5e-5 asked."""
    x = _film_inputs(N)
    got = evaluate("pbr_iridescent_f0(f0, NdotV, pbr_Iridescence(factor, ior, thickness))", INCLUDES,
                   f0=vec3(x["f0"]), NdotV=x["NdotV"].astype(np.float32), factor=x["factor"].astype(np.float32),
                   ior=x["ior"].astype(np.float32), thickness=x["thickness"].astype(np.float32))[:, :3]
    want = ref_surface.iridescent_f0(x["f0"], x["NdotV"], x["factor"], x["ior"], x["thickness"])
    err = np.abs(got - want)
    assert err.max() < 5e-5, err.max()
    assert np.all((got >= 0.0) & (got <= 1.0))


def test_the_films_f0_reproduces_its_reflectance_at_the_view():
    """Schlick(F0_film, NdotV) with F90 = 1 is F_iridescence(NdotV) wherever the inversion
    needs no clamp (float64: the twin, exactly up to rounding)."""
    x = _film_inputs(N)
    film = ref_iridescence.F_Iridescence(1.0, x["ior"], x["NdotV"], x["thickness"], x["f0"])
    f0_film = ref_surface.iridescent_f0(x["f0"], x["NdotV"], 1.0, x["ior"], x["thickness"])
    w = ((1.0 - x["NdotV"]) ** 5)[:, None]
    back = f0_film + (1.0 - f0_film) * w
    inside = (film >= w) & (w <= ref_surface.IRIDESCENCE_MAX_SCHLICK_WEIGHT)  # no clamp at 0
    np.testing.assert_allclose(back[inside], film[inside], atol=1e-12)
    assert inside.mean() > 0.5


def test_mask_zero_is_the_base_f0_exactly():
    x = _film_inputs(4096)
    got = evaluate("pbr_iridescent_f0(f0, NdotV, pbr_Iridescence(0.0, ior, thickness))", INCLUDES,
                   f0=vec3(x["f0"]), NdotV=x["NdotV"].astype(np.float32), ior=x["ior"].astype(np.float32),
                   thickness=x["thickness"].astype(np.float32))[:, :3]
    np.testing.assert_array_equal(got, x["f0"].astype(np.float32))


def test_f0_from_schlick_matches_the_reference_and_clamps():
    F = RNG.uniform(-0.1, 1.1, (N, 3))
    c = RNG.uniform(-0.1, 1.1, N)
    c[:8] = [0.0, 1.0, 1e-6, 0.5, -0.1, 1.1, 0.01, 0.99]
    F32, c32 = F.astype(np.float32), c.astype(np.float32)
    got = evaluate("pbr_f0_from_schlick(F, c)", INCLUDES, F=vec3(F32), c=c32)[:, :3]
    want = ref_surface.f0_from_schlick(F32.astype(np.float64), c32.astype(np.float64))
    # (F - x) / (1 - x) in float32: a few roundings of F and x (each 2^-24 relative, |.| <= 1.1),
    # amplified by 1/(1 - x) (at most 1e4 by the clamp); 8 roughly-unit roundings asked per
    # sample. Measured worst 2.9e-6 absolute, at a grazing c.
    x = np.minimum((1.0 - np.clip(c32.astype(np.float64), 0.0, 1.0)) ** 5, ref_surface.IRIDESCENCE_MAX_SCHLICK_WEIGHT)
    bound = 8 * 2.0 ** -24 / (1.0 - x)
    assert np.all(np.abs(got - want) <= bound[:, None]), np.max(np.abs(got - want) / bound[:, None])
    assert np.all((got >= 0.0) & (got <= 1.0))
