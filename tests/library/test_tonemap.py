"""Exposure and tonemappers (glsl/pbr/tonemap/) against harness/pbrlab/maths/reference/tonemap.py.
Outputs are display-linear values in [0, 1] (unitless); inputs linear HDR up to 1000."""

import numpy as np
import pytest

from library_helpers import seeded_rng, RTOL_WELL_CONDITIONED, as_f32, assert_close, evaluate, vec3
from pbrlab.maths.reference import tonemap


@pytest.fixture(scope="module")
def hdr():
    """Grey ramp (exercises every branch along the neutral axis) plus random HDR colours
    spanning 1e-4 .. 1e3 per channel, and pure black."""
    rng = seeded_rng("hdr")
    ramp = np.geomspace(1e-4, 1e3, 8192)
    grey = np.stack([ramp] * 3, axis=-1)
    colours = 10.0 ** rng.uniform(-4, 3, (50_000, 3))
    return as_f32(np.concatenate([np.zeros((1, 3)), grey, colours]))


# atol 1e-6 (display-linear units, ~1/4000 of an 8-bit step): the ACES output matrix has
# negative coefficients, so channels near 0 come from cancelling terms of size ~1 (error
# ~ a few float32 ulps of 1); the other curves meet it with margin.
TONEMAP_ATOL = 1e-6


@pytest.mark.parametrize("name", ["reinhard", "hable", "aces_fitted", "aces_narkowicz", "khronos_neutral"])
def test_tonemapper_matches_reference(name, hdr):
    got = evaluate(f"pbr_tonemap_{name}(c)", c=vec3(hdr))
    # Hable's curve passes 1 above its white point W = 11.2; the GLSL caps the input at W,
    # which is exactly saturate(curve) (hable.glsl): compared with the exact curve, capped.
    ref = np.minimum(getattr(tonemap, f"tonemap_{name}")(hdr), 1.0)
    assert_close(f"pbr_tonemap_{name}", got, ref, rtol=RTOL_WELL_CONDITIONED, atol=TONEMAP_ATOL)
    assert (got >= 0.0).all() and (got <= 1.0).all()


def test_tonemap_reinhard_extended_matches_reference_and_maps_white_to_one(hdr):
    white = np.array([1.0, 4.0, 11.2, 100.0])[:, None]
    got = evaluate("pbr_tonemap_reinhard_extended(c, w)", c=vec3(hdr[None]), w=white)
    # eq. 4 passes 1 above the white point; the GLSL caps the input there, which is exactly
    # saturate(eq. 4) (reinhard.glsl): compared with the exact curve, capped at 1.
    ref = np.minimum(tonemap.tonemap_reinhard_extended(hdr[None], white), 1.0)
    assert_close("pbr_tonemap_reinhard_extended", got, ref, rtol=RTOL_WELL_CONDITIONED, atol=TONEMAP_ATOL)
    at_white = evaluate("pbr_tonemap_reinhard_extended(vec3(w), w)", w=white[:, 0])
    np.testing.assert_allclose(at_white, 1.0, rtol=1e-6)


def test_tonemap_hable_white_point_maps_to_one():
    got = evaluate("pbr_tonemap_hable(vec3(PBR_HABLE_WHITE))", x=0.0)
    np.testing.assert_allclose(got, 1.0, rtol=1e-6)
    assert tonemap.tonemap_hable(np.full(3, tonemap.HABLE_WHITE)) == pytest.approx(1.0)
    assert tonemap.tonemap_hable(np.zeros(3)) == pytest.approx(0.0, abs=1e-12)


def test_tonemap_khronos_neutral_passes_low_colours_and_compresses_highlights():
    """Below K_s only the toe offset applies (base colours stay true); above, peaks -> <= 1."""
    low = as_f32(np.array([[0.5, 0.3, 0.2], [0.7, 0.7, 0.1]]))
    got = evaluate("pbr_tonemap_khronos_neutral(c)", c=vec3(low))
    np.testing.assert_allclose(got, low - 0.04, rtol=1e-6)
    high = evaluate("pbr_tonemap_khronos_neutral(vec3(1e4))", x=0.0)
    assert 0.99 < high[0] <= 1.0


@pytest.mark.parametrize("variant", tonemap.TONEMAPS)
def test_tonemap_dispatch_matches_reference(variant, hdr):
    got = evaluate("pbr_tonemap(c)", defines={"PBR_TONEMAP": f"PBR_TONEMAP_{variant}"}, c=vec3(hdr[:5000]))
    assert_close(f"pbr_tonemap {variant}", got, tonemap.tonemap(hdr[:5000], variant),
                 rtol=RTOL_WELL_CONDITIONED, atol=TONEMAP_ATOL)


def test_apply_exposure_matches_reference_and_is_exact_for_whole_stops(hdr):
    ev = as_f32(np.linspace(-10.0, 10.0, 81))[:, None]
    got = evaluate("pbr_apply_exposure(c, ev)", c=vec3(hdr[None, :2000]), ev=ev)
    assert_close("pbr_apply_exposure", got, tonemap.apply_exposure(hdr[None, :2000], ev), rtol=RTOL_WELL_CONDITIONED)
    whole = np.arange(-8.0, 9.0)[:, None]
    got = evaluate("pbr_apply_exposure(c, ev)", c=vec3(hdr[None, :2000]), ev=whole)
    np.testing.assert_array_equal(got, (hdr[None, :2000] * 2.0 ** whole[..., None]).astype(np.float32))
