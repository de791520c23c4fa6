"""The unit sphere at the origin as the camera sees it, in float64, and the bound on an eye depth
read back from pbrlab's depth pre-pass: shared by the deferred path's tests and URP's scene
texture tests, which read the same texture through the same float32 chain."""

from __future__ import annotations

import numpy as np

from pbrlab.maths.camera import camera_rays
from pbrlab.render.renderer import render_scene

SILHOUETTE_MARGIN = 0.95  # rays within 0.95 of the radius: a pixel's footprint stays on the sphere
# z is stored in float32 after a few roundings (6 units of 2^-24: clip product, divide,
# * 0.5 + 0.5, store, and the ray's float32 error through the depth); 1/e is affine in z with
# slope (1/near - 1/far), so e moves by e^2 (1/near - 1/far) dz; plus 8 ulp of e for
# LinearEyeDepth's own float32 arithmetic.
K_DEPTH_ULPS = 6.0


def sphere_hits(frame):
    """(unit ray directions HxWx3, float64 distance to the unit sphere at the origin or NaN,
    mask of rays well inside the rim), top row first."""
    d = camera_rays(frame)
    o = np.asarray(frame.position, np.float64)
    b = d @ o
    closest2 = o @ o - b * b
    t = -b - np.sqrt(np.maximum(1.0 - closest2, 0.0))
    return d, np.where(closest2 <= 1.0, t, np.nan), closest2 <= SILHOUETTE_MARGIN ** 2


def depth_bound(eye, frame):
    """The bound on an eye depth read from the depth texture (the module's K_DEPTH_ULPS note)."""
    return eye ** 2 * (1 / frame.near - 1 / frame.far) * K_DEPTH_ULPS * 2.0 ** -24 + 8 * 2.0 ** -24 * eye


def rendered_sphere(scene, frame, language):
    """(linear image float64, pixels well inside the sphere and drawn, float64 eye depth there)."""
    d, t, inside = sphere_hits(frame)
    image = render_scene(scene, language=language).linear.astype(np.float64)
    covered = inside & (image[..., 3] > 0)
    assert covered.sum() > 1000
    return image, covered, t * (d @ frame.forward)
