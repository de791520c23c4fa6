"""Image-based lighting data the harness generates for the library:

* ``dfg_lut()``: the split-sum environment BRDF table (A, B) over warped (NdotV,
  roughness) axes, integrated in float64 numpy with the library's own default visibility
  (exact height-correlated Smith GGX) by a deterministic quadrature in GGX's sampling
  variables (``integrate_dfg``). Karis 2013, "Real Shading in Unreal Engine 4", eq. 8 and
  its listing "IntegrateBRDF".
* ``prefiltered_environment(ctx, image)``: an equirectangular mip chain whose level i is
  the environment convolved with the GGX lobe of perceptual roughness i / (levels - 1),
  under Karis's n = v = r assumption, computed on the GPU by GGX importance sampling with
  filtered importance sampling (Krivanek & Colbert 2008, "Real-time Shading with Filtered
  Importance Sampling", eq. 10) to avoid noise.

The GLSL side reads them through pbr/ibl/environment_brdf.glsl
(``PBR_DFG_LUT_LOOKUP`` hook, ``pbr_ibl_lod_from_perceptual_roughness``).
"""

from __future__ import annotations

import argparse
import os
from functools import lru_cache
from pathlib import Path

import moderngl
import numpy as np

from ..foundation import disk_cache, outputs
from . import targets
from ..foundation.errors import PbrlabError
from .programs import program_from_templates, template_source
from ..maths.reference import brdf as ref_brdf
from ..maths.reference import surface as ref_surface

PREFILTER_SIZE = (256, 128)  # level 0 of the prefiltered chain (equirect 2:1)
PREFILTER_LEVELS = 6       # 256x128 ... 8x4: perceptual roughness 0, 0.2, ..., 1
PREFILTER_SAMPLES = 256    # GGX samples per texel (filtered importance sampling)

# The DFG table: layout (size and warped axes) in reference/surface.py and
# glsl/pbr/ibl/environment_brdf.glsl; values from integrate_dfg, stored in
# data/dfg_lut.npy (computing 256 x 256 texels takes about a minute, so it is made once by
# `python -m pbrlab.gpu.ibl --write-dfg` and checked by tests/surface/test_dfg_table.py).
DFG_LUT_FILE = Path(__file__).resolve().parent / "data" / "dfg_lut.npy"
DFG_W_PANELS = 6       # equal panels in w = log(1 - u) over the partially visible band
DFG_NODES = 24         # Gauss-Legendre nodes per panel
DFG_PHI_NODES = 32     # Gauss-Legendre nodes in phi
DFG_MIN_NDOTV = 1e-9   # column 0 is NdotV = 0: the limit, taken at 1e-9 (E changes ~1e-6 there)


def hammersley(count: int) -> np.ndarray:
    """count x 2 Hammersley points: (i/count, base-2 radical inverse of i)."""
    i = np.arange(count, dtype=np.uint64)
    bits = i.copy()
    rev = np.zeros_like(bits)
    for b in range(32):
        rev |= ((bits >> np.uint64(b)) & np.uint64(1)) << np.uint64(31 - b)
    return np.stack([i / count, rev.astype(np.float64) / 2.0**32], axis=1)


def _gauss_legendre(n):
    x, w = np.polynomial.legendre.leggauss(n)
    return 0.5 * (x + 1.0), 0.5 * w


