"""glTF cameras (spec 3.10) as pbrlab cameras, and a framing camera for files without one.

A glTF camera looks down its node's -Z with +Y up. pbrlab chooses near and far from the
scene bounds (camera.py), so znear / zfar are not used. The image is DEFAULT_HEIGHT pixels
high and aspectRatio (perspective) or xmag / ymag (orthographic) wide, unless --size says
otherwise.
"""

from __future__ import annotations

import math

import numpy as np

from ...scene.model import Camera
from .extent import bounds, world_points

DEFAULT_HEIGHT = 512
FRAMING_FOV_DEG = 45.0
FRAMING_DIRECTION = np.array([0.0, 0.35, 1.0])  # from the front (+Z, glTF's front), a little above
FRAMING_MARGIN = 1.05                            # the vertices fill 1/1.05 of the limiting axis
MAX_WIDTH = 16384                                # the JSON scene's camera.size limit (scene.py)


def _size(aspect: float, size, spec) -> tuple[int, int]:
    if size is not None:
        return tuple(size)
    width = DEFAULT_HEIGHT * aspect
    if not width <= MAX_WIDTH:
        spec.fail(f"its aspect ratio {aspect:g} makes the image {width:g} pixels wide at height "
                  f"{DEFAULT_HEIGHT} (at most {MAX_WIDTH}); give the size (--size)")
    return max(1, round(width)), DEFAULT_HEIGHT


def gltf_camera(doc, index, world: np.ndarray, where: str, scene, size) -> Camera:
    spec = doc.get("cameras", index, where)
    position = world[:3, 3].copy()
    forward = world[:3, :3] @ np.array([0.0, 0.0, -1.0])
    up = world[:3, :3] @ np.array([0.0, 1.0, 0.0])
    if np.linalg.norm(np.cross(forward, up)) < 1e-12:
        doc.fail(where, "the node's transform collapses the camera's view or up direction")
    forward /= np.linalg.norm(forward)
    lo, hi = bounds(scene)
    distance = max(float(np.dot((lo + hi) / 2 - position, forward)), 1e-3)
    kind = spec.enum("type", ("perspective", "orthographic"))
    if kind == "perspective":
        p = spec.object("perspective")
        yfov = p.number("yfov", None, 0.0, math.pi, lo_open=True)
        if yfov >= math.pi:
            p.fail(f"yfov must be below pi, got {yfov:g}")
        aspect = p.number("aspectRatio", 1.0, 0.0, lo_open=True)
        return Camera(position, position + forward * distance, up, math.degrees(yfov), _size(aspect, size, p))
    o = spec.object("orthographic")
    xmag = o.number("xmag", None, 0.0, lo_open=True)
    ymag = o.number("ymag", None, 0.0, lo_open=True)
    camera = Camera(position, position + forward * distance, up, FRAMING_FOV_DEG, _size(xmag / ymag, size, o))
    camera.ortho_half_height = ymag
    return camera


def framing_camera(scene, size) -> Camera:
    """A perspective camera from the front (FRAMING_DIRECTION) that fits the scene's
    vertices to its view on both axes, the image's aspect ratio considered: the limiting
    axis spans 1 / FRAMING_MARGIN of the image, the other axis is centred.

    The fit is exact for a pinhole camera. With the view's right a, up b and backward
    direction d (towards the camera), the camera at c = u a + v b + w d, a point p is in
    view horizontally when |(p - c).a| <= k (c - p).d, k = tan(half the horizontal fov) /
    FRAMING_MARGIN: u + k w >= max(p.a + k p.d) = A+ and k w - u >= max(-p.a + k p.d) = A-,
    both tight at w = (A+ + A-) / (2k), u = (A+ - A-) / 2; likewise vertically for (v, w).
    The larger w serves both axes; the other axis, its u or v as computed, stays centred."""
    points = world_points(scene)
    width, height = _size(1.0, size, None)
    tan_v = math.tan(math.radians(FRAMING_FOV_DEG) / 2)
    backward = FRAMING_DIRECTION / np.linalg.norm(FRAMING_DIRECTION)
    right = np.cross(np.array([0.0, 1.0, 0.0]), backward)
    right /= np.linalg.norm(right)
    up = np.cross(backward, right)
    depth = points @ backward
    placement = {}
    for axis, k in ((right, tan_v * width / height / FRAMING_MARGIN), (up, tan_v / FRAMING_MARGIN)):
        across = points @ axis
        a_plus, a_minus = float(np.max(across + k * depth)), float(np.max(-across + k * depth))
        placement[id(axis)] = ((a_plus + a_minus) / (2 * k), (a_plus - a_minus) / 2)
    (w_h, u), (w_v, v) = placement[id(right)], placement[id(up)]
    extent = float(np.ptp(points, axis=0).max()) if len(points) > 1 else 0.0
    w = max(w_h, w_v, float(depth.max()) + max(extent, 1e-6) * 1e-3)  # in front of every vertex
    position = u * right + v * up + w * backward
    target = position - backward * max(w - float(depth.mean()), 1e-6)
    return Camera(position, target, np.array([0.0, 1.0, 0.0]), FRAMING_FOV_DEG, (width, height))
