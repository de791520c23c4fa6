"""Generates the example scenes' assets (committed next to this script; run it again to
rebuild them byte for byte): procedural brick textures (albedo and emission as sRGB
colour, normal and metallic/smoothness as linear data), a leaf with an alpha cut-out, an
HDR sky (equirectangular EXR), a UV-mapped cushion model (OBJ), and an RGBM-encoded baked
lightmap (8-bit RGBA: the Unity corpus scene's supplied lightmap, importers/unity/lightmaps.py)
and a realtime GI lightmap (float EXR: its supplied realtime lightmap, importers/unity/dynamic_lightmaps.py).

    .venv/bin/python scenes/assets/make_assets.py
"""

from pathlib import Path

import numpy as np

from pbrlab.foundation import images
from pbrlab.maths.reference.color import linear_to_srgb

HERE = Path(__file__).resolve().parent
SIZE = 128


def _srgb8(linear):
    return np.round(linear_to_srgb(np.clip(linear, 0, 1)) * 255).astype(np.uint8)


def bricks():
    """Running-bond bricks: 4 rows of 2 bricks per tile, mortar 1/16 of a brick high."""
    v, u = np.meshgrid((np.arange(SIZE) + 0.5) / SIZE, (np.arange(SIZE) + 0.5) / SIZE, indexing="ij")
    row = np.floor(v * 4)
    bu = (u * 2 + 0.5 * (row % 2)) % 1.0
    bv = (v * 4) % 1.0
    mortar_dist = np.minimum(np.minimum(bu, 1 - bu) * 2, np.minimum(bv, 1 - bv))  # in brick heights
    height = np.clip(mortar_dist / 0.08, 0, 1)  # bricks stand out of the mortar
    rng = np.random.default_rng(3)
    tint = rng.uniform(0.8, 1.1, size=(8, 3))[(row * 2 + np.floor(u * 2 + 0.5 * (row % 2)) % 2).astype(int) % 8]
    brick = np.array([0.45, 0.16, 0.09]) * tint
    mortar = np.array([0.55, 0.53, 0.5])
    albedo = np.where(height[..., None] > 0.5, brick, mortar)
    # Normals from the height field (central differences, tangent space, +z out).
    dh_du = (np.roll(height, -1, 1) - np.roll(height, 1, 1)) * 0.5 * 3.0
    dh_dv = (np.roll(height, -1, 0) - np.roll(height, 1, 0)) * 0.5 * 3.0
    n = np.stack([-dh_du, dh_dv, np.ones_like(height)], axis=-1)  # image rows grow downward: v flips
    n /= np.linalg.norm(n, axis=-1, keepdims=True)
    normal8 = np.round((n * 0.5 + 0.5) * 255).astype(np.uint8)
    # Metallic 0; smoothness: glazed bricks 0.7, mortar 0.1 (Unity packing: R metal, A smooth).
    ms = np.zeros((SIZE, SIZE, 4), np.uint8)
    ms[..., 3] = np.round(np.where(height > 0.5, 0.7, 0.1) * 255).astype(np.uint8)
    # Emission: glowing mortar lines in one row only.
    glow = ((height < 0.5) & (row == 1))[..., None] * np.array([1.0, 0.45, 0.1])
    images.write_png(HERE / "bricks_albedo.png", _srgb8(albedo))
    images.write_png(HERE / "bricks_normal.png", normal8)
    images.write_png(HERE / "bricks_metallic_smoothness.png", ms)
    images.write_png(HERE / "bricks_emission.png", _srgb8(glow))


def leaf():
    """A green leaf shape in RGBA: alpha 1 inside, 0 outside (for cutout mode)."""
    v, u = np.meshgrid((np.arange(SIZE) + 0.5) / SIZE * 2 - 1, (np.arange(SIZE) + 0.5) / SIZE * 2 - 1,
                       indexing="ij")
    inside = (u / 0.55) ** 2 + (v / 0.95) ** 2 * (1 + 0.6 * v) < 1
    vein = np.abs(u) < 0.03
    color = np.where(vein[..., None], [0.35, 0.5, 0.15], [0.12, 0.38, 0.08])
    rgba = np.concatenate([_srgb8(color), (inside * 255).astype(np.uint8)[..., None]], axis=2)
    images.write_png(HERE / "leaf.png", rgba)


