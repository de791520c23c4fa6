#!/usr/bin/env python3
"""Orientation and exposure check of the fidelity benchmark's real-time peers (issue 38).

Renders a mirror sphere (metallic 1, roughness 0) and a white diffuse sphere (metallic 0,
roughness 1), unit spheres at the origin, with a peer (tools/threejs_gltf/render.mjs or
tools/sample_viewer/render.mjs) under an equirect environment, from three cameras (+Z, +X and
above), and compares each image with a numpy reference that uses pbrlab's equirect convention
(/work/fidelity_spec.md, harness/pbrlab/scene/environment.py):

    u = atan2(d.x, -d.z) / 2pi wrapped to [0, 1),  v_from_top = acos(d.y) / pi.

Mirror sphere: per pixel, the camera ray, its hit on the unit sphere, the reflected direction
and a bilinear lookup of the EXR along it (Fresnel is 1 for a metal of base colour 1, and a
split-sum's scale plus bias is 1 at roughness 0). Diffuse sphere: the cosine-weighted
irradiance of the EXR along the normal over pi (an albedo-1 Lambertian surface), summed over
the EXR averaged down to 128 x 64 texels; the peer's F0 = 0.04 specular and its own diffuse
model make this an approximation of a few per cent. Reported: the median and 99th percentile
over covered pixels (the analytic disc less its outer 2 pixels) of the relative difference
|peer - ref|_1 / |ref|_1 (RGB), the median of the per-pixel ratio peer / ref (RGB sums: the
exposure, robust to a sun the peer blurs), the ratio of the means over the disc, and, for the mirror
sphere, the environment turn (about +Y, and with u or v mirrored) that would fit the peer
best: it must come out at 0 degrees, unmirrored, for the peer to see pbrlab's sky.

    /work/main/.venv/bin/python tools/threejs_gltf/check_orientation.py --peer threejs
    /work/main/.venv/bin/python tools/threejs_gltf/check_orientation.py --peer sample_viewer \
        --environment /work/fidelity_staging/sunrise.exr --size 128 --out /tmp/orientation

Measured (sunrise.exr, 96 x 96, SwiftShader; median / p99 relative difference, median ratio):
  three.js r187, turn -90 deg:   mirror 0.052/1.15/1.008 (+Z), 0.047/1.25/1.004 (+X),
      0.023/0.90/1.004 (top); diffuse 0.017/0.13/1.015, 0.003/0.22/1.003, 0.034/0.26/1.034
  gltf-viewer 1.1.0, 90 deg:     mirror 0.020/0.73/0.996, 0.016/0.77/0.996, 0.008/0.33/0.996;
      diffuse 0.067/0.20/0.977, 0.042/0.37/1.037, 0.068/0.23/0.990 (Lambertian 2048 samples)
  best-fitting extra turn for every mirror view of both: 0 deg, unmirrored.

The .hdr twin the Sample Viewer reads is the EXR's path with the suffix .hdr (the view spec's
environment_hdr). Needs numpy, OpenImageIO, node and the peers' node_modules.
"""
from __future__ import annotations

import argparse
import json
import math
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import OpenImageIO as oiio

TOOLS = Path(__file__).resolve().parent.parent
PEERS = {"threejs": TOOLS / "threejs_gltf" / "render.mjs",
         "sample_viewer": TOOLS / "sample_viewer" / "render.mjs"}
STAGING = Path("/work/fidelity_staging")
# (name, eye): +Z, +X, and from above (a hair off the pole so that up = +Y stays usable)
VIEWS = [("front_z", [0.0, 0.0, 4.0]), ("side_x", [4.0, 0.0, 0.0]), ("top_y", [0.0, 4.0, 0.001])]
YFOV_DEG = 35.0
EDGE_PX = 2


def read_exr(path: Path) -> np.ndarray:
    image = oiio.ImageInput.open(str(path))
    if image is None:
        raise SystemExit(f"{path}: {oiio.geterror()}")
    pixels = image.read_image("float")
    image.close()
    if pixels is None or pixels.ndim != 3 or pixels.shape[2] < 3:
        raise SystemExit(f"{path}: expected an RGB(A) image")
    return np.asarray(pixels[:, :, :3], np.float64)


def camera_rays(eye, target, up, yfov_deg, width, height) -> np.ndarray:
    """Unit ray directions (H, W, 3) through pixel centres, rows top to bottom (the basis of
    three.js's lookAt and of the view spec: right = forward x up, up' = right x forward)."""
    eye, target, up = (np.asarray(x, np.float64) for x in (eye, target, up))
    forward = target - eye
    forward /= np.linalg.norm(forward)
    right = np.cross(forward, up)
    right /= np.linalg.norm(right)
    true_up = np.cross(right, forward)
    t = math.tan(math.radians(yfov_deg) / 2)
    xs = ((np.arange(width) + 0.5) / width * 2 - 1) * t * width / height
    ys = (1 - (np.arange(height) + 0.5) / height * 2) * t
    d = forward + xs[None, :, None] * right + ys[:, None, None] * true_up
    return d / np.linalg.norm(d, axis=-1, keepdims=True)


