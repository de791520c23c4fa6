"""The sheen albedo table: E(NdotV, sheen perceptual roughness), the directional albedo of the
library's white sheen lobe D_Charlie · V (glsl/pbr/shading/sheen.glsl, pbr_sheen_lobe with
sheenColor = 1 and the default PBR_SHEEN_V_CHARLIE), for KHR_materials_sheen's albedo scaling
(Estevez & Kulla 2017 §4): E(μ) = ∫ D V (n·l) dω_l.

* ``integrate_sheen_albedo(NdotV, r)``: float64, a deterministic product quadrature over the
  light direction (no random numbers): Gauss-Legendre in NdotL on panels spaced geometrically
  towards the horizon (Λ has x^c, c ≈ 0.2, and the lobe peaks at grazing), split at NdotL = 1/2
  (the fit's reflection point, where V has a kink), times Gauss-Legendre in the azimuth over
  [0, π] (the lobe is symmetric in φ). The cosine floors of the library (PBR_MIN_NDOTV) are
  applied as the shader applies them (reference/sheen.py sheen_lobe).
* ``sheen_lut()``: the shipped table data/sheen_albedo_lut.npy (HEIGHT x WIDTH float32, image
  order: top row first), made by ``python -m pbrlab.gpu.sheen_table --write``.
* ``sheen_texture(ctx)``: the table as an R32F texture, linear filtering, clamp to edge, for
  ``#define PBR_SHEEN_LUT_LOOKUP(NdotV, r) texture(u_sheen_lut, pbr_sheen_lut_uv(NdotV, r)).r``.

Layout (shared with pbr/shading/sheen.glsl, constants tested equal): texel (i, j) holds E
exactly at x = i / (WIDTH - 1), y = j / (HEIGHT - 1) of the warped axes
  x = log2(max(NdotV, 1e-4) / 1e-4) / log2(1e4)                 (PBR_MIN_NDOTV = 1e-4),
  y = log2(max(r, r_min) / r_min) / log2(1 / r_min)             (r_min = 0.07, the sheen floor),
so a bilinear fetch at the texel centres (x (W - 1) + 0.5) / W interpolates between exact
values. E has a peak of width ~1e-3 in NdotV at grazing views of smooth sheens (v_charlie.glsl):
the log axes resolve it. Size chosen by measured bilinear error against a finer quadrature
(max over 201 NdotV x 47 roughness): 64 x 32: 4.7e-3, 64 x 64: 2.2e-3, 128 x 64: 1.3e-3,
96 x 96: 9.7e-4, 128 x 128: 5.5e-4 (shipped; a uniform NdotV axis at 128 x 128 reached 2.7e-3).
"""

from __future__ import annotations

import argparse
from functools import lru_cache
from pathlib import Path

import numpy as np

from ..foundation import outputs
from ..foundation.errors import PbrlabError
from ..maths.reference import sheen as ref_sheen

LUT_FILE = Path(__file__).resolve().parent / "data" / "sheen_albedo_lut.npy"
LUT_WIDTH = 128      # PBR_SHEEN_LUT_WIDTH (NdotV axis)
LUT_HEIGHT = 128     # PBR_SHEEN_LUT_HEIGHT (roughness axis)
LUT_MIN_NDOTV = ref_sheen.MIN_NDOTV  # the axis starts at PBR_MIN_NDOTV: E is constant below it
MIN_ROUGHNESS = ref_sheen.SHEEN_MIN_PERCEPTUAL_ROUGHNESS

# The quadrature: NdotL panels [0, 1e-6 .. 1/2 geometric (NODES_PANELS), 3/4, 1], NODES per
# panel, PHI_NODES in φ. Against twice the nodes everywhere: < 1e-6 (tests/library/test_sheen.py
# checks the table against an independent, much finer quadrature).
NDOTL_PANELS = 14
NODES = 24
PHI_NODES = 64


def _gauss_legendre(n):
    x, w = np.polynomial.legendre.leggauss(n)
    return 0.5 * (x + 1.0), 0.5 * w


