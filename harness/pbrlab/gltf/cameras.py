"""glTF cameras (spec 3.10) as pbrlab cameras, and a framing camera for files without one.

A glTF camera looks down its node's -Z with +Y up. pbrlab chooses near and far from the
scene bounds (camera.py), so znear / zfar are not used. The image is DEFAULT_HEIGHT pixels
high and aspectRatio (perspective) or xmag / ymag (orthographic) wide, unless --size says
otherwise.
"""

from __future__ import annotations

import math

import numpy as np

from ..scene import Camera

DEFAULT_HEIGHT = 512
FRAMING_FOV_DEG = 45.0
FRAMING_DIRECTION = np.array([0.0, 0.35, 1.0])  # from the front (+Z, glTF's front), a little above
FRAMING_MARGIN = 1.1                             # the bounding sphere fills 1/1.1 of the view
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
    from . import bounds

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
    """A perspective camera that sees the whole scene: its bounding sphere from the front."""
    from . import bounds

    lo, hi = bounds(scene)
    centre = (lo + hi) / 2
    radius = max(float(np.linalg.norm(hi - lo)) / 2, 1e-6)
    distance = radius / math.sin(math.radians(FRAMING_FOV_DEG) / 2) * FRAMING_MARGIN
    direction = FRAMING_DIRECTION / np.linalg.norm(FRAMING_DIRECTION)
    return Camera(centre + direction * distance, centre, np.array([0.0, 1.0, 0.0]), FRAMING_FOV_DEG,
                  _size(1.0, size, None))
