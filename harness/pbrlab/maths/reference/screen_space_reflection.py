"""Float64 references of the screen-space reflections (render.screen_space_reflections:
harness/pbrlab/render/screen_space_reflection.py, templates/screen_space_reflection.inc).

* ``hit_weight``: the weight a hit at screen position uv (0..1) gets for a lobe of perceptual
  roughness r: clamp(2 - 2 r / 0.6, 0, 1) (1 up to 0.3, 0 from 0.6) times the screen-edge vignette
  clamp(1 - |s|^2, 0, 1), s = clamp(5 |2 uv - 1| - 4, 0, 1) per axis (1 inside 80 % of the screen).
  The rule is Unreal Engine 4's SSR (ScreenSpaceReflections.usf: GetRoughnessFade with its
  default r.SSR.MaxRoughness 0.6, and ComputeHitVignetteFromScreenPos), written here from its
  formulas.
* ``mirror_plane_reflection``: the geometry of the tests' scene, a mirror plane y = height
  (normal +y) reflecting a box (any affine image of the unit cube): per camera ray, where it meets the plane,
  the direction the environment read takes there (the mirror direction leant towards the normal
  by alpha: dominant_direction.specular_dominant_direction) and where that ray meets the box
  (volume_chord.ray_box_interval, the slab method).
"""

from __future__ import annotations

import numpy as np

from . import dominant_direction, volume_chord

MAX_ROUGHNESS = 0.6


def hit_weight(uv, perceptual_roughness):
    uv = np.asarray(uv, np.float64)
    roughness_fade = np.clip(2.0 - 2.0 * np.asarray(perceptual_roughness, np.float64) / MAX_ROUGHNESS, 0.0, 1.0)
    s = np.clip(np.abs(2.0 * uv - 1.0) * 5.0 - 4.0, 0.0, 1.0)
    return roughness_fade * np.clip(1.0 - np.sum(s * s, axis=-1), 0.0, 1.0)


def mirror_plane_reflection(origin, direction, height, box_model, alpha):
    """Per ray (origin, unit direction, ...x3): (on_plane, p, d, hits_box, q): whether the ray
    meets the plane y = height from above, the point p, the read direction d there, whether the
    ray p + t d (t > 0) meets the box ``box_model`` (world from the cube [-1/2, 1/2]^3) and
    where it enters it, q."""
    o, v = np.asarray(origin, np.float64), np.asarray(direction, np.float64)
    with np.errstate(divide="ignore", invalid="ignore"):
        t = (height - o[..., 1]) / v[..., 1]
    on_plane = (v[..., 1] < 0.0) & (t > 0.0)
    p = o + np.where(on_plane, t, 0.0)[..., None] * v
    n = np.broadcast_to(np.array([0.0, 1.0, 0.0]), p.shape)
    r = v - 2.0 * v[..., 1:2] * n               # reflect(v, n): v the incoming ray
    d = dominant_direction.specular_dominant_direction(n, r, alpha)
    t_enter, t_exit = volume_chord.ray_box_interval(p, d, box_model)
    hits_box = on_plane & (t_exit > t_enter) & (t_enter > 0.0)
    return on_plane, p, d, hits_box, p + t_enter[..., None] * d