def integrate_dfg(NdotV, perceptual_roughness) -> np.ndarray:
    """(A, B) of the split sum (..., 2) for arrays of NdotV and perceptual roughness, float64,
    by deterministic quadrature in GGX's sampling variables (Karis 2013's IntegrateBRDF,
    with quadrature nodes in place of random samples).

    The half vector h is drawn from D(h) (n.h): u = the CDF in theta (Walter et al. 2007,
    eq. 35: cos^2 theta = (1 - u) / (1 + (alpha^2 - 1) u)), phi uniform; then
    f cos / pdf = V (n.l) 4 (v.h) / (n.h) and E = (1 / pi) int_0^1 du int_0^pi dphi of it
    (the half plane phi < 0 mirrors phi > 0). The horizon n.l > 0 is done analytically: for
    each u, phi runs over [0, phi_max(u)] (full for theta < pi/4 - theta_v/2, empty past
    pi/4 + theta_v/2); u is integrated in w = log(1 - u), whose nodes spread over every
    scale of D's tail, with Gauss-Legendre on [0, w_full] and on DFG_W_PANELS equal panels
    of [w_full, w_end], each after x = a + (b - a)(1 - cos(pi t)) / 2 (clusters at both ends,
    where phi_max has square-root behaviour). V is the library's exact height-correlated
    Smith (reference/brdf.py). A + B is the albedo at F = 1; f0 A + f90 B at Schlick's F.
    """
    NdotV, rough = np.broadcast_arrays(np.asarray(NdotV, np.float64), np.asarray(perceptual_roughness, np.float64))
    shape = NdotV.shape
    mu = np.clip(NdotV.reshape(-1), DFG_MIN_NDOTV, 1.0)[:, None]
    alpha = np.clip(rough.reshape(-1) ** 2, 1e-6, 1.0)[:, None]
    theta_v = np.arccos(mu)
    sin_v = np.sin(theta_v)

    def w_of_theta(theta):  # w = log(1 - u), 1 - u = alpha^2 / (alpha^2 + tan^2)
        t2 = np.tan(theta) ** 2
        return -np.log1p(t2 / (alpha * alpha))

    w_full = w_of_theta(0.25 * np.pi - 0.5 * theta_v)
    w_end = w_of_theta(np.minimum(0.25 * np.pi + 0.5 * theta_v, 0.5 * np.pi - 1e-12))
    t, tw = _gauss_legendre(DFG_NODES)
    edges = [np.zeros_like(w_full), w_full] + [
        w_full + (w_end - w_full) * k / DFG_W_PANELS for k in range(1, DFG_W_PANELS + 1)]
    p_nodes, p_weights = _gauss_legendre(DFG_PHI_NODES)
    out = np.zeros((mu.shape[0], 2))
    for lo, hi in zip(edges[:-1], edges[1:]):
        w = lo + (hi - lo) * 0.5 * (1 - np.cos(np.pi * t))                  # (texels, nodes)
        dw = (lo - hi) * 0.5 * np.pi * np.sin(np.pi * t) * tw                # du = -(1-u) dw >= 0
        one_minus_u = np.exp(w)
        du = one_minus_u * dw
        u = -np.expm1(w)
        cos2 = one_minus_u / (one_minus_u + alpha * alpha * u)               # eq. 35 rearranged
        cos_h, sin_h = np.sqrt(cos2), np.sqrt(np.maximum(1 - cos2, 0.0))
        with np.errstate(divide="ignore", invalid="ignore"):
            c = mu * (2 * cos2 - 1) / (sin_v * 2 * sin_h * cos_h) * -1.0    # n.l > 0 <=> cos phi > c
        c = np.where(np.isfinite(c), c, -1.0)
        phi_max = np.arccos(np.clip(c, -1.0, 1.0))
        phi = phi_max[..., None] * p_nodes
        dphi = phi_max[..., None] * p_weights
        VdotH = sin_v[..., None] * sin_h[..., None] * np.cos(phi) + mu[..., None] * cos_h[..., None]
        NdotL = 2 * VdotH * cos_h[..., None] - mu[..., None]
        lit = NdotL > 0
        NdotL_c = np.where(lit, NdotL, 1.0)
        vis = ref_brdf.V_SmithGGXCorrelated(NdotL_c, mu[..., None], alpha[..., None])
        weight = np.where(lit, vis * NdotL_c * 4 * VdotH / cos_h[..., None], 0.0) * (du[..., None] * dphi) / np.pi
        fc = (1 - np.clip(VdotH, 0, 1)) ** 5
        out[:, 0] += np.sum((1 - fc) * weight, axis=(1, 2))
        out[:, 1] += np.sum(fc * weight, axis=(1, 2))
    return out.reshape(shape + (2,))


def compute_dfg_lut() -> np.ndarray:
    """HEIGHT x WIDTH x 2 float32, image order (top row first = the last row, y = 1): texel
    (i, j) of GL row j holds (A, B) at the warped axes x = i / (WIDTH - 1), y = j / (HEIGHT - 1)."""
    xs = np.arange(ref_surface.DFG_LUT_WIDTH) / (ref_surface.DFG_LUT_WIDTH - 1)
    ys = np.arange(ref_surface.DFG_LUT_HEIGHT) / (ref_surface.DFG_LUT_HEIGHT - 1)
    y, x = np.meshgrid(ys, xs, indexing="ij")
    NdotV, rough = ref_surface.dfg_lut_texel_coordinates(x, y)
    rows = [integrate_dfg(NdotV[j], rough[j]) for j in range(len(ys))]
    return np.stack(rows)[::-1].astype(np.float32)


@lru_cache(maxsize=1)
def dfg_lut() -> np.ndarray:
    """The shipped table (data/dfg_lut.npy), HEIGHT x WIDTH x 2 float32, image order."""
    if not DFG_LUT_FILE.exists():
        raise PbrlabError(f"{DFG_LUT_FILE} is missing; create it with python -m pbrlab.gpu.ibl --write-dfg")
    table = np.load(DFG_LUT_FILE)
    if table.shape != (ref_surface.DFG_LUT_HEIGHT, ref_surface.DFG_LUT_WIDTH, 2):
        raise PbrlabError(f"{DFG_LUT_FILE}: shape {table.shape} is not the layout's; "
                          "regenerate it with python -m pbrlab.gpu.ibl --write-dfg")
    return table


