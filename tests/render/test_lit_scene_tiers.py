"""The Unity-style example scene (scenes/unity_example): a ported surface function with
albedo, normal, metallic/smoothness and emission maps, metallic, dielectric, cut-out,
faded and transparent materials, three light types and an HDR environment, at each
quality tier."""

import numpy as np
import pytest

from pbrlab.checking.golden_scenes import lit_scene
from pbrlab.render.renderer import render_scene
from pbrlab.scene.model import QUALITIES


@pytest.fixture(scope="module")
def renders():
    out = {}
    for quality in QUALITIES:
        out[quality] = render_scene(lit_scene(quality))
    return out


@pytest.mark.parametrize("quality", QUALITIES)
def test_lit_scene_tier_matches_golden(quality, renders, golden):
    golden.check(f"lit_scene_{quality}", renders[quality].linear, renders[quality].srgb8)


@pytest.mark.parametrize("quality", QUALITIES)
def test_lit_scene_tier_has_no_nonfinite_or_negative_pixel(quality, renders):
    linear = renders[quality].linear
    assert np.isfinite(linear).all()  # float readback: NaN cannot hide as it would in 8 bits
    assert (linear >= 0).all()


def _tier_error(renders, tier):
    high = renders["high"].linear[..., :3].astype(np.float64)
    other = renders[tier].linear[..., :3].astype(np.float64)
    covered = renders["high"].linear[..., 3] > 0
    rel = np.abs(other - high)[covered] / (1e-2 + high[covered])
    srgb = np.abs(renders[tier].srgb8.astype(int) - renders["high"].srgb8.astype(int))[..., :3]
    print(f"{tier} vs high: linear relative error median {np.median(rel):.4f}, p99 "
          f"{np.quantile(rel, 0.99):.4f}, max {rel.max():.4f}; display max {srgb.max()} codes, "
          f"mean {srgb.mean():.3f}")
    return rel, srgb


def test_medium_tier_error_against_high_tier_is_measured(renders):
    rel, srgb = _tier_error(renders, "medium")
    # MEDIUM swaps V for the fast correlated-Smith fit and F for the spherical-Gaussian
    # Schlick (documented bounds 0.293 and 0.0038; the direct diffuse coupling adds the
    # latter's albedo bound, pbr_specular_albedo_bound). Measured on this scene: median
    # 0.0023, p99 0.0047, max 0.056 relative; display mean 0.097 codes, max 2 codes.
    assert 2e-4 < np.median(rel) < 3e-3 and np.quantile(rel, 0.99) < 0.01
    assert srgb.max() <= 3


def test_low_tier_differs_from_high_by_its_environment_choices(renders):
    rel, srgb = _tier_error(renders, "low")
    # LOW is its own lobe (issue 25): V bounded without a square root (0.5 / n·(l + v)),
    # Schlick's F (issue 35; issue 25's LOW had F = f0), the 0.089 roughness floor. Since issue
    # 35's whole-pixel tier it also reads the environment along the mirror direction, without
    # horizon occlusion, without multiple-scattering compensation and with the AO as its
    # specular occlusion, and reads its own DFG table (pbr/shading/dispatch.glsl). Measured on
    # this scene: relative to 0.01 + |high|, median 0.0158, p99 0.086, max 5.07; display mean
    # 0.83 codes, max 103. With the lobe alone (before the environment choices): median 0.0044,
    # p99 0.029, mean 0.23 codes. This test is the control that the environment choices are in
    # effect: its lower limits sit above the lobe-only LOW's figures. It asserts no upper limit:
    # how far LOW's mirror read of this HDR sky is from HIGH's dominant-direction read has no
    # bound to derive (it is the sky's own variation), and the former upper limits were the
    # measured figures with room (removed, session 39). LOW's accuracy is held by derived bounds
    # where a float64 reference exists (tests/render/test_gpu_matches_cpu_reference.py at
    # quality low under a constant sky, the white furnace, reciprocity and grazing Fresnel in
    # tests/checking/hardcases) and its image here by the lit_scene_low golden.
    assert np.median(rel) > 1e-2 and srgb.mean() > 0.5
