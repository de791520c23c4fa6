"""The torture chart (scenes/torture): every hard case of the catalogue at once, rendered.

Grazing light (a horizon sun of intensity 1e4) and grazing view of a floor; white metal
(F0 = 1) at smoothness 1 (roughness 0, clamped by the tier) to 0; a light exactly behind
the objects along the view axis (v = -l); a point light on a sphere's surface (distance
0); a low-poly sphere whose normal map points into the surface (normals facing away from
the viewer); an environment with a +Inf and a NaN texel; an RGBA16F target.
"""

import numpy as np
import pytest

from pbrlab.checking.golden_scenes import GOLDEN_SCENES
from pbrlab.render.renderer import render_scene

# A sparkle: a display pixel brighter than every one of its 8 neighbours by more than this
# many 8-bit codes (a lone NaN-turned-white or overflow pixel; real highlights on these
# spheres span several pixels, so their centre exceeds its brightest neighbour by < 20).
SPARKLE_CODES = 48


def sparkles(srgb8: np.ndarray) -> np.ndarray:
    """Boolean mask of isolated bright pixels (see SPARKLE_CODES)."""
    grey = srgb8[..., :3].astype(np.int32).max(axis=-1)
    padded = np.pad(grey, 1, mode="edge")
    h, w = grey.shape
    neighbours = np.stack([padded[1 + dy:1 + dy + h, 1 + dx:1 + dx + w]
                           for dy in (-1, 0, 1) for dx in (-1, 0, 1) if (dy, dx) != (0, 0)])
    return grey - neighbours.max(axis=0) > SPARKLE_CODES


@pytest.fixture(scope="module")
def torture():
    return render_scene(GOLDEN_SCENES["torture_chart"]())


def test_torture_chart_float_render_has_no_nonfinite_or_negative_value(torture):
    linear = torture.linear
    assert np.isfinite(linear).all(), int((~np.isfinite(linear)).sum())
    assert (linear >= 0).all()
    assert linear[..., :3].max() <= 65504.0  # RGBA16F target: clamped to the largest half


def test_torture_chart_display_has_no_sparkles(torture):
    assert sparkles(torture.srgb8).sum() == 0


def test_sparkle_detector_finds_a_planted_sparkle(torture):
    planted = torture.srgb8.copy()
    planted[99:102, 99:102, :3] = 20
    planted[100, 100, :3] = 255
    assert sparkles(planted)[100, 100] and sparkles(planted).sum() == 1


def test_torture_chart_matches_golden(torture, golden):
    golden.check("torture_chart", torture.linear, torture.srgb8)


def test_environment_texels_are_sanitised_like_the_library():
    from pbrlab.scene.environment import sanitize_radiance

    raw = np.array([[np.nan, np.inf, -np.inf, -1.0, 0.5, 1e6]])
    np.testing.assert_array_equal(sanitize_radiance(raw), [[0.0, 65504.0, 0.0, 0.0, 0.5, 65504.0]])