def integrate_sheen_albedo(NdotV, sheen_perceptual_roughness, visibility="CHARLIE", *, nodes=NODES,
                           phi_nodes=PHI_NODES, panels=NDOTL_PANELS) -> np.ndarray:
    """E for arrays of NdotV and sheen perceptual roughness (broadcast), float64."""
    mu, rough = np.broadcast_arrays(np.asarray(NdotV, np.float64), np.asarray(sheen_perceptual_roughness, np.float64))
    shape = mu.shape
    mu = mu.reshape(-1)
    rough = rough.reshape(-1)
    edges = np.concatenate([[0.0], np.geomspace(1e-6, 0.5, panels), [0.75, 1.0]])
    t, tw = _gauss_legendre(nodes)
    p, pw = _gauss_legendre(phi_nodes)
    cos_phi = np.cos(np.pi * p)
    dphi = 2.0 * np.pi * pw                       # both halves of the azimuth
    out = np.zeros(mu.shape[0])
    white = np.ones(3)
    chunk = max(1, 200_000 // (nodes * phi_nodes))
    for start in range(0, mu.shape[0], chunk):
        m = mu[start:start + chunk, None, None]
        r = rough[start:start + chunk, None, None]
        cm = np.clip(m, ref_sheen.MIN_NDOTV, 1.0)  # the shader's v after its clamp (n·v >= 1e-4)
        sin_v = np.sqrt(1.0 - cm * cm)
        total = np.zeros(m.shape[0])
        for lo, hi in zip(edges[:-1], edges[1:]):
            u = (lo + (hi - lo) * t)[None, :, None]
            du = ((hi - lo) * tw)[None, :, None]
            sin_l = np.sqrt(1.0 - u * u)
            LdotV = cm * u + sin_v * sin_l * cos_phi[None, None, :]
            NdotH = (u + cm) / np.sqrt(np.maximum(2.0 + 2.0 * LdotV, 1e-300))
            lobe = ref_sheen.sheen_lobe(u, m, NdotH, white, r, visibility)[..., 0]
            total += np.sum(lobe * u * du * dphi[None, None, :], axis=(1, 2))
        out[start:start + chunk] = total
    return out.reshape(shape)


# The table's warped axes live with the reference (the fit in reference/sheen.py reads them
# too, and a reference never imports this module's GL side: docs/layers.md).
lut_axes = ref_sheen.lut_axes


def lut_texel_coordinates(x, y):
    """Inverse of lut_axes: (NdotV, sheen perceptual roughness) of the axes (x, y)."""
    NdotV = LUT_MIN_NDOTV * (1.0 / LUT_MIN_NDOTV) ** np.asarray(x, np.float64)
    r = MIN_ROUGHNESS * (1.0 / MIN_ROUGHNESS) ** np.asarray(y, np.float64)
    return np.clip(NdotV, 0.0, 1.0), np.clip(r, 0.0, 1.0)


def lut_uv(NdotV, sheen_perceptual_roughness, width=LUT_WIDTH, height=LUT_HEIGHT):
    """pbr_sheen_lut_uv: the texel-centre texture coordinates."""
    x, y = lut_axes(NdotV, sheen_perceptual_roughness)
    return (x * (width - 1) + 0.5) / width, (y * (height - 1) + 0.5) / height


def compute_sheen_lut(width=LUT_WIDTH, height=LUT_HEIGHT, visibility="CHARLIE") -> np.ndarray:
    """HEIGHT x WIDTH float32, image order (top row first = y = 1)."""
    xs = np.arange(width) / (width - 1)
    ys = np.arange(height) / (height - 1)
    y, x = np.meshgrid(ys, xs, indexing="ij")
    NdotV, rough = lut_texel_coordinates(x, y)
    return integrate_sheen_albedo(NdotV, rough, visibility)[::-1].astype(np.float32)


def sample_sheen_lut(table, NdotV, sheen_perceptual_roughness) -> np.ndarray:
    """What a GPU reads from ``table`` (image order) at pbr_sheen_lut_uv: bilinear, clamp to
    edge, in float64."""
    t = np.asarray(table, np.float64)[::-1]      # GL row order: row j = y j / (H - 1)
    h, w = t.shape
    u, v = lut_uv(NdotV, sheen_perceptual_roughness, w, h)
    fx, fy = u * w - 0.5, v * h - 0.5
    i0 = np.clip(np.floor(fx).astype(int), 0, w - 1)
    j0 = np.clip(np.floor(fy).astype(int), 0, h - 1)
    i1, j1 = np.minimum(i0 + 1, w - 1), np.minimum(j0 + 1, h - 1)
    tx, ty = fx - np.floor(fx), fy - np.floor(fy)
    return ((t[j0, i0] * (1 - tx) + t[j0, i1] * tx) * (1 - ty) + (t[j1, i0] * (1 - tx) + t[j1, i1] * tx) * ty)


def fit_sheen_albedo_approx(table, offset=0.001, iterations=30):
    """The 4 x 4 coefficients of pbr_sheen_albedo_approx: log-linear least squares of
    log(E + offset) in x^i y^j, then Gauss-Newton on the absolute error of exp(.) - offset."""
    t = np.asarray(table, np.float64)[::-1]
    h, w = t.shape
    y, x = np.meshgrid(np.arange(h) / (h - 1), np.arange(w) / (w - 1), indexing="ij")
    A = np.stack([(x ** i * y ** j).ravel() for i in range(4) for j in range(4)], axis=1)
    coef = np.linalg.lstsq(A, np.log(t.ravel() + offset), rcond=None)[0]
    for _ in range(iterations):
        f = np.exp(A @ coef)
        coef -= np.linalg.lstsq(A * f[:, None], f - offset - t.ravel(), rcond=None)[0]
    return coef.reshape(4, 4)


@lru_cache(maxsize=1)
def sheen_lut() -> np.ndarray:
    """The shipped table (data/sheen_albedo_lut.npy), HEIGHT x WIDTH float32, image order."""
    if not LUT_FILE.exists():
        raise PbrlabError(f"{LUT_FILE} is missing; create it with python -m pbrlab.gpu.sheen_table --write")
    table = np.load(LUT_FILE)
    if table.shape != (LUT_HEIGHT, LUT_WIDTH) or table.dtype != np.float32:
        raise PbrlabError(f"{LUT_FILE}: {table.shape} {table.dtype} is not the layout's; "
                          "regenerate it with python -m pbrlab.gpu.sheen_table --write")
    return table


def sheen_texture(ctx):
    """The table as a single-channel float texture (R32F), linear filtering, clamp to edge."""
    from . import targets
    return targets.lookup_table_texture(ctx, sheen_lut())


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="python -m pbrlab.gpu.sheen_table", description=__doc__.splitlines()[0])
    parser.add_argument("--write", action="store_true", help=f"recompute {LUT_FILE.name}")
    args = parser.parse_args(argv)
    if args.write:
        LUT_FILE.parent.mkdir(exist_ok=True)
        outputs.write_npy(LUT_FILE, compute_sheen_lut())
        print(LUT_FILE)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