def sphere_hits(eye, rays):
    """Hit points on the unit sphere at the origin and the mask of rays that hit."""
    o = np.asarray(eye, np.float64)
    b = rays @ o
    disc = b * b - (o @ o - 1.0)
    hit = disc > 0
    t = -b - np.sqrt(np.where(hit, disc, 0.0))
    return o + t[..., None] * rays, hit


def direction_uv(d, turn_deg=0.0, mirror_u=False, flip_v=False):
    """pbrlab's equirect coordinates of unit directions, optionally perturbed (for the scan)."""
    u = np.arctan2(d[..., 0], -d[..., 2]) / (2 * np.pi)
    if mirror_u:
        u = -u
    u = np.mod(u + turn_deg / 360.0, 1.0)
    v = np.arccos(np.clip(d[..., 1], -1, 1)) / np.pi
    return u, (1 - v) if flip_v else v


def bilinear(env, u, v):
    h, w, _ = env.shape
    x = u * w - 0.5
    y = np.clip(v * h - 0.5, 0, h - 1)
    x0, y0 = np.floor(x).astype(int), np.floor(y).astype(int)
    fx, fy = (x - x0)[..., None], (y - y0)[..., None]
    x0m, x1m = np.mod(x0, w), np.mod(x0 + 1, w)
    y1 = np.minimum(y0 + 1, h - 1)
    return ((1 - fy) * ((1 - fx) * env[y0, x0m] + fx * env[y0, x1m])
            + fy * ((1 - fx) * env[y1, x0m] + fx * env[y1, x1m]))


