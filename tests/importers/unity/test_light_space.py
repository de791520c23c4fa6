"""Unity's forward-add light space (issue 34): unity_WorldToLight and the attenuation / cookie
textures a Unity Shaders Book style ForwardAdd pass reads itself (shaders/
forward_add_light_space.shader: POINT writes dot(c, c) and the attenuation lookup, SPOT the
cookie uv c.xy / c.w + 0.5 and the attenuation with its c.z > 0 test), against the float64
light space importers/unity/light_space.py documents, in both languages. Before, the names were
refused ("light cookies and attenuation textures").

Scene: a plane y = -1 seen straight down (tests/importers/urp/test_urp_scene_textures.py's
opaque-copy view), one positional light; the ForwardBase pass writes black, the ForwardAdd pass
adds its value (Blend One One). The float64 world position of each pixel is the pixel-centre ray
met with the plane.

Bound: the fragment's world position is the vertices' float32 positions interpolated at the
pixel centre, a few float32 operations on coordinates below 2: DELTA_P = 16 ulp of 2 (2^-19)
per component, sqrt(3) of that in length; the light-space value's own float32 arithmetic (a
4x4 product, a dot, a divide) 16 ulp of it. Each output is bounded by its first-order
sensitivity to the position times that, plus those ulps.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from pbrlab.importers.loader import parse_scene
from pbrlab.maths.camera import camera_rays
from pbrlab.render.depth_range import scene_frame
from pbrlab.render.renderer import render_scene

LANGUAGES = ("glsl", "hlsl")
SHADER = Path(__file__).parent / "shaders" / "forward_add_light_space.shader"
DISTANCE, FOV_DEG = 3.0, 40.0
POINT = {"type": "point", "position": [0.3, 0.5, -0.2], "color": [1, 1, 1], "intensity": 2.0, "range": 4.0}
SPOT = {"type": "spot", "position": [0.2, 0.6, 0.1], "direction": [0.2, -1.0, 0.1], "color": [1, 1, 1],
        "intensity": 2.0, "range": 5.0, "inner_cone_deg": 20.0, "outer_cone_deg": 40.0}
DELTA_P = np.sqrt(3.0) * 2.0 ** -19
ULPS = 16 * 2.0 ** -24


def _render(light, language):
    side = 2 * DISTANCE * np.tan(np.radians(FOV_DEG / 2))
    data = {
        "camera": {"position": [0.0, 2.0, 0.0], "target": [0.0, -1.0, 0.0], "up": [0.0, 0.0, -1.0],
                   "fov_y_deg": FOV_DEG, "size": [64, 64]},
        "lights": [light],
        "materials": {"m": {"surface": str(SHADER)}},
        "objects": [{"mesh": {"primitive": "plane", "size": float(side)},
                     "transform": {"translate": [0.0, -1.0, 0.0]}, "material": "m"}],
    }
    scene = parse_scene(data, origin="light-space test scene", base=SHADER.parent)
    frame = scene_frame(scene)
    d = camera_rays(frame)
    o = np.asarray(frame.position, np.float64)
    p = o + ((-1.0 - o[1]) / d[..., 1])[..., None] * d  # the plane y = -1 at each pixel centre
    image = render_scene(scene, language=language).linear.astype(np.float64)
    assert (image[..., 3] > 0).all()
    return image[..., :3], p


@pytest.mark.parametrize("language", LANGUAGES)
def test_point_light_space_is_distance_over_range(language):
    """POINT: dot(c, c) = |p - position|^2 / range^2 (c = (p - position) / range) and the
    attenuation texture reads 1 (white: the falloff is in _LightColor0). Bound: d(r) = 2 |l| /
    range^2 DELTA_P plus ULPS of r. Control: the squared distance not divided by range^2 (the
    identity matrix's light space) fails it."""
    image, p = _render(POINT, language)
    l = p - np.asarray(POINT["position"])
    r = (l * l).sum(-1) / POINT["range"] ** 2
    bound = 2 * np.linalg.norm(l, axis=-1) / POINT["range"] ** 2 * DELTA_P + ULPS * r
    err = np.abs(image[..., 0] - r)
    assert (err <= bound).all(), (err / bound).max()
    assert (np.abs(image[..., 1] - 1.0) <= ULPS).all()
    assert (np.abs(image[..., 0] - (l * l).sum(-1)) > bound).all()  # control


def _spot_frame(direction):
    z = np.asarray(direction, np.float64) / np.linalg.norm(direction)
    up = np.array([0.0, 1.0, 0.0]) if abs(z[1]) < 0.999 else np.array([1.0, 0.0, 0.0])
    x = np.cross(up, z)
    x /= np.linalg.norm(x)
    return x, np.cross(z, x), z


@pytest.mark.parametrize("language", LANGUAGES)
def test_spot_light_space_is_the_cone_projection(language):
    """SPOT: the cookie uv c.xy / c.w + 0.5 = 0.5 cot(outer) (l . right, l . up) / (l . axis) + 0.5
    (the cone's rim at 0 and 1) and the attenuation (c.z > 0) * cookie * falloff = 1 in front of
    the light (every pixel here: l . axis > 0). Bound: the uv's sensitivity to the position,
    0.5 cot(outer) (1 + |uv - 0.5| / (0.5 cot)) / (l . axis) DELTA_P, plus ULPS of the uv.
    Control: the uv with tan for cot (a cone of the complementary angle) fails it."""
    image, p = _render(SPOT, language)
    x, y, z = _spot_frame(SPOT["direction"])
    l = p - np.asarray(SPOT["position"])
    lz = l @ z
    assert (lz > 0.5).all()
    cot = 1.0 / np.tan(np.radians(SPOT["outer_cone_deg"]))
    uv = np.stack([0.5 * cot * (l @ x) / lz + 0.5, 0.5 * cot * (l @ y) / lz + 0.5], axis=-1)
    sens = (0.5 * cot + np.abs(uv - 0.5)) / lz[..., None] * DELTA_P
    bound = sens + ULPS * np.abs(uv)
    err = np.abs(image[..., :2] - uv)
    assert (err <= bound).all(), (err / bound).max()
    assert (np.abs(image[..., 2] - 1.0) <= ULPS).all()
    wrong = np.stack([0.5 * np.tan(np.radians(SPOT["outer_cone_deg"])) * (l @ a) / lz + 0.5 for a in (x, y)], -1)
    assert (np.abs(image[..., :2] - wrong) > bound).any(axis=-1).mean() > 0.9  # control