def dfg_texture(ctx: moderngl.Context) -> moderngl.Texture:
    return targets.lookup_table_texture(ctx, dfg_lut())


def prefiltered_environment(ctx: moderngl.Context, image: np.ndarray) -> moderngl.Texture:
    """The GGX-prefiltered mip chain of an equirectangular radiance image (HxWx3, linear),
    as an RGBA32F texture with PREFILTER_LEVELS levels (see module docstring). The levels
    come from the disk cache when an earlier process filtered the same image with the same
    program on the same driver (_prefilter_cache_key): 256 samples per texel cost llvmpipe
    about 0.3 s, a third of a render's start-up (issue 25)."""
    name = _prefilter_cache_key(ctx, image)
    payload = disk_cache.load("prefiltered-environment", name)
    if payload is not None:
        levels = disk_cache.unpack_arrays(payload)
    else:
        levels = _prefilter_levels(ctx, image)
        disk_cache.store("prefiltered-environment", name, disk_cache.pack_arrays(levels))
    result = targets.float_texture_from_levels(ctx, levels)
    result.filter = (moderngl.LINEAR_MIPMAP_LINEAR, moderngl.LINEAR)
    result.repeat_x, result.repeat_y = True, False
    return result


def _prefilter_cache_key(ctx: moderngl.Context, image: np.ndarray) -> str:
    """Everything the prefiltered levels are computed from: the image's pixels, the
    program's full expanded source, the constants and code of this module, and the driver
    (renderer, version, and the environment variables that steer Mesa and llvmpipe, such as
    LP_NATIVE_VECTOR_WIDTH): any change gives another key, so no entry is ever stale."""
    pixels = np.ascontiguousarray(image[..., :3], np.float32)
    programs = [template_source(name, {}).text for name in ("fullscreen.vert", "prefilter.frag")]
    driver = [ctx.info["GL_VENDOR"], ctx.info["GL_RENDERER"], ctx.info["GL_VERSION"],
              sorted((k, v) for k, v in os.environ.items() if k.startswith(("LP_", "GALLIUM_", "MESA_")))]
    return disk_cache.key("prefiltered-environment", pixels.shape, pixels.tobytes(), *programs, driver,
                          PREFILTER_SIZE, PREFILTER_LEVELS, PREFILTER_SAMPLES, Path(__file__).read_bytes())


def _prefilter_levels(ctx: moderngl.Context, image: np.ndarray) -> list[np.ndarray]:
    """The PREFILTER_LEVELS levels, each float32 in GL row order, filtered on the GPU."""
    source = targets.upload_texture(ctx, np.concatenate(
        [image[..., :3], np.ones(image.shape[:2] + (1,), image.dtype)], axis=2).astype(np.float32),
        srgb=False)
    source.repeat_x, source.repeat_y = True, False
    program = program_from_templates(ctx, "fullscreen.vert", "prefilter.frag", {})
    vao = ctx.vertex_array(program, [])
    w0, h0 = PREFILTER_SIZE
    source_levels = 1 + int(np.floor(np.log2(max(image.shape[0], image.shape[1]))))
    levels = []
    try:
        for level in range(PREFILTER_LEVELS):
            size = (max(w0 >> level, 1), max(h0 >> level, 1))
            with targets.Target(ctx, size, "f32", depth=False) as target:
                target.use()
                source.use(0)
                program["u_source"].value = 0
                program["u_source_size"].value = (float(image.shape[1]), float(image.shape[0]))
                program["u_source_max_lod"].value = float(source_levels - 1)
                program["u_perceptual_roughness"].value = level / (PREFILTER_LEVELS - 1)
                program["u_sample_count"].value = PREFILTER_SAMPLES
                program["u_target_size"].value = (float(size[0]), float(size[1]))
                vao.render(moderngl.TRIANGLES, vertices=3)
                levels.append(np.ascontiguousarray(target.read()[::-1]))  # back to GL row order
    finally:
        vao.release()
        source.release()
    return levels


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="python -m pbrlab.gpu.ibl", description=__doc__.splitlines()[0])
    parser.add_argument("--write-dfg", action="store_true", help=f"recompute {DFG_LUT_FILE.name}")
    args = parser.parse_args(argv)
    if args.write_dfg:
        DFG_LUT_FILE.parent.mkdir(exist_ok=True)
        outputs.write_npy(DFG_LUT_FILE, compute_dfg_lut())
        print(DFG_LUT_FILE)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
