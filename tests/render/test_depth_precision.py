"""Decals hold: a quad a little above a base plane wins at every pixel it covers, at every
scale and camera distance (depth_range.py chooses near and far from what the camera sees).

With near = far * 1e-5 a 24-bit depth buffer resolved only 5.6e-6 to 5.6e-2 of the plane's
size (measured: benchmarks/depth_resolution.py), so the Khronos sample models' 0.01-unit
decals at 5 to 20 units z-fought (TextureTransformTest's markers, AlphaBlendModeTest's "Opaque" label,
NegativeScaleTest's labels). Near and far from the bounds resolve 5.6e-8 to 5.6e-7 of it;
the smallest offset here, 1e-4 of the plane, keeps a margin of 180 over that."""

from __future__ import annotations

import math

import numpy as np
import pytest

from pbrlab.render.depth_range import scene_frame
from pbrlab.render.renderer import render_scene
from pbrlab.scene import parse_scene

SCALES = (0.1, 1.0, 100.0, 1e4)
OFFSETS = (1e-2, 1e-3, 1e-4)  # above the base plane, relative to its size (0.01 units at size 1)
# (camera distance / plane size, angle of the view from the plane's normal, degrees)
CAMERAS = ((2.5, 5.0), (2.5, 60.0), (10.0, 30.0), (0.6, 75.0))
SIZE = (96, 96)


def _scene(scale: float, distance: float, angle_deg: float, with_base: bool) -> dict:
    """A base plane of size ``scale`` (red) and three decals (green) above it at OFFSETS."""
    a = math.radians(angle_deg)
    position = [0.0, distance * scale * math.cos(a), distance * scale * math.sin(a)]
    objects = [{"mesh": {"primitive": "plane", "size": 0.25 * scale}, "material": "decal",
                "transform": {"translate": [(i - 1) * 0.3 * scale, offset * scale, 0.0]}}
               for i, offset in enumerate(OFFSETS)]
    if with_base:
        objects.append({"mesh": {"primitive": "plane", "size": scale}, "material": "base"})
    emissive = {"workflow": "metallic", "albedo": [0, 0, 0], "metallic": 0.0, "smoothness": 0.5}
    return {
        "camera": {"position": position, "target": [0.0, 0.0, 0.0], "up": [0, 1, 0] if angle_deg > 1 else [0, 0, -1],
                   "fov_y_deg": min(60.0, math.degrees(2 * math.atan(0.6 / distance))), "size": list(SIZE)},
        "lights": [],
        "materials": {"base": {**emissive, "emission": [1.0, 0.0, 0.0]},
                      "decal": {**emissive, "emission": [0.0, 1.0, 0.0]}},
        "objects": objects,
        "render": {"quality": "high", "tonemap": "none", "exposure": 0.0},
    }


@pytest.mark.parametrize("distance, angle", CAMERAS)
@pytest.mark.parametrize("scale", SCALES)
def test_a_decal_wins_at_every_pixel_it_covers(scale, distance, angle, gl_context):
    decals = render_scene(parse_scene(_scene(scale, distance, angle, False)), gl_context).linear
    covered = decals[..., 3] > 0
    assert covered.sum() > 150  # the three decals are in view
    both = render_scene(parse_scene(_scene(scale, distance, angle, True)), gl_context).linear
    lost = covered & (both[..., 0] > 0.5)  # the base plane shows where a decal is
    assert not lost.any(), f"{lost.sum()} of {covered.sum()} decal pixels show the plane below"
    np.testing.assert_array_equal(both[covered, :3], decals[covered, :3])


def test_the_planes_hug_what_the_camera_sees(gl_context):
    """Head-on at 2.5 plane sizes, near and far lie within the margin around the plane."""
    scene = parse_scene(_scene(1.0, 2.5, 5.0, True))
    frame = scene_frame(scene)
    depth = 2.5  # of the plane's centre; the plane spans about +-0.05 of depth at 5 degrees
    assert depth * 0.9 < frame.near < depth - 0.06 and depth + 0.06 < frame.far < depth * 1.1


MANUAL = __import__("pathlib").Path(__file__).resolve().parents[2] / "scenes" / "unity_manual"


def _unity_scene(shader: str) -> dict:
    """A unit sphere at 4 units drawn with one of the manual's Unity surface shaders."""
    return {
        "camera": {"position": [0.0, 0.0, 4.0], "target": [0.0, 0.0, 0.0], "up": [0, 1, 0],
                   "fov_y_deg": 40.0, "size": [64, 64]},
        "lights": [{"type": "directional", "direction": [0, 0, 1], "color": [1, 1, 1], "intensity": 1.0}],
        "materials": {"m": {"surface": str(MANUAL / shader)}},
        "objects": [{"sphere": {"center": [0, 0, 0], "radius": 1.0}, "material": "m"}],
    }


def test_a_unity_program_that_moves_vertices_keeps_the_whole_scene_range():
    """A vertex: function puts the mesh where it likes (normal extrusion by _Amount grows the
    sphere), so the unit sphere's bounds (near 2.86) would clip its front: such a scene keeps
    the range from the scene radius alone (near = max(far * 1e-5, 1e-4))."""
    frame = scene_frame(parse_scene(_unity_scene("normal_extrusion.shader")))
    assert frame.near == pytest.approx(max(frame.far * 1e-5, 1e-4))


def test_a_unity_program_sees_a_near_plane_no_farther_than_unitys_default():
    """Unity programs read the planes (_ProjectionParams.y is near): a scene of Unity shaders
    keeps near at most Unity's default camera's 0.3 (here the bounds alone would give 2.86);
    a scene of pbrlab's own materials keeps near at its bounds."""
    frame = scene_frame(parse_scene(_unity_scene("simple.shader")))
    assert frame.near == pytest.approx(0.3)
    own = _unity_scene("simple.shader")
    own["materials"]["m"] = {"workflow": "metallic", "albedo": [1, 1, 1], "metallic": 0.0, "smoothness": 0.5}
    assert scene_frame(parse_scene(own)).near > 2.5
