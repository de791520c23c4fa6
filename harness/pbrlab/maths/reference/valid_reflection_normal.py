"""Float64 valid-reflection normal: a normal-mapped shading normal bent until the view's
mirror reflection stays just above the geometric surface.

Keller et al. 2017, "The Iray Light Transport Simulation and Rendering System" (arXiv
1705.01263), section on bump and normal maps: a shading normal n whose mirror reflection of
the view v falls below the geometric surface (r.Ng < 0, r = 2 (n.v) n - v) sends light
through the object; they replace n by the n' in the plane of n and Ng whose reflection lies
at a small height t above the surface. Cycles (intern/cycles/kernel/closure/bsdf_util.h,
``ensure_valid_specular_reflection``; applied to its glossy closures where the shading normal
differs from Ng) takes t = min(0.9 (v.Ng), 0.01): a reflection may always be as shallow as the
view, and at most 0.01 above the plane. n is unchanged where r.Ng >= t already.

Two float64 forms of the same n' (glsl/pbr/shading/valid_reflection_normal.glsl is tested
against both):

* ``valid_reflection_normal``: the closed form. In the frame with Ng as z and n in the x-z
  plane (x = the part of n across Ng, normalised), n' = (sqrt(1 - z^2), 0, z) must satisfy
  2 (n'.v) z - v.z = t; squared, 4 a z^4 - 2 b z^2 + c = 0 with a = vx^2 + vz^2,
  b = 2 (a + vz t), c = (vz + t)^2, and of its roots the one that solves the unsquared
  equation: z^2 = (b + sqrt(b^2 - 4ac)) / 4a where vx < 0, (b - sqrt(...)) / 4a otherwise
  (Cycles' derivation, re-derived here). Written without cancellation: the second as
  c / (b + sqrt(...)) (the roots' product is c / 4a), and x'^2 = u = 1 - z^2 from its own
  quadratic 4a u^2 - 2B u + C = 0, B = 2 (a - vz t), C = (vz - t)^2 (the same discriminant):
  (vz - t)^2 / (B + sqrt(...)) where vx < 0, (B + sqrt(...)) / 4a otherwise (at a grazing view
  1 - z^2 is ~vz^2 and would keep none of its digits).
* ``valid_reflection_normal_bisection``: no algebra: the angle of n' from Ng in that plane,
  found by bisection on the height of its reflection, which rises monotonically as n' turns
  from n towards Ng over the range where it is needed (checked by the tests).
"""

from __future__ import annotations

import numpy as np

THRESHOLD_SCALE = 0.9      # Cycles: the reflection may be as shallow as 0.9 of the view's elevation
THRESHOLD_MAX = 0.01       # ... and at most 0.01 (cosine) above the plane


def _unit(x):
    return x / np.linalg.norm(x, axis=-1, keepdims=True)


def threshold(VdotNg):
    """The height t above the geometric plane a reflection must reach: min(0.9 v.Ng, 0.01),
    the view's elevation taken as at least 0 (a view just below an interpolated normal's
    plane: t = 0, the reflection brought to the plane)."""
    return np.minimum(THRESHOLD_SCALE * np.maximum(VdotNg, 0.0), THRESHOLD_MAX)


def _frame(n, ng):
    """x: n's part across ng, normalised (n itself where n is along ng)."""
    across = n - np.sum(n * ng, -1, keepdims=True) * ng
    length = np.linalg.norm(across, axis=-1, keepdims=True)
    return np.where(length > 0, across / np.where(length > 0, length, 1.0), n)


def valid_reflection_normal(n, ng, v):
    """n' for unit n, ng, v (arrays (..., 3), float64), by the closed form."""
    n, ng, v = (np.asarray(x, np.float64) for x in (n, ng, v))
    n, ng, v = np.broadcast_arrays(n, ng, v)
    r = 2.0 * np.sum(n * v, -1, keepdims=True) * n - v
    vz = np.maximum(np.sum(v * ng, -1), 0.0)   # a view behind the plane taken as on it
    t = threshold(vz)
    keep = np.sum(r * ng, -1) >= t
    x = _frame(n, ng)
    vx = np.sum(v * x, -1)
    a = vx * vx + vz * vz
    b = 2.0 * (a + vz * t)
    c = (t + vz) ** 2
    root = np.sqrt(np.maximum(b * b - 4.0 * a * c, 0.0))
    # w = z^2 and u = 1 - w, each in the form without cancellation (the module docstring)
    big_b = 2.0 * (a - vz * t)
    safe_a = np.where(a > 0, a, 1.0)
    w = np.where(vx < 0, (b + root) / (4.0 * safe_a), c / np.maximum(b + root, 1e-300))
    u = np.where(vx < 0, (vz - t) ** 2 / np.maximum(big_b + root, 1e-300), (big_b + root) / (4.0 * safe_a))
    bent = np.sqrt(np.clip(u, 0.0, 1.0))[..., None] * x + np.sqrt(np.clip(w, 0.0, 1.0))[..., None] * ng
    return np.where(keep[..., None], n, bent)


def reflection_height(n, ng, v):
    """r.Ng for r = reflect(-v, n) = 2 (n.v) n - v."""
    return np.sum((2.0 * np.sum(n * v, -1, keepdims=True) * n - v) * ng, -1)


def valid_reflection_normal_bisection(n, ng, v, steps: int = 80):
    """n' for one (n, ng, v) (each (3,)), by bisection on the angle from n towards ng in
    their plane: the smallest turn that lifts the reflection to the threshold."""
    n, ng, v = (np.asarray(x, np.float64) for x in (n, ng, v))
    t = float(threshold(v @ ng))
    if reflection_height(n, ng, v) >= t:
        return n
    x = _frame(n[None], ng[None])[0]
    start = np.arctan2(n @ x, n @ ng)          # n's angle from ng, towards x

    def at(angle):
        return np.sin(angle) * x + np.cos(angle) * ng

    lo, hi = 0.0, start                         # ng itself reflects v to v.Ng >= t
    for _ in range(steps):
        mid = 0.5 * (lo + hi)
        if reflection_height(at(mid), ng, v) >= t:
            lo = mid
        else:
            hi = mid
    return at(lo)
