"""The staging check: does every renderer see the same environment, the same way up, at the
same brightness? A mirror sphere and a diffuse sphere (spheres.py) rendered by each renderer
are compared in LINEAR with what the environment image itself predicts, computed here in
float64 independently of every renderer:

* mirror: per pixel, the camera ray meets the unit sphere at n; the mirror shows the
  environment in the reflected direction reflect(d, n) (pbrlab's equirect convention,
  scene/environment.py; bilinear between texel centres, wrapping in u);
* diffuse (white, roughness 1): Lambert's irradiance over pi, E(n)/pi = (1/pi) sum L cos
  dOmega over the environment's texels (box-averaged 8x8 first: the cosine lobe is smooth,
  so this moves E by far less than the renderers' differences). A renderer whose rough
  dielectric is not Lambertian (Cycles' Principled BSDF at roughness 1, with its specular
  layer) differs by its own model: reported, not a staging fault.

Orientation faults show as a mirror error of tens of percent (a 90 degree turn of the sky),
exposure faults as a diffuse ratio away from 1. Figures over the pixels whose normal faces
the camera (n.v > COS_LIMIT): the silhouette's grazing reflections depend on each renderer's
tessellation and filtering, not on staging.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from ...foundation import images
from . import renderers, spheres, staging

COS_LIMIT = 0.5          # pixels whose surface faces the camera within 60 degrees
VIEWS = {"front": [0.0, 0.0, 4.0], "side": [4.0, 0.0, 0.0], "above": [0.0, 4.0, 0.001]}
SIZE = (128, 128)
BOX = 8                  # texels averaged per side before the irradiance sum


def _rays(camera: dict, size) -> tuple[np.ndarray, np.ndarray]:
    """Eye and unit ray directions through pixel centres (rows top to bottom)."""
    eye, target, up = (np.asarray(camera[k], np.float64) for k in ("eye", "target", "up"))
    forward = (target - eye) / np.linalg.norm(target - eye)
    right = np.cross(forward, up)
    right /= np.linalg.norm(right)
    true_up = np.cross(right, forward)
    w, h = size
    tan_half = math.tan(math.radians(camera["yfov_deg"]) / 2)
    x = ((np.arange(w) + 0.5) / w * 2 - 1) * tan_half * w / h
    y = (1 - (np.arange(h) + 0.5) / h * 2) * tan_half
    d = forward + x[None, :, None] * right + y[:, None, None] * true_up
    return eye, d / np.linalg.norm(d, axis=-1, keepdims=True)


def _sphere_hits(eye, d):
    """Unit-sphere hit points (NaN where missed) of rays eye + t d."""
    b = d @ eye
    disc = b * b - (eye @ eye - 1.0)
    t = -b - np.sqrt(np.where(disc > 0, disc, np.nan))
    return eye + t[..., None] * d


def equirect_lookup(image: np.ndarray, directions: np.ndarray) -> np.ndarray:
    """Bilinear radiance of an equirect (pbrlab's convention) at unit directions."""
    h, w = image.shape[:2]
    u = (np.arctan2(directions[..., 0], -directions[..., 2]) / (2 * np.pi)) % 1.0
    v = np.arccos(np.clip(directions[..., 1], -1, 1)) / np.pi
    x, y = u * w - 0.5, np.clip(v * h - 0.5, 0, h - 1)
    x0, y0 = np.floor(x).astype(int), np.floor(y).astype(int)
    fx, fy = (x - x0)[..., None], (y - y0)[..., None]
    y1 = np.minimum(y0 + 1, h - 1)
    x0w, x1w = x0 % w, (x0 + 1) % w
    top = image[y0, x0w] * (1 - fx) + image[y0, x1w] * fx
    bottom = image[y1, x0w] * (1 - fx) + image[y1, x1w] * fx
    return top * (1 - fy) + bottom * fy


def irradiance_over_pi(image: np.ndarray, normals: np.ndarray) -> np.ndarray:
    """(1/pi) sum over texels of L max(0, n.w) dOmega, the image box-averaged BOX x BOX first."""
    from ...scene.environment import equirect_directions

    h, w = image.shape[0] // BOX, image.shape[1] // BOX
    coarse = image[:h * BOX, :w * BOX].reshape(h, BOX, w, BOX, 3).mean(axis=(1, 3))
    dirs, solid = equirect_directions(h, w)
    dirs, weighted = dirs.reshape(-1, 3), (coarse * solid[..., None]).reshape(-1, 3)
    flat = normals.reshape(-1, 3)
    out = np.empty_like(flat)
    for start in range(0, len(flat), 4096):
        cos = np.maximum(flat[start:start + 4096] @ dirs.T, 0.0)
        out[start:start + 4096] = cos @ weighted / np.pi
    return out.reshape(normals.shape)


def predicted(kind: str, environment: np.ndarray, camera: dict, size=SIZE):
    """What the environment predicts at each pixel (HxWx3, NaN off the sphere) and the mask
    of the pixels scored."""
    eye, d = _rays(camera, size)
    n = _sphere_hits(eye, d)
    hit = ~np.isnan(n[..., 0])
    facing = np.nan_to_num(-(n * d).sum(-1), nan=-1.0) > COS_LIMIT
    n = np.where(hit[..., None], n, np.array([0.0, 1.0, 0.0]))
    if kind == "mirror_sphere":
        r = d - 2 * (d * n).sum(-1, keepdims=True) * n
        return equirect_lookup(environment, r), facing, hit
    return irradiance_over_pi(environment, n), facing, hit


def compare(linear: np.ndarray, expected: np.ndarray, mask: np.ndarray, hit: np.ndarray) -> dict:
    """Luminance errors over the mask, relative to the prediction's mean there (a dark studio
    wall beside a lamp makes per-pixel relative errors meaningless), the ratio of the means,
    and the pixels whose coverage disagrees with the sphere's disc."""
    lum = np.array([0.2126, 0.7152, 0.0722])
    got, want = linear[..., :3].astype(np.float64) @ lum, expected @ lum
    covered = mask & (linear[..., 3] > 0.5)
    if not covered.any():
        return {"pixels": 0, "coverage_mismatch": int((hit != (linear[..., 3] > 0.5)).sum()),
                "median_err": math.nan, "p90_err": math.nan, "mean_ratio": math.nan}
    scale = want[covered].mean()
    err = np.abs(got[covered] - want[covered]) / scale
    return {"pixels": int(covered.sum()), "coverage_mismatch": int((hit != (linear[..., 3] > 0.5)).sum()),
            "median_err": float(np.median(err)), "p90_err": float(np.percentile(err, 90)),
            "mean_ratio": float(got[covered].mean() / scale)}


def run(renderer_names=("pbrlab",), lightings=("sunrise",), folder: Path = Path("out/fidelity/staging"),
        log=print) -> list[dict]:
    """Every renderer x lighting x sphere x view: compare() against the prediction."""
    folder = Path(folder)
    models = spheres.write_spheres(folder / "models")
    rows = []
    for lighting in lightings:
        environment = staging.prepare_environment(lighting, folder / "environments")
        radiance = images.read_image(environment["environment"])[..., :3].astype(np.float64)
        for kind, model in models.items():
            for view_name, eye in VIEWS.items():
                camera = {"eye": eye, "target": [0.0, 0.0, 0.0], "up": [0.0, 1.0, 0.0], "yfov_deg": 45.0,
                          "znear": 0.01, "zfar": 20.0}
                view = {"gltf": str(model), **environment, "size": list(SIZE), "camera": camera,
                        "samples": 64, "seed": 0, "denoise": False}
                expected, mask, hit = predicted(kind, radiance, camera)
                for name in renderer_names:
                    linear, _ = renderers.render(name, view)
                    row = {"renderer": name, "lighting": lighting, "sphere": kind, "view": view_name,
                           **compare(linear, expected, mask, hit)}
                    log(" ".join(f"{k}={v:.4f}" if isinstance(v, float) else f"{k}={v}" for k, v in row.items()))
                    rows.append(row)
    return rows
