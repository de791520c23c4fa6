"""Proof of the Cycles reference's environment orientation and exposure: a mirror sphere.

    python tools/cycles/orientation_proof.py SPEC.json OUT.f32

SPEC.json is the view spec the Cycles render OUT.f32 was made from (tools/cycles/render.py);
its glTF must be a unit sphere at the origin with a perfect mirror (metallic 1,
roughness 0, base colour 1: /work/fidelity_staging/mirror_sphere.gltf). For every pixel
this computes in float64 what the sphere shows: the camera ray, its hit on the analytic unit
sphere, the reflected direction, and the environment EXR's radiance in that direction,
looked up with pbrlab's equirect convention (harness/pbrlab/scene/environment.py:
u = atan2(x, -z) / (2 pi), v_from_top = acos(y) / pi, glTF axes) with bilinear
interpolation. A metal of base colour 1 reflects all light at every angle (Fresnel of
F0 = 1 is 1), so the expected radiance is the environment's, unscaled. The pixel is
integrated over Cycles' pixel filter on a 24x24 grid: Blackman-Harris with filter_width
1.5, which Cycles' filter_table() doubles (intern/cycles/scene/film.cpp: "width *= 2.0f" for
FILTER_BLACKMAN_HARRIS) before tabulating the window over [-width/2, width/2]: the window
reaches 1.5 px on either side of the pixel centre, 3 px in all.

Prints the relative difference |cycles - expected| / expected over the covered pixels (the
silhouette's outer 2 pixels left out: there the mesh's facets and the filter's reach differ
from the analytic sphere), for pbrlab's convention and, to show the test discriminates, for
the same lookup turned by 90, 180 and 270 degrees about +Y and mirrored; then the ratio of
the sums (exposure). Needs numpy and OpenImageIO (pbrlab's virtualenv has both).
"""

from __future__ import annotations

import json
import math
import sys
from pathlib import Path

import numpy as np


def read_exr(path: Path) -> np.ndarray:
    import OpenImageIO as oiio

    image = oiio.ImageInput.open(str(path))
    if image is None:
        raise SystemExit(f"orientation_proof.py: cannot read {path}: {oiio.geterror()}")
    pixels = image.read_image(oiio.FLOAT)
    image.close()
    return np.asarray(pixels, np.float64)[..., :3]


def lookup(env: np.ndarray, d: np.ndarray, turn: float = 0.0, mirror: bool = False) -> np.ndarray:
    """Bilinear lookup of the equirect image at unit directions d[..., 3] (glTF axes) with
    pbrlab's convention; ``turn`` (radians about +Y) and ``mirror`` give wrong variants."""
    x, y, z = d[..., 0], d[..., 1], d[..., 2]
    phi = np.arctan2(x, -z) + turn
    if mirror:
        phi = -phi
    u = np.mod(phi / (2 * np.pi), 1.0)
    v = np.arccos(np.clip(y, -1, 1)) / np.pi
    h, w = env.shape[:2]
    px, py = u * w - 0.5, v * h - 0.5  # texel centres at (i + 0.5) / size
    x0, y0 = np.floor(px).astype(int), np.floor(py).astype(int)
    fx, fy = (px - x0)[..., None], (py - y0)[..., None]
    xa, xb = np.mod(x0, w), np.mod(x0 + 1, w)            # wraps around in azimuth
    ya, yb = np.clip(y0, 0, h - 1), np.clip(y0 + 1, 0, h - 1)  # clamps at the poles
    return ((env[ya, xa] * (1 - fx) + env[ya, xb] * fx) * (1 - fy)
            + (env[yb, xa] * (1 - fx) + env[yb, xb] * fx) * fy)


def blackman_harris(x: np.ndarray, width: float) -> np.ndarray:
    """Cycles' pixel filter (intern/cycles/scene/film.cpp, filter_func_blackman_harris):
    the 4-term Blackman-Harris window over [-width/2, width/2]; Cycles passes it twice the
    user's filter_width."""
    t = 2 * np.pi * (x / width + 0.5)
    return 0.35875 - 0.48829 * np.cos(t) + 0.14128 * np.cos(2 * t) - 0.01168 * np.cos(3 * t)


FILTER_REACH = 1.5  # px either side: Cycles' filter_width 1.5, doubled by filter_table()