def sky():
    """Equirect 128x64 HDR sky: blue gradient, warm ground, a sun of radiance 150."""
    h, w = 64, 128
    theta = (np.arange(h) + 0.5) / h * np.pi
    phi = (np.arange(w) + 0.5) / w * 2 * np.pi
    t, p = np.meshgrid(theta, phi, indexing="ij")
    d = np.stack([np.sin(t) * np.sin(p), np.cos(t), -np.sin(t) * np.cos(p)], -1)
    up = d[..., 1]
    sky_col = np.array([0.25, 0.45, 0.9])[None, None] * (0.4 + 0.6 * np.clip(up, 0, 1)[..., None])
    ground = np.array([0.18, 0.14, 0.1])[None, None] * np.ones_like(sky_col)
    radiance = np.where(up[..., None] >= 0, sky_col, ground)
    sun = np.array([0.4, 0.7, 0.55])
    sun /= np.linalg.norm(sun)
    radiance = radiance + (d @ sun > np.cos(np.radians(4)))[..., None] * np.array([150.0, 135.0, 110.0])
    images.write_exr(HERE / "sky.exr", radiance.astype(np.float32))


def cushion():
    """A superellipsoid cushion, 64 x 32 vertices, with UVs; OBJ with normals."""
    nu, nv = 64, 32
    uu, vv = np.meshgrid(np.linspace(0, 1, nu + 1), np.linspace(0, 1, nv + 1), indexing="ij")
    phi, theta = uu * 2 * np.pi, vv * np.pi
    e = 0.4  # squareness

    def spow(x, k):
        return np.sign(x) * np.abs(x) ** k
    x = spow(np.sin(theta), e) * spow(np.cos(phi), e) * 1.0
    z = spow(np.sin(theta), e) * spow(np.sin(phi), e) * 1.0
    y = spow(np.cos(theta), e) * 0.45
    pos = np.stack([x, y, z], -1).reshape(-1, 3)
    uv = np.stack([uu, 1 - vv], -1).reshape(-1, 2)
    idx = np.arange((nu + 1) * (nv + 1)).reshape(nu + 1, nv + 1)
    a, b, c, d = idx[:-1, :-1], idx[1:, :-1], idx[1:, 1:], idx[:-1, 1:]
    faces = np.concatenate([np.stack([a, c, d], -1).reshape(-1, 3), np.stack([a, b, c], -1).reshape(-1, 3)])
    lines = ["# cushion: superellipsoid, generated by scenes/assets/make_assets.py"]
    lines += [f"v {p[0]:.6f} {p[1]:.6f} {p[2]:.6f}" for p in pos]
    lines += [f"vt {t[0]:.6f} {t[1]:.6f}" for t in uv]
    lines += [f"f {f[0]+1}/{f[0]+1} {f[1]+1}/{f[1]+1} {f[2]+1}/{f[2]+1}" for f in faces]
    (HERE / "cushion.obj").write_text("\n".join(lines) + "\n")


def torture():
    """For the torture chart: a normal map whose tangent-space normal points into the
    surface and sideways (normals facing away from the viewer), and a small sky with one
    +Inf and one NaN texel."""
    n = np.array([0.0, 0.85, -0.53])
    n /= np.linalg.norm(n)
    images.write_png(HERE / "away_normal.png",
                     np.tile(np.round((n * 0.5 + 0.5) * 255).astype(np.uint8), (8, 8, 1)))
    sky_image = np.full((8, 16, 3), [0.3, 0.4, 0.6], np.float32)
    sky_image[2, 5] = np.inf
    sky_image[5, 11] = np.nan
    images.write_exr(HERE / "broken_sky.exr", sky_image)


def lightmap():
    """A 16 x 16 RGBM lightmap (Unity's Normal Quality encoding: decoded 34.49 a^2.2 rgb, rgb
    sampled as sRGB): a warm light falling off across u, a cool one along v, the multiplier
    brightest at the centre; every texel a different value."""
    n = 16
    v, u = np.meshgrid((np.arange(n) + 0.5) / n, (np.arange(n) + 0.5) / n, indexing="ij")
    rgb = np.stack([0.25 + 0.7 * u, 0.35 + 0.3 * u * v, 0.3 + 0.65 * v], axis=-1)
    m = 0.2 + 0.6 * np.exp(-((u - 0.5) ** 2 + (v - 0.5) ** 2) * 4.0)
    rgbm = np.concatenate([rgb, m[..., None]], axis=-1)
    images.write_png(HERE / "lightmap_rgbm.png", np.round(rgbm * 255).astype(np.uint8))


def realtime_lightmap():
    """A 16 x 16 realtime GI lightmap (Unity's RGB9E5 output: float RGB, read as it is, linear):
    green-blue light rising across u, red along v, from 0.05 to 2.5; every texel a different value."""
    n = 16
    v, u = np.meshgrid((np.arange(n) + 0.5) / n, (np.arange(n) + 0.5) / n, indexing="ij")
    rgb = np.stack([0.05 + 2.0 * v, 0.1 + 1.5 * u * (1.0 - 0.5 * v), 0.2 + 2.3 * u * u], axis=-1)
    images.write_exr(HERE / "realtime_lightmap.exr", rgb.astype(np.float32))


if __name__ == "__main__":
    bricks()
    leaf()
    sky()
    cushion()
    torture()
    lightmap()
    realtime_lightmap()
    print(f"wrote assets to {HERE}")
