"""A URP toon pass's ramp steps (issue 34's toon category, content checked in colour): the
main light from GetMainLight, N.L stepped into two bands (urp_toon_ramp.shader). On a sphere
lit from one side, every covered pixel is one of the two band colours exactly (a step, not a
gradient), both bands show, and the lit band is where N.L exceeds the threshold: checked
against the sphere's normals computed in float64 from the camera ray at each pixel centre."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from pbrlab.importers.loader import parse_scene
from pbrlab.render.renderer import render_scene

from test_urp_front_end import SHADERS

TOON = SHADERS / "urp_toon_ramp.shader"
LIT, SHADE = np.array([1.0, 0.75, 0.5]), np.array([0.25, 0.125, 0.5])
SIZE, FOV_DEG, CAMERA_Z, RADIUS = 48, 40.0, 3.2, 1.0
LIGHT_DIRECTION = np.array([-1.0, 0.0, -0.35])  # the way the light travels: from +x, a little towards the camera


def _render(language: str) -> np.ndarray:
    scene = {
        "camera": {"position": [0.0, 0.0, CAMERA_Z], "target": [0.0, 0.0, 0.0], "fov_y_deg": FOV_DEG,
                   "size": [SIZE, SIZE]},
        "lights": [{"type": "directional", "direction": LIGHT_DIRECTION.tolist(), "color": [1, 1, 1], "intensity": 1.0}],
        "materials": {"m": {"surface": str(TOON)}},
        "objects": [{"mesh": {"primitive": "uv_sphere", "radius": RADIUS}, "material": "m"}],
    }
    return render_scene(parse_scene(scene, origin="t", base=TOON.parent), language=language).linear


def _sphere_n_dot_l() -> np.ndarray:
    """N.L at each pixel centre's ray hit on the exact sphere (NaN off it), float64."""
    half = np.tan(np.radians(FOV_DEG) / 2)
    c = (np.arange(SIZE) + 0.5) / SIZE * 2 - 1
    x, y = np.meshgrid(c * half, -c * half)
    d = np.stack([x, y, -np.ones_like(x)], -1)
    d /= np.linalg.norm(d, axis=-1, keepdims=True)
    o = np.array([0.0, 0.0, CAMERA_Z])
    b = d @ o
    disc = b * b - (o @ o - RADIUS ** 2)
    t = -b - np.sqrt(np.where(disc >= 0, disc, np.nan))
    n = (o + t[..., None] * d) / RADIUS
    to_light = -LIGHT_DIRECTION / np.linalg.norm(LIGHT_DIRECTION)
    return n @ to_light


@pytest.mark.parametrize("language", ["glsl", "hlsl"])
def test_a_urp_toon_ramp_steps_between_two_colours_where_n_dot_l_crosses_the_threshold(language):
    img = _render(language)
    covered = img[..., 3] > 0.999  # whole pixels (the silhouette's are blended with the background)
    rgb = img[..., :3][covered]
    is_lit = np.all(np.abs(rgb - LIT) < 1e-6, axis=-1)
    is_shade = np.all(np.abs(rgb - SHADE) < 1e-6, axis=-1)
    assert np.all(is_lit | is_shade)            # a step: no colour between the bands
    assert is_lit.mean() > 0.1 and is_shade.mean() > 0.1
    # Where the band is decided: the mesh is a UV sphere (facets, interpolated normals), so
    # pixels near N.L = 0.5 may fall either way; away from it (|N.L - 0.5| > 0.05, about 3
    # degrees, more than the facets' normal error at this tessellation) the band must match.
    ndl = _sphere_n_dot_l()[covered]
    sure = np.abs(ndl - 0.5) > 0.05
    assert np.array_equal(is_lit[sure], (ndl > 0.5)[sure])