def expected_image(spec: dict, env: np.ndarray, grid: int = 24, **variant):
    """Filtered radiance (HxWx3) of the analytic mirror sphere and the mask of pixels whose
    whole filter footprint (3 px wide) lies on the sphere, eroded by a further 2 pixels."""
    width, height = spec["size"]
    cam = spec["camera"]
    eye, target = np.array(cam["eye"], float), np.array(cam["target"], float)
    up = np.array(cam.get("up", [0, 1, 0]), float)
    f = (target - eye) / np.linalg.norm(target - eye)
    r = np.cross(f, up); r /= np.linalg.norm(r)
    u = np.cross(r, f)
    t = math.tan(math.radians(cam["yfov_deg"]) / 2)
    offsets = ((np.arange(grid) + 0.5) / grid * 2 - 1) * FILTER_REACH
    wsum = 0.0
    total = np.zeros((height, width, 3))
    hit_all = np.ones((height, width), bool)
    jj, ii = np.mgrid[0:height, 0:width].astype(float)
    for oy in offsets:
        for ox in offsets:
            wgt = blackman_harris(ox, 2 * FILTER_REACH) * blackman_harris(oy, 2 * FILTER_REACH)
            sx = (2 * (ii + 0.5 + ox) / width - 1) * t * width / height
            sy = (1 - 2 * (jj + 0.5 + oy) / height) * t
            d = f + sx[..., None] * r + sy[..., None] * u
            d /= np.linalg.norm(d, axis=-1, keepdims=True)
            b = d @ eye
            c = eye @ eye - 1.0
            disc = b * b - c
            hit = disc > 0
            s = -b - np.sqrt(np.maximum(disc, 0))
            n = eye + s[..., None] * d
            refl = d - 2 * np.sum(d * n, -1, keepdims=True) * n
            total += wgt * lookup(env, refl, **variant)
            wsum += wgt
            hit_all &= hit
    mask = hit_all.copy()
    for _ in range(2):  # erode by 2 pixels (4-neighbourhood)
        m = mask.copy()
        m[1:] &= mask[:-1]; m[:-1] &= mask[1:]; m[:, 1:] &= mask[:, :-1]; m[:, :-1] &= mask[:, 1:]
        mask = m
    return total / wsum, mask


def main(argv: list[str]) -> int:
    if len(argv) != 2:
        raise SystemExit("usage: orientation_proof.py SPEC.json OUT.f32")
    spec = json.loads(Path(argv[0]).read_text())
    width, height = spec["size"]
    cycles = np.fromfile(argv[1], np.float32)
    if cycles.size != width * height * 4:
        raise SystemExit(f"orientation_proof.py: {argv[1]} holds {cycles.size} floats, not {width}x{height}x4")
    cycles = cycles.reshape(height, width, 4).astype(np.float64)
    env = read_exr(Path(spec["environment"]))
    print(f"{argv[1]} vs analytic mirror sphere in {Path(spec['environment']).name}, {width}x{height}")
    variants = [("pbrlab's convention", {}), ("turned 90 deg about +Y", {"turn": np.pi / 2}),
                ("turned 180 deg", {"turn": np.pi}), ("turned 270 deg", {"turn": 3 * np.pi / 2}),
                ("mirrored in azimuth", {"mirror": True})]
    for name, variant in variants:
        expected, mask = expected_image(spec, env, **variant)
        c, e = cycles[..., :3][mask], expected[mask]
        rel = np.abs(c - e) / np.maximum(e, 1e-6)
        line = (f"  {name:24s} pixels {mask.sum():6d}  rel. diff median {np.median(rel):.5f}  "
                f"p99 {np.percentile(rel, 99):.4f}")
        if not variant:
            ratio = c.sum(0) / e.sum(0)
            lum = e.mean(1)
            dim = lum < np.percentile(lum, 99)  # the sun's few pixels dominate the sums and their noise
            ratio_dim = c[dim].sum(0) / e[dim].sum(0)
            alpha = cycles[..., 3][mask]
            line += (f"\n  exposure: sum(cycles)/sum(expected) per channel {ratio.round(5).tolist()}, "
                     f"without the brightest 1% of pixels {ratio_dim.round(5).tolist()}, "
                     f"median of cycles/expected {np.median(c / np.maximum(e, 1e-6)):.5f}; "
                     f"alpha on the sphere min {alpha.min():.5f}; alpha off the sphere max "
                     f"{cycles[..., 3][~_near(mask, 8)].max():.5f}")
        print(line)
    return 0


def _near(mask: np.ndarray, pixels: int) -> np.ndarray:
    """The mask grown by ``pixels`` (4-neighbourhood)."""
    m = mask.copy()
    for _ in range(pixels):
        g = m.copy()
        g[1:] |= m[:-1]; g[:-1] |= m[1:]; g[:, 1:] |= m[:, :-1]; g[:, :-1] |= m[:, 1:]
        m = g
    return m


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
