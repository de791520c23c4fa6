"""Float64 references of the path a ray travels inside a volume (render.volume_chord,
harness/pbrlab/render/volume_exit.py): the chord from where it enters a convex body to where
it leaves it.

KHR_materials_volume ("Thickness Texture") gives rasterisers the thickness beneath the surface
as a material value because the real distance is hard to find without tracing rays; it names
deriving the distance along the ray from the geometry as the preferred approach, and the one a
path tracer takes. These are that distance, for the two bodies the tests draw:

* a sphere: the roots of |o + t d - c|^2 = r^2 (d a unit vector), t = -b -+ sqrt(b^2 - q) with
  b = d . (o - c), q = |o - c|^2 - r^2; the chord is their difference, 2 sqrt(b^2 - q);
* a box (any affine image of the cube [-1/2, 1/2]^3: a rotated, scaled slab): the slab method
  (Kay & Kajiya 1986, "Ray Tracing Complex Scenes", SIGGRAPH, section 3), run in the box's own
  coordinates, where an affine map keeps the ray's parameter t, so t_exit - t_enter is the
  chord in world units when d is a world unit vector.

Rays that miss (or only touch) the body have chord 0. For a refracted path: the entering face's
normal (ray_box_entry_normal), Snell's direction from it (transmission.refraction_direction),
and the chord of that ray from the entry point.
"""

import numpy as np


def _f(x):
    return np.asarray(x, np.float64)


def ray_sphere_chord(origin, direction, centre, radius):
    """The length of the ray's path through the sphere (..., from unit ``direction``s)."""
    o, d, c = _f(origin), _f(direction), _f(centre)
    oc = o - c
    b = np.sum(d * oc, axis=-1)
    q = np.sum(oc * oc, axis=-1) - float(radius) ** 2
    disc = b * b - q
    return np.where(disc > 0.0, 2.0 * np.sqrt(np.maximum(disc, 0.0)), 0.0)


def _in_box(origin, direction, model):
    """The ray in the box's coordinates (``model``: world from box): origin, direction."""
    inverse = np.linalg.inv(_f(model))
    return _f(origin) @ inverse[:3, :3].T + inverse[:3, 3], _f(direction) @ inverse[:3, :3].T


def ray_box_entry_normal(origin, direction, model):
    """The world unit normal (outward) of the face where the ray enters the box: the slab
    whose entering parameter is the largest (the slab method's t_enter), its outward normal
    -sign(d) e_axis in the box's coordinates, taken to the world by the inverse transpose."""
    lo, ld = _in_box(origin, direction, model)
    with np.errstate(divide="ignore", invalid="ignore"):
        near = np.minimum((-0.5 - lo) / ld, (0.5 - lo) / ld)
    axis = np.argmax(np.where(np.isnan(near), -np.inf, near), axis=-1)
    local = -np.sign(np.take_along_axis(ld, axis[..., None], axis=-1)) * np.eye(3)[axis]
    world = local @ np.linalg.inv(_f(model))[:3, :3]   # n_world = M^-T n_local, as rows
    return world / np.linalg.norm(world, axis=-1, keepdims=True)


def ray_box_interval(origin, direction, model):
    """(t_enter, t_exit) of the ray in the box ``model`` (4x4, world from box) maps the cube
    [-1/2, 1/2]^3 onto, the ray's ``direction`` a world unit vector; t_enter is at least 0 (the
    part behind the origin is not counted); t_exit <= t_enter where the ray misses."""
    lo, ld = _in_box(origin, direction, model)   # ld not normalised: t is kept
    with np.errstate(divide="ignore", invalid="ignore"):
        t1 = (-0.5 - lo) / ld
        t2 = (0.5 - lo) / ld
    parallel = ld == 0.0
    inside = np.abs(lo) <= 0.5
    near = np.where(parallel, np.where(inside, -np.inf, np.inf), np.minimum(t1, t2))
    far = np.where(parallel, np.where(inside, np.inf, -np.inf), np.maximum(t1, t2))
    return np.maximum(near.max(axis=-1), 0.0), far.min(axis=-1)


def ray_box_chord(origin, direction, model):
    """The length of the ray's path through the box (ray_box_interval's ray and box)."""
    t_enter, t_exit = ray_box_interval(origin, direction, model)
    return np.where(t_exit > t_enter, t_exit - t_enter, 0.0)
