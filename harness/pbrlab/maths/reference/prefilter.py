"""Float64 brute force of the prefiltered environment (harness/pbrlab/gpu/ibl.py,
templates/prefilter.frag): Karis 2013, "Real Shading in Unreal Engine 4", the first sum of
the split sum ("PrefilterEnvMap") under n = v = r, as the library's prefilter defines it:

    P(n, alpha) = integral L(l) D(h) (n.l)+ dl / integral D(h) (n.l)+ dl,   h = (n + l) / |n + l|

The prefilter draws h from D(h) (n.h) and reflects it (pdf over l: D (n.h) / (4 (v.h)) =
D / 4 with v = n; Walter et al. 2007, eq. 14) and averages L(l) with weights (n.l): the
estimator's expectation is the ratio above (the constant 1/4 cancels). With h the bisector
of n and l, n.h = sqrt((1 + n.l) / 2), so the weight depends on n.l alone. At perceptual
roughness 0 the lobe is a delta: P(n) = L(n).

The environment L is the equirectangular image as the GPU reconstructs it: bilinear
between texel centres, repeating in u, clamped to the edge rows in t (GL's REPEAT /
CLAMP_TO_EDGE; the convention of scene/environment.py). The integral is a midpoint rule
over sub-cells: each texel split into ``subdivision`` x ``subdivision`` cells of equal
(u, t) extent, whose exact solid angle (2 pi / W') (cos theta0 - cos theta1) weights the
bilinear radiance and the lobe at the cell's centre. With an even subdivision the cell
edges contain the texel centres, so the bilinear radiance is smooth inside every cell and
the rule's error is O(cell^2) in the lobe's curvature (Richardson: quadrature_error_estimate).
"""

from __future__ import annotations

import numpy as np

from .brdf import D_GGX

_CHUNK = 1 << 22  # directions x cells per block (32 MiB of float64)


def equirect_direction(u, t):
    """pbr_equirect_direction: (u, t) -> unit direction (t = 1 is the top row, +Y)."""
    phi = 2.0 * np.pi * np.asarray(u, np.float64)
    theta = (1.0 - np.asarray(t, np.float64)) * np.pi
    return np.stack([np.sin(theta) * np.sin(phi), np.cos(theta), -np.sin(theta) * np.cos(phi)], axis=-1)


def equirect_uv(d):
    """pbr_equirect_uv: unit direction -> (u, t)."""
    d = np.asarray(d, np.float64)
    u = np.mod(np.arctan2(d[..., 0], -d[..., 2]) / (2.0 * np.pi), 1.0)
    t = 1.0 - np.arccos(np.clip(d[..., 1], -1.0, 1.0)) / np.pi
    return u, t


def bilinear(image, u, t):
    """GL's bilinear reconstruction of a top-row-first image (H x W x C) at (u, t): REPEAT in
    u, CLAMP_TO_EDGE in t."""
    image = np.asarray(image, np.float64)
    h, w = image.shape[:2]
    x = np.asarray(u, np.float64) * w - 0.5
    y = (1.0 - np.asarray(t, np.float64)) * h - 0.5  # row index from the top
    x0, y0 = np.floor(x), np.floor(y)
    fx, fy = (x - x0)[..., None], (y - y0)[..., None]
    x0 = x0.astype(np.int64)
    y0 = y0.astype(np.int64)
    xa, xb = np.mod(x0, w), np.mod(x0 + 1, w)
    ya, yb = np.clip(y0, 0, h - 1), np.clip(y0 + 1, 0, h - 1)
    top = image[ya, xa] * (1 - fx) + image[ya, xb] * fx
    bottom = image[yb, xa] * (1 - fx) + image[yb, xb] * fx
    return top * (1 - fy) + bottom * fy


