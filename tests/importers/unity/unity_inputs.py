"""Inputs for the unity-model tests: the full parameter ranges with Unity's hard corners."""

import numpy as np


def unit(v):
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def lighting_inputs(rng, n):
    """Random surfaces, directions and light over the full ranges, with fixed shares of the
    corners: dark metals (albedo 0.02..1, metallic 1), smoothness exactly 0 and 1, grazing
    view and light, V = -L and mirror configurations. Normals are tilted off +z (unit)."""
    normal = unit(rng.normal(size=(n, 3)) * 0.3 + [0.0, 0.0, 1.0])
    v = unit(rng.normal(size=(n, 3)))
    v = np.where(np.sum(v * normal, -1, keepdims=True) < 0, -v, v)  # visible side (Unity takes |n.v| anyway)
    l = unit(rng.normal(size=(n, 3)))
    albedo = rng.uniform(0.0, 1.0, (n, 3))
    metallic = rng.uniform(0.0, 1.0, n)
    smoothness = rng.uniform(0.0, 1.0, n)
    k = n // 10
    metallic[:k] = 1.0                                           # dark to bright metals
    albedo[:k] = rng.uniform(0.02, 1.0, (k, 1)) * rng.uniform(0.5, 1.0, (k, 3))
    smoothness[k:2 * k] = 1.0
    smoothness[2 * k:3 * k] = 0.0
    # grazing view: n.v in [0, 1e-3]
    t = slice(3 * k, 4 * k)
    tangent = unit(np.cross(normal[t], rng.normal(size=(k, 3))))
    v[t] = unit(tangent + normal[t] * rng.uniform(0.0, 1e-3, (k, 1)))
    # V = -L exactly
    l[4 * k:5 * k] = -v[4 * k:5 * k]
    # mirror: l = reflect(-v, n), the peak of every lobe
    m = slice(5 * k, 6 * k)
    l[m] = unit(2.0 * np.sum(normal[m] * v[m], -1, keepdims=True) * normal[m] - v[m])
    # grazing light
    g = slice(6 * k, 7 * k)
    tangent = unit(np.cross(normal[g], rng.normal(size=(k, 3))))
    l[g] = unit(tangent + normal[g] * rng.uniform(0.0, 1e-3, (k, 1)))
    return dict(normal=normal, v=v, l=l, albedo=albedo, metallic=metallic, smoothness=smoothness,
                occlusion=rng.uniform(0.0, 1.0, n), light=rng.uniform(0.0, 2.0, (n, 3)),
                idiff=rng.uniform(0.0, 1.0, (n, 3)), ispec=rng.uniform(0.0, 2.0, (n, 3)))


def pixel_rays(camera, size, offset=(0.0, 0.0)):
    """(eye, unit ray directions HxWx3) of a test scene's camera dict (position, target,
    fov_y_deg; up +y) at size (h, w), each ray through its pixel's centre moved by ``offset``
    pixels: the renderer's own ray formula (maths.camera.camera_rays), in float64."""
    from types import SimpleNamespace
    from pbrlab.maths.camera import camera_frame, camera_rays
    eye = np.array(camera["position"], np.float64)
    frame = camera_frame(SimpleNamespace(position=eye, target=np.array(camera["target"], np.float64),
                                         up=np.array([0.0, 1.0, 0.0]), fov_y_deg=camera["fov_y_deg"],
                                         size=(size[1], size[0])), 1.0)
    return eye, camera_rays(frame, offset)
