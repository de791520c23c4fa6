"""Why a rendered frame shows nothing: a render whose every pixel is uncovered (alpha 0:
``Rendering.linear``'s alpha is the material's alpha where a surface is drawn, 0 elsewhere)
is reported with its likely cause instead of passing as a picture (issue 39: skinned Draco
meshes whose joints were read as zeros collapsed to a point and wrote a black PNG, exit 0).

The causes are told apart from the scene itself, in this order:
  - collapsed: every triangle of every mesh has zero area in world space (a skin whose
    weights are all zero, morph weights that flatten the mesh; points and lines excepted);
  - out of view: no object's bounds reach into the view frustum (render.depth_range);
  - otherwise: the geometry is in view and still covers no pixel centre (materials of
    alpha 0, culled faces, triangles thinner than a pixel).
A frame whose covered pixels are all exactly black is reported too: a scene without a light
or an environment (a glTF file without KHR_lights_punctual rendered without --environment
drew an opaque black PNG, exit 0), or lights that reach no visible surface.
"""

from __future__ import annotations

import numpy as np

from ..scene import meshes
from .depth_range import scene_frame, visible_depths


def covered_fraction(linear: np.ndarray) -> float:
    """The fraction of pixels a surface covers (alpha > 0)."""
    return float((np.asarray(linear)[..., 3] > 0).mean())


def _triangle_area(obj) -> float:
    """Total world-space area of a mesh object's triangles (inf for spheres, points, lines:
    they are not checked for collapse)."""
    if obj.sphere is not None or getattr(obj.geometry, "topology", "triangles") != "triangles":
        return np.inf
    arrays = meshes.mesh_data(obj).arrays
    world = np.asarray(arrays[0], np.float64) @ obj.transform[:3, :3].T
    corners = world[np.asarray(arrays[4]).reshape(-1, 3)]
    cross = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
    return float(np.linalg.norm(cross, axis=1).sum() / 2)


def empty_frame_reason(scene, linear: np.ndarray) -> str | None:
    """None when a covered pixel has colour; else a sentence naming why none has (module doc)."""
    linear = np.asarray(linear)
    if covered_fraction(linear) > 0:
        covered = linear[..., 3] > 0
        if np.any(linear[..., :3][covered] != 0):
            return None
        if not scene.lights and scene.environment is None:
            return ("every covered pixel is black: the scene has no light and no environment (for a glTF "
                    "file without KHR_lights_punctual, give --environment R,G,B or an image)")
        return ("every covered pixel is black: no light reaches a visible surface, and nothing visible "
                "emits (lights behind the objects, of zero intensity, or out of range)")
    if not scene.objects:
        return "the scene has no object"
    if all(_triangle_area(obj) == 0 for obj in scene.objects):
        return ("nothing drawn: every triangle has zero area (the meshes collapse: a skin whose JOINTS/WEIGHTS "
                "weigh every vertex 0, or morph weights that flatten them)")
    if visible_depths(scene, scene_frame(scene)) is None:
        return "nothing drawn: every object lies outside the camera's view (try another camera)"
    return ("nothing drawn: the objects are in view but cover no pixel (materials of alpha 0, culled faces, or "
            "triangles thinner than a pixel)")