def quadrature_cells(image, subdivision: int = 2):
    """(directions (P, 3), solid angles (P,), radiance (P, C)) of the sub-cells."""
    h, w = image.shape[:2]
    rows, cols = h * subdivision, w * subdivision
    u = (np.arange(cols) + 0.5) / cols
    t = 1.0 - (np.arange(rows) + 0.5) / rows
    theta_edges = np.arange(rows + 1) / rows * np.pi
    solid_row = (2.0 * np.pi / cols) * (np.cos(theta_edges[:-1]) - np.cos(theta_edges[1:]))
    uu, tt = np.meshgrid(u, t)
    radiance = bilinear(image, uu, tt)
    d = equirect_direction(uu, tt)
    solid = np.broadcast_to(solid_row[:, None], (rows, cols))
    return d.reshape(-1, 3), solid.reshape(-1).copy(), radiance.reshape(rows * cols, -1)


def lobe_weight(NdotL, alpha):
    """D(h) (n.l)+ with h the bisector of n and l (n.h = sqrt((1 + n.l) / 2))."""
    NdotL = np.asarray(NdotL, np.float64)
    NdotH = np.sqrt(np.clip(0.5 * (1.0 + NdotL), 0.0, 1.0))
    return np.where(NdotL > 0.0, D_GGX(NdotH, alpha) * NdotL, 0.0)


def prefiltered_radiance(image, directions, perceptual_roughness: float, subdivision: int = 2,
                         cells=None):
    """P(n, alpha) (module docstring) for unit directions (M, 3) -> (M, C), float64.
    ``cells``: quadrature_cells(image, subdivision), to reuse across calls."""
    directions = np.asarray(directions, np.float64).reshape(-1, 3)
    if perceptual_roughness == 0.0:
        return bilinear(image, *equirect_uv(directions))
    alpha = float(perceptual_roughness) ** 2
    d, solid, radiance = cells if cells is not None else quadrature_cells(image, subdivision)
    out = np.zeros((directions.shape[0], radiance.shape[1]))
    block = max(1, _CHUNK // d.shape[0])
    for start in range(0, directions.shape[0], block):
        n = directions[start:start + block]
        w = lobe_weight(n @ d.T, alpha) * solid                    # (m, P)
        out[start:start + block] = (w @ radiance) / w.sum(axis=1, keepdims=True)
    return out


def quadrature_error_estimate(image, directions, perceptual_roughness: float, subdivision: int = 2):
    """(P at subdivision, an estimate of its quadrature error): the midpoint rule's error is
    O(cell^2), so P_k - P_exact ~ (4 / 3) (P_k - P_2k) (Richardson)."""
    coarse = prefiltered_radiance(image, directions, perceptual_roughness, subdivision)
    fine = prefiltered_radiance(image, directions, perceptual_roughness, 2 * subdivision)
    return coarse, (4.0 / 3.0) * np.abs(coarse - fine)


def cube_face_directions(edge: int) -> np.ndarray:
    """prefilter.frag's pbrlab_cube_face_direction at the texel centres of an edge x edge
    level: 6 x edge x edge x 3 unit directions, faces +X, -X, +Y, -Y, +Z, -Z, row j at
    t = (j + 0.5) / edge (GL's first row), column i at s; OpenGL 4.6, table 8.19."""
    c = (np.arange(edge) + 0.5) / edge * 2.0 - 1.0
    sc, tc = np.meshgrid(c, c)  # [j, i]
    one = np.ones_like(sc)
    d = np.stack([np.stack(f, axis=-1) for f in (
        (one, -tc, -sc), (-one, -tc, sc), (sc, one, tc), (sc, -one, -tc), (sc, -tc, one), (-sc, -tc, -one))])
    return d / np.linalg.norm(d, axis=-1, keepdims=True)


def equirect_texels(height: int, width: int):
    """Texel-centre directions (H, W, 3) and exact solid angles (H, W) of an equirect image:
    (2 pi / W) (cos theta0 - cos theta1) per row."""
    u = (np.arange(width) + 0.5) / width
    t = 1.0 - (np.arange(height) + 0.5) / height
    uu, tt = np.meshgrid(u, t)
    edges = np.arange(height + 1) / height * np.pi
    solid = (2.0 * np.pi / width) * (np.cos(edges[:-1]) - np.cos(edges[1:]))
    return equirect_direction(uu, tt), np.broadcast_to(solid[:, None], (height, width)).copy()
