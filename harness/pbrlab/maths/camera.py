"""Camera maths shared by the GPU renderer and the float64 CPU renderer."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

NEAR_FAR_MARGIN = 1.05  # depth range padding around the scene bounds


@dataclass
class CameraFrame:
    position: np.ndarray
    forward: np.ndarray  # unit
    right: np.ndarray    # unit right * tan(fov/2) * aspect
    up: np.ndarray       # unit up * tan(fov/2)
    size: tuple[int, int]
    view_proj: np.ndarray  # 4x4, row-major maths (column vectors)
    view: np.ndarray       # 4x4 world to eye (GL: camera at the origin looking down -z)
    proj: np.ndarray       # 4x4 eye to clip (GL: clip z in [-w, w]); view_proj = proj @ view
    near: float            # the planes proj maps to clip z = -w and +w (eye z = -near, -far)
    far: float


def camera_frame(camera, scene_radius: float, depths: tuple[float, float] | None = None) -> CameraFrame:
    """Basis and view-projection of a scene camera. ``scene_radius`` bounds the scene
    around its camera target; ``depths``, the (nearest, farthest) eye depth of what the
    camera sees (depth_range.visible_depths), sets a perspective camera's planes around it
    (else far from the radius and near = far * 1e-5). depth_range.scene_frame chooses both."""
    w, h = camera.size
    forward = camera.target - camera.position
    forward = forward / np.linalg.norm(forward)
    right = np.cross(forward, camera.up)
    right /= np.linalg.norm(right)
    up = np.cross(right, forward)
    tan_half = math.tan(math.radians(camera.fov_y_deg) / 2)
    aspect = w / h
    distance = float(np.linalg.norm(camera.target - camera.position))
    far = (distance + scene_radius) * NEAR_FAR_MARGIN
    near = max(far * 1e-5, 1e-4)
    if depths is not None:  # the planes just around what is seen (depth_range.py: the figures)
        far = depths[1] * NEAR_FAR_MARGIN
        near = max(depths[0] / NEAR_FAR_MARGIN, far * 1e-5)
    view = np.eye(4)
    view[0, :3], view[1, :3], view[2, :3] = right, up, -forward
    view[:3, 3] = -view[:3, :3] @ camera.position
    proj = np.zeros((4, 4))
    ortho = getattr(camera, "ortho_half_height", None)
    if ortho is not None:  # orthographic (glTF 2.0, 3.10.3, with near = 0 moved to keep depth)
        near = -(distance + scene_radius) * NEAR_FAR_MARGIN
        proj[0, 0] = 1 / (ortho * aspect)
        proj[1, 1] = 1 / ortho
        proj[2, 2] = -2 / (far - near)
        proj[2, 3] = -(far + near) / (far - near)
        proj[3, 3] = 1
    else:
        proj[0, 0] = 1 / (tan_half * aspect)
        proj[1, 1] = 1 / tan_half
        proj[2, 2] = -(far + near) / (far - near)
        proj[2, 3] = -2 * far * near / (far - near)
        proj[3, 2] = -1
    return CameraFrame(camera.position.astype(np.float64), forward, right * tan_half * aspect,
                       up * tan_half, (w, h), proj @ view, view, proj, near, far)


def camera_rays(frame: CameraFrame, offset: tuple[float, float] = (0.0, 0.0)) -> np.ndarray:
    """Unit ray directions through every pixel centre, top row first: HxWx3 float64.
    Same formula as templates/surface_pixel.inc. ``offset`` moves every sample from its pixel's
    centre by that many pixels (x to the right, y down the image): a test's neighbours of a
    pixel's sample, to find the pixels whose expectation changes within a pixel."""
    w, h = frame.size
    x = (np.arange(w) + 0.5 + offset[0]) / w * 2 - 1
    y = (np.arange(h)[::-1] + 0.5 - offset[1]) / h * 2 - 1  # GL rows count from the bottom
    d = (frame.forward[None, None] + x[None, :, None] * frame.right[None, None]
         + y[:, None, None] * frame.up[None, None])
    return d / np.linalg.norm(d, axis=-1, keepdims=True)