def irradiance_over_pi(env, normals, small=(64, 128)):
    """E(n) / pi for unit normals (N, 3): the EXR area-averaged to `small` texels, each texel a
    direction (pbrlab's convention) with its solid angle, summed with max(0, n . w)."""
    h, w, _ = env.shape
    sh, sw = small
    if h % sh or w % sw:
        raise SystemExit(f"the environment's size {w}x{h} is not a multiple of {sw}x{sh}")
    coarse = env.reshape(sh, h // sh, sw, w // sw, 3).mean(axis=(1, 3))
    theta = (np.arange(sh) + 0.5) / sh * np.pi            # from +Y
    phi = (np.arange(sw) + 0.5) / sw * 2 * np.pi           # from -Z towards +X
    st = np.sin(theta)[:, None]
    dirs = np.stack([st * np.sin(phi)[None, :], np.cos(theta)[:, None] * np.ones((1, sw)),
                     -st * np.cos(phi)[None, :]], axis=-1).reshape(-1, 3)
    weight = (coarse * (np.sin(theta) * (np.pi / sh) * (2 * np.pi / sw))[:, None, None]).reshape(-1, 3)
    out = np.empty((len(normals), 3))
    for i in range(0, len(normals), 4096):
        cos = np.maximum(normals[i:i + 4096] @ dirs.T, 0.0)
        out[i:i + 4096] = cos @ weight
    return out / np.pi


def erode(mask, px):
    m = mask.copy()
    for _ in range(px):
        inner = m.copy()
        inner[1:] &= m[:-1]
        inner[:-1] &= m[1:]
        inner[:, 1:] &= m[:, :-1]
        inner[:, :-1] &= m[:, 1:]
        m = inner
    return m


def relative_stats(peer_rgb, ref_rgb):
    rel = np.abs(peer_rgb - ref_rgb).sum(-1) / np.maximum(np.abs(ref_rgb).sum(-1), 1e-12)
    return float(np.median(rel)), float(np.percentile(rel, 99))


def compare(env, spec, image, material):
    """Statistics of one peer image (H, W, 4) against the reference for its spec."""
    width, height = spec["size"]
    cam = spec["camera"]
    rays = camera_rays(cam["eye"], cam["target"], cam["up"], cam["yfov_deg"], width, height)
    hits, mask = sphere_hits(cam["eye"], rays)
    inner = erode(mask, EDGE_PX)
    normals = hits[inner]
    peer = image[inner][:, :3].astype(np.float64)
    alpha = image[..., 3]
    result = {"pixels": int(inner.sum()),
              "alpha_min_inner": float(alpha[inner].min()),
              "alpha_max_outside": float(alpha[~mask].max()) if (~mask).any() else 0.0}
    if material == "mirror":
        d = rays[inner]
        reflected = d - 2 * (d * normals).sum(-1, keepdims=True) * normals

        def reference(**perturb):
            return bilinear(env, *direction_uv(reflected, **perturb))
        ref = reference()
        scan = []
        for mirror_u in (False, True):
            for flip_v in (False, True):
                for turn in range(0, 360, 5):
                    med, _ = relative_stats(peer, reference(turn_deg=turn, mirror_u=mirror_u, flip_v=flip_v))
                    scan.append((med, turn, mirror_u, flip_v))
        scan.sort()
        result["best_fits"] = [{"median": round(m, 4), "turn_deg": t, "mirror_u": mu, "flip_v": fv}
                               for m, t, mu, fv in scan[:3]]
    else:
        ref = irradiance_over_pi(env, normals)
    result["median_rel"], result["p99_rel"] = relative_stats(peer, ref)
    result["mean_ratio_rgb"] = [float(x) for x in peer.mean(0) / ref.mean(0)]
    # exposure, robust to a sun that the peer blurs: the median of per-pixel RGB-sum ratios
    result["median_ratio"] = float(np.median(peer.sum(-1) / np.maximum(ref.sum(-1), 1e-12)))
    return result


def read_f32(prefix: Path, width, height):
    pixels = np.fromfile(prefix.with_suffix(".f32"), np.float32)
    if pixels.size != width * height * 4:
        raise SystemExit(f"{prefix}.f32: {pixels.size} floats, expected {width * height * 4}")
    return pixels.reshape(height, width, 4)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--peer", choices=sorted(PEERS), required=True)
    parser.add_argument("--environment", type=Path, default=STAGING / "sunrise.exr")
    parser.add_argument("--size", type=int, default=96, help="square image size in pixels (default 96)")
    parser.add_argument("--out", type=Path, default=Path("/tmp/pbrlab-orientation"))
    parser.add_argument("--extra", default="{}", help="JSON merged into every view spec (e.g. '{\"msaa\": 0}')")
    args = parser.parse_args(argv)
    env_path = args.environment.resolve()
    env = read_exr(env_path)
    args.out.mkdir(parents=True, exist_ok=True)
    report = {"peer": args.peer, "environment": str(env_path), "size": args.size, "renders": {}}
    for material in ("mirror", "diffuse"):
        gltf = STAGING / f"{material}_sphere.gltf"
        for view, eye in VIEWS:
            name = f"{args.peer}_{material}_{view}"
            spec = {"gltf": str(gltf), "environment": str(env_path),
                    "environment_hdr": str(env_path.with_suffix(".hdr")), "size": [args.size, args.size],
                    "camera": {"eye": eye, "target": [0, 0, 0], "up": [0, 1, 0], "yfov_deg": YFOV_DEG,
                               "znear": 0.1, "zfar": 100.0}}
            spec.update(json.loads(args.extra))
            spec_path = args.out / f"{name}.spec.json"
            spec_path.write_text(json.dumps(spec), encoding="utf-8")
            t0 = time.time()
            run = subprocess.run(["node", str(PEERS[args.peer]), str(spec_path), str(args.out / name)],
                                 capture_output=True, text=True)
            if run.returncode != 0:
                raise SystemExit(f"{args.peer} failed on {name}:\n{run.stderr.strip() or run.stdout.strip()}")
            stats = compare(env, spec, read_f32(args.out / name, args.size, args.size), material)
            stats["seconds"] = round(time.time() - t0, 2)
            report["renders"][name] = stats
            fits = stats.get("best_fits", [{}])[0]
            print(f"{name:36s} median {stats['median_rel']:.4f}  p99 {stats['p99_rel']:.4f}  "
                  f"median ratio {stats['median_ratio']:.4f}  "
                  f"mean ratio {' '.join(f'{r:.4f}' for r in stats['mean_ratio_rgb'])}"
                  + (f"  best fit: turn {fits['turn_deg']} mirror_u {fits['mirror_u']} flip_v {fits['flip_v']}"
                     if fits else ""), flush=True)
    (args.out / f"{args.peer}_report.json").write_text(json.dumps(report, indent=1), encoding="utf-8")
    oriented = all(r["best_fits"][0]["turn_deg"] == 0 and not r["best_fits"][0]["mirror_u"]
                   and not r["best_fits"][0]["flip_v"] for r in report["renders"].values() if "best_fits" in r)
    print(f"orientation {'matches' if oriented else 'DOES NOT match'} pbrlab's; report: {args.out / (args.peer + '_report.json')}")
    return 0 if oriented else 1


if __name__ == "__main__":
    sys.exit(main())
