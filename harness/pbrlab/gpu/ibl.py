"""Image-based lighting data the harness generates for the library:

* ``dfg_lut()``: the split-sum environment BRDF table (A, B) over warped (NdotV,
  roughness) axes, integrated in float64 numpy with the library's own default visibility
  (exact height-correlated Smith GGX) by a deterministic quadrature in GGX's sampling
  variables (``integrate_dfg``). Karis 2013, "Real Shading in Unreal Engine 4", eq. 8 and
  its listing "IntegrateBRDF".
* ``prefiltered_environment(ctx, image)``: a cube map mip chain whose level i is the
  environment convolved with the GGX lobe of perceptual roughness i / (levels - 1), under
  Karis's n = v = r assumption: the mirror resampled on the GPU, the rough levels by the
  exact texel sum on the CPU (roughness 0.25 within a window around each tile of directions,
  box averages outside it: PREFILTER_WINDOW; before, filtered importance sampling on the GPU,
  Krivanek & Colbert 2008, which had no error bound), the brightest texels summed exactly at
  every rough level (split_bright); sampled with seamless cube filtering
  (ARB_seamless_cubemap_per_texture), so no level has a pole or a seam (issue 38: the former
  equirectangular chain, 8x4 at roughness 1, clamped the rows next to the poles and made a star
  at the zenith and nadir, up to 5x the radiance of the float64 brute force,
  maths/reference/prefilter.py). Accuracy and cost: docs/shading.md.

* ``irradiance_environment(ctx, image)``: a cube of the environment's irradiance over pi,
  E(n) / pi = sum L (n.w)+ dOmega / sum (n.w)+ dOmega over its texels (the image box-averaged
  to IRRADIANCE_SOURCE_WIDTH first), exact in float64 on the CPU: the Lambertian term of the
  scene programs (pbrlab_indirect). It replaces the order-2 spherical harmonics (Ramamoorthi &
  Hanrahan 2001), which cannot hold a sun's terminator: on Blender's sunrise a white sphere
  seen from the side was 30 % (median per pixel) off the exact irradiance with SH9, which the
  peers' convolved cube maps are not (issue 38). Dividing by the discrete sum of the cosine
  weights, not by pi, keeps a constant environment exactly constant.

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
from . import gl, targets
from ..foundation.errors import PbrlabError
from .programs import program_from_templates, template_source
from ..maths.reference import brdf as ref_brdf
from ..maths.reference import prefilter as ref_prefilter
from ..maths.reference import surface as ref_surface
from ..maths.reference import shading as ref_shading

# The chain: level i holds perceptual roughness i / (PREFILTER_LEVELS - 1) (the shaders'
# pbr_ibl_lod_from_perceptual_roughness), faces PREFILTER_FACE_SIZE >> i texels wide:
# 256^2 (the mirror) .. 16^2 (roughness 1), in steps of 0.25. Sizes (issue 38): the mirror's
# face of 256 texels spans 90 degrees, 0.35 degrees a texel at its centre, the equator texel
# of a 1024 x 512 environment (Blender's and the fidelity benchmark's); roughness 1 was read
# from 4^2 faces (22 degrees between texels) and its bilinear reconstruction of the lobe's
# cosine ramp past a sun missed the float64 brute force by 2x in the dark directions beside
# it; at 16^2 (5.6 degrees) that error is 16x smaller (h^2). Five levels, not six: a sixth
# at this base would be 8^2 at roughness 1, and a base of 512 would hold 6.3 M float texels.
PREFILTER_FACE_SIZE = 256  # texels per face edge of level 0 (the mirror)
PREFILTER_LEVELS = 5       # faces 256^2 ... 16^2: perceptual roughness 0, 0.25, ..., 1
# Bright texels (a sun, lamps): their radiance above PREFILTER_BRIGHT_FACTOR times the image's
# mean luminance is taken out of the image the rough levels box-average and summed exactly,
# texel by texel at the image's own resolution (prefilter_bright_sum), at most
# PREFILTER_BRIGHT_TEXELS of them (the threshold rises to keep to that): a sun 10^4 times the
# sky averaged into a 2.8 to 5.6-degree cell would move its light by up to half a cell. (The
# split began with filtered importance sampling, whose mip blur leaked such a sun several lobe
# widths away: issue 38, up to 2x the float64 brute force at roughness 1, 37 % at 0.2.)
PREFILTER_BRIGHT_FACTOR = 16.0
# The irradiance cube: faces 32^2 (2.8 degrees a texel at a face's centre: bilinear
# reconstruction of a cosine-convolved function, whose curvature is at most that of cos, errs
# by at most h^2/8 = 3e-4 of its peak), summed from the image averaged to 128 x 64 (a sun
# spread over 2.8 degrees: the cosine lobe moves by sin(1.4 degrees) = 2.4 % of its peak at
# most, on the terminator only).
IRRADIANCE_FACE_SIZE = 32
IRRADIANCE_SOURCE_WIDTH = 128
# Levels from PREFILTER_CPU_FIRST_LEVEL on (perceptual roughness >= 0.25) are the exact texel
# sum of the clipped image box-averaged (solid-angle weighted) to PREFILTER_CPU_SOURCE_WIDTH[level]
# x half that, in float64 on the CPU: FIS's mip blur read the equirect mips' pole rows and
# smeared the horizon (up to 38 % at roughness 1 after the bright split), and at roughness 0.25
# it had no error bound (issue 38: 16 and 47 of 242 directions over the test's bound, up to
# 2.8x it); the sum is the brute force itself at a cell size inside the lobe. Roughness 0.25
# (its lobe's half maximum 4.6 degrees from n) reads a source of 128 x 64 (2.8 degrees a texel
# at the equator; 256 x 128 cost 2x to 9x the time, and the level's error on sunrise and studio
# stays that of the bright texels' sum, 2 %), and only inside a window (PREFILTER_WINDOW):
# every direction against every texel would be 8e8 products for 128^2 faces.
PREFILTER_CPU_FIRST_LEVEL = 1
PREFILTER_CPU_SOURCE_WIDTH = {1: 128, 2: 64, 3: 64, 4: 64}
# The windowed sum (_windowed_texel_sum), for the levels named here: the level's faces in tiles
# of tile x tile texels; for each tile, the source texels within radius degrees of every
# direction of the tile are summed at the level's source width, all others at the outer
# width's box averages (one cell per block of source texels). That is a texel sum over another
# partition of the sphere, exact where the lobe's weight is constant over each outer cell; the
# difference from the full sum is
#   sum over outer blocks B, their texels f: (L_f - T) Omega_f (w(n.c_B) - w(n.c_f)) / sum w Omega
# (T the full sum), which the test bounds with |L_f - T| (tests/render/test_prefiltered_environment.py,
# E_window). Beyond 15 degrees from n the GGX lobe of alpha 1/16 holds 16 % of its mass (3.4 %
# beyond 30, maths/reference/prefilter.py's lobe_weight integrated) and falls as angle^-4, so
# w(n.c_B) - w(n.c_f) is first order in the block's 5.6 degrees and changes sign across the
# block: measured, the window moves level 1 by at most 1.1e-3 (sunrise) and 2.0e-3 (studio) of
# the local mean, against the full sum (256 x 128, poles, seam, sun, random directions).
# Radius 10 degrees: 3e-3 on sunrise; 30 degrees: 1.5e-4 at about 6x the time.
PREFILTER_WINDOW = {1: {"radius": 15.0, "outer_width": 64, "tile": 8}}
PREFILTER_BRIGHT_TEXELS = 4096
LUMINANCE = np.array([0.2126, 0.7152, 0.0722])  # ITU-R BT.709 (the library's pbr_luminance)

# The DFG table: layout (size and warped axes) in reference/surface.py and
# glsl/pbr/ibl/environment_brdf.glsl; values from integrate_dfg, stored in
# data/dfg_lut.npy (computing 256 x 256 texels takes about a minute, so it is made once by
# `python -m pbrlab.gpu.ibl --write-dfg` and checked by tests/surface/test_dfg_table.py).
DFG_LUT_FILE = Path(__file__).resolve().parent / "data" / "dfg_lut.npy"
# The LOW tier's table (PBR_DFG_LUT_LAYOUT_SQRT: x = sqrt(NdotV), y = perceptual roughness),
# made and checked the same way (about 15 s); its rows below PBR_MIN_PERCEPTUAL_ROUGHNESS hold
# that roughness's values (no tier reads below it, and alpha -> 0 is a mirror's singular lobe).
DFG_LUT_FILES = {"WARPED": DFG_LUT_FILE,
                 "SQRT": Path(__file__).resolve().parent / "data" / "dfg_lut_sqrt.npy"}
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


def compute_dfg_lut(layout: str = "WARPED") -> np.ndarray:
    """HEIGHT x WIDTH x 2 float32, image order (top row first = the last row, y = 1): texel
    (i, j) of GL row j holds (A, B) at the axes of ``layout`` (reference/surface.py
    dfg_lut_nodes, dfg_lut_axes)."""
    xs, ys = ref_surface.dfg_lut_nodes(layout)
    y, x = np.meshgrid(ys, xs, indexing="ij")
    NdotV, rough = ref_surface.dfg_lut_texel_coordinates(x, y, layout)
    if layout == "SQRT":  # rows below the library's smallest roughness: its values
        rough = np.maximum(rough, ref_shading.MIN_PERCEPTUAL_ROUGHNESS)
    rows = [integrate_dfg(NdotV[j], rough[j]) for j in range(len(ys))]
    return np.stack(rows)[::-1].astype(np.float32)


@lru_cache(maxsize=2)
def dfg_lut(layout: str = "WARPED") -> np.ndarray:
    """The shipped table of ``layout`` (data/dfg_lut[_sqrt].npy), HEIGHT x WIDTH x 2 float32,
    image order."""
    path = DFG_LUT_FILES[layout]
    if not path.exists():
        raise PbrlabError(f"{path} is missing; create it with python -m pbrlab.gpu.ibl --write-dfg")
    table = np.load(path)
    if table.shape != (ref_surface.DFG_LUT_HEIGHT, ref_surface.DFG_LUT_WIDTH, 2):
        raise PbrlabError(f"{path}: shape {table.shape} is not the layout's; "
                          "regenerate it with python -m pbrlab.gpu.ibl --write-dfg")
    return table


def dfg_texture(ctx: moderngl.Context, layout: str = "WARPED") -> moderngl.Texture:
    return targets.lookup_table_texture(ctx, dfg_lut(layout))


def prefiltered_environment(ctx: moderngl.Context, image: np.ndarray) -> moderngl.TextureCube:
    """The GGX-prefiltered cube mip chain of an equirectangular radiance image (HxWx3,
    linear), as an RGBA32F cube texture with PREFILTER_LEVELS levels, trilinear and seamless
    (see module docstring). The levels come from the disk cache when an earlier process
    filtered the same image with the same program on the same driver (_prefilter_cache_key):
    256 samples per texel cost llvmpipe a good part of a render's start-up (issue 25)."""
    name = _prefilter_cache_key(ctx, image)
    levels = disk_cache.load("prefiltered-environment", name, _decode_levels)
    if levels is None:
        levels = _prefilter_levels(ctx, image)
        disk_cache.store("prefiltered-environment", name, disk_cache.pack_arrays(levels))
    return float_cube_from_levels(ctx, levels)


def _decode_levels(payload: bytes) -> list[np.ndarray]:
    """A prefiltered environment's entry: PREFILTER_LEVELS float32 arrays of 6 x n x n x 4,
    n = prefilter_level_size(level); ValueError when the payload is anything else."""
    levels = disk_cache.unpack_arrays(payload)
    expected = [(6, prefilter_level_size(level), prefilter_level_size(level), 4) for level in range(PREFILTER_LEVELS)]
    if [level.shape for level in levels] != expected or any(level.dtype != np.float32 for level in levels):
        raise ValueError(f"levels {[(level.dtype.name, level.shape) for level in levels]}, not float32 {expected}")
    return levels


# OpenGL 4.6 core: section 8.13 (cube map targets, one per face, +X, -X, +Y, -Y, +Z, -Z in
# order), table 8.20 (GL_TEXTURE_MAX_LEVEL); ARB_seamless_cubemap_per_texture (the per-texture
# TEXTURE_CUBE_MAP_SEAMLESS, the same enum as the global enable of OpenGL 3.2).
_GL_TEXTURE_CUBE_MAP = 0x8513
_GL_TEXTURE_CUBE_MAP_POSITIVE_X = 0x8515
_GL_TEXTURE_MAX_LEVEL = 0x813D
_GL_TEXTURE_CUBE_MAP_SEAMLESS = 0x884F
_GL_RGBA32F, _GL_RGBA, _GL_FLOAT = 0x8814, 0x1908, 0x1406
_GL_UNPACK_ALIGNMENT = 0x0CF5


def float_cube_from_levels(ctx: moderngl.Context, levels) -> moderngl.TextureCube:
    """An RGBA32F cube texture whose mip levels are ``levels`` (each 6 x n x n x 4 float32,
    faces +X, -X, +Y, -Y, +Z, -Z, rows in GL order, level 0 first), trilinear, with seamless
    filtering across the faces' edges: per texture where the driver has
    ARB_seamless_cubemap_per_texture (llvmpipe has; then the scene's other cube maps,
    scene/cubemap.py, filter as before), else the context-wide enable of OpenGL 3.2."""
    first = np.ascontiguousarray(levels[0], np.float32)
    size = first.shape[1]
    tex = ctx.texture_cube((size, size), 4, first.tobytes(), dtype="f4")
    unit = ctx.info["GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS"] - 1  # as targets._upload_levels
    tex.use(unit)
    tex_image_2d = gl.gl_function(ctx, "glTexImage2D")
    tex_parameter = gl.gl_function(ctx, "glTexParameteri")
    gl.gl_function(ctx, "glPixelStorei")(_GL_UNPACK_ALIGNMENT, 1)
    for index, level in enumerate(levels[1:], start=1):
        faces = np.ascontiguousarray(level, np.float32)
        edge = faces.shape[1]
        for face in range(6):
            data = np.ascontiguousarray(faces[face])
            tex_image_2d(_GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, index, _GL_RGBA32F, edge, edge, 0,
                         _GL_RGBA, _GL_FLOAT, data.ctypes.data)  # copies before returning
    tex_parameter(_GL_TEXTURE_CUBE_MAP, _GL_TEXTURE_MAX_LEVEL, len(levels) - 1)
    if "GL_ARB_seamless_cubemap_per_texture" in ctx.extensions:
        tex_parameter(_GL_TEXTURE_CUBE_MAP, _GL_TEXTURE_CUBE_MAP_SEAMLESS, 1)
    else:
        ctx.enable_direct(_GL_TEXTURE_CUBE_MAP_SEAMLESS)
    tex.filter = (moderngl.LINEAR_MIPMAP_LINEAR, moderngl.LINEAR)
    return tex


def irradiance_faces(image: np.ndarray) -> np.ndarray:
    """6 x IRRADIANCE_FACE_SIZE^2 x 4 float32 (faces +X .. -Z, GL rows, alpha 1): E(n) / pi
    at every texel centre's direction (module docstring)."""
    source = box_average(np.asarray(image, np.float64)[..., :3], IRRADIANCE_SOURCE_WIDTH)
    d, solid = ref_prefilter.equirect_texels(*source.shape[:2])
    d, solid, radiance = d.reshape(-1, 3), solid.reshape(-1), source.reshape(-1, 3)
    normals = ref_prefilter.cube_face_directions(IRRADIANCE_FACE_SIZE).reshape(-1, 3)
    out = np.empty((len(normals), 3))
    for start, stop in _blocks(len(normals), len(d)):
        w = np.maximum(normals[start:stop] @ d.T, 0.0) * solid
        out[start:stop] = (w @ radiance) / w.sum(axis=1, keepdims=True)
    faces = np.ones((len(normals), 4), np.float32)
    faces[:, :3] = out
    return faces.reshape(6, IRRADIANCE_FACE_SIZE, IRRADIANCE_FACE_SIZE, 4)


def irradiance_environment(ctx: moderngl.Context, image: np.ndarray) -> moderngl.TextureCube:
    """The irradiance cube (irradiance_faces) as a seamless, bilinear RGBA32F cube texture."""
    return float_cube_from_levels(ctx, [irradiance_faces(image)])


def black_cube(ctx: moderngl.Context) -> moderngl.TextureCube:
    """A 1x1 black cube: what the full program samples in a scene without environment."""
    return ctx.texture_cube((1, 1), 4, np.zeros(6 * 4, np.float32).tobytes(), dtype="f4")


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
                          PREFILTER_FACE_SIZE, PREFILTER_LEVELS, Path(__file__).read_bytes())


def prefilter_level_roughness(level: int) -> float:
    """The perceptual roughness level ``level`` is filtered for: level / (PREFILTER_LEVELS - 1),
    the inverse of pbr_ibl_lod_from_perceptual_roughness (glsl/pbr/ibl/environment_brdf.glsl)."""
    return level / (PREFILTER_LEVELS - 1)


def prefilter_level_size(level: int) -> int:
    """Texels per face edge of a level: PREFILTER_FACE_SIZE halved per level (a mip chain)."""
    return max(PREFILTER_FACE_SIZE >> level, 1)


def lobe_normalisation(alpha: float) -> float:
    """N(alpha) = integral of D(h) (n.l)+ over l, h the bisector of n and l (the prefilter's
    weight, maths/reference/prefilter.py). With dl = 4 (h.l) dh = 4 (n.h) dh and
    n.l = 2 (n.h)^2 - 1, in s = (n.h)^2 over [1/2, 1]: N = 4 pi int D(s) (2 s - 1) ds, and with
    D = alpha^2 / (pi (1 - b s)^2), b = 1 - alpha^2 (Walter et al. 2007, eq. 33), the
    antiderivative of (2 s - 1) / (1 - b s)^2 is (2 / b^2) ln(1 - b s) + (2 - b) / (b^2 (1 - b s)).
    At alpha = 1 (b = 0) D = 1 / pi and N = 1."""
    b = 1.0 - alpha * alpha
    if b < 1e-6:
        return 1.0

    def antiderivative(x):
        return (2.0 / b**2) * np.log1p(-b * x) + (2.0 - b) / (b**2 * (1.0 - b * x))
    return float(4.0 * alpha * alpha * (antiderivative(1.0) - antiderivative(0.5)))


def split_bright(image: np.ndarray):
    """(the image with its bright texels clipped, the bright excess as (directions (K, 3),
    solid angles (K,), radiance (K, 3))), float64; see PREFILTER_BRIGHT_FACTOR."""
    rgb = np.asarray(image[..., :3], np.float64)
    lum = np.maximum(rgb @ LUMINANCE, 0.0)
    threshold = PREFILTER_BRIGHT_FACTOR * float(lum.mean())
    if lum.size > PREFILTER_BRIGHT_TEXELS:
        threshold = max(threshold, float(np.partition(lum.reshape(-1), -PREFILTER_BRIGHT_TEXELS - 1)[
            -PREFILTER_BRIGHT_TEXELS - 1]))
    bright = lum > threshold
    keep = np.where(bright, threshold / np.where(bright, lum, 1.0), 1.0)[..., None]
    clipped = rgb * keep
    d, solid = ref_prefilter.equirect_texels(*rgb.shape[:2])
    return clipped, (d[bright], solid[bright], (rgb - clipped)[bright])


def prefilter_bright_sum(directions: np.ndarray, bright, perceptual_roughness: float) -> np.ndarray:
    """The bright texels' share of the prefiltered radiance at unit directions (M, 3):
    sum of L D(h) (n.l)+ dOmega over the texels, over N(alpha) (lobe_normalisation)."""
    d, solid, radiance = bright
    out = np.zeros((directions.shape[0], 3))
    if len(d) == 0:
        return out
    alpha = perceptual_roughness ** 2
    scale = (alpha * alpha / np.pi) / lobe_normalisation(alpha)
    for start, stop in _blocks(directions.shape[0], len(d)):
        w = _lobe_weight_unscaled(directions[start:stop] @ d.T, alpha)
        w *= solid * scale
        out[start:stop] = w @ radiance
    return out


# Directions x texels per block of the CPU sums: 2^18 float64 (2 MiB) stay in a core's cache;
# one product over every direction at once (98 k x 2048 at level 1) was memory-bound, 4x slower.
_BLOCK_ELEMENTS = 1 << 18


def _blocks(directions: int, texels: int):
    step = max(1, _BLOCK_ELEMENTS // max(texels, 1))
    return [(start, min(start + step, directions)) for start in range(0, directions, step)]


def _prefilter_levels(ctx: moderngl.Context, image: np.ndarray) -> list[np.ndarray]:
    """The PREFILTER_LEVELS levels, each 6 x n x n x 4 float32 (faces +X .. -Z, GL row
    order): the mirror resamples the whole image on the GPU; the rough levels are the clipped
    image's exact texel sum on the CPU (windowed for the levels in PREFILTER_WINDOW), plus the
    bright texels' exact sum (split_bright)."""
    clipped, bright = split_bright(image)
    levels = [_mirror_level(ctx, image)]
    for level in range(PREFILTER_CPU_FIRST_LEVEL, PREFILTER_LEVELS):
        edge = prefilter_level_size(level)
        directions = ref_prefilter.cube_face_directions(edge).reshape(-1, 3)
        roughness = prefilter_level_roughness(level)
        source = box_average(clipped, PREFILTER_CPU_SOURCE_WIDTH[level])
        faces = np.ones((6, edge, edge, 4), np.float32)
        if level in PREFILTER_WINDOW:
            faces[..., :3] = _windowed_texel_sum(edge, source, roughness, PREFILTER_WINDOW[level])
        else:
            faces[..., :3] = _texel_sum(directions, source, roughness).reshape(6, edge, edge, 3)
        faces[..., :3] += prefilter_bright_sum(directions, bright, roughness).reshape(6, edge, edge, 3)
        levels.append(faces)
    return levels


def box_average(image: np.ndarray, width: int) -> np.ndarray:
    """The equirect image averaged over blocks to width x width / 2, each texel weighted by its
    solid angle (rows near the poles are smaller); the image itself when it is not a whole
    multiple of that size."""
    h, w = image.shape[:2]
    height = width // 2
    if w % width or h % height or w < width:
        return np.asarray(image, np.float64)
    _, solid = ref_prefilter.equirect_texels(h, w)
    fy, fx = h // height, w // width
    weighted = (np.asarray(image, np.float64)[..., :3] * solid[..., None]).reshape(height, fy, width, fx, 3)
    return weighted.sum(axis=(1, 3)) / solid.reshape(height, fy, width, fx).sum(axis=(1, 3))[..., None]


def _texel_sum(directions: np.ndarray, image: np.ndarray, perceptual_roughness: float) -> np.ndarray:
    """sum L D(h) (n.l)+ dOmega / sum D(h) (n.l)+ dOmega over the image's texels (their centres,
    exact solid angles): the brute force of maths/reference/prefilter.py with the image held
    constant over each texel."""
    d, solid = ref_prefilter.equirect_texels(*image.shape[:2])
    d, solid, radiance = d.reshape(-1, 3), solid.reshape(-1), image.reshape(-1, 3)
    out = np.empty((directions.shape[0], 3))
    for start, stop in _blocks(directions.shape[0], len(d)):
        out[start:stop] = _weighted_mean(directions[start:stop], (d, solid, radiance), perceptual_roughness)
    return out


def _weighted_mean(directions: np.ndarray, texels, perceptual_roughness: float) -> np.ndarray:
    """The lobe-weighted mean of texels (directions (K, 3), solid angles (K,), radiance (K, 3))
    at each of the directions (M, 3): sum L w dOmega / sum w dOmega, w = D(h) (n.l)+."""
    d, solid, radiance = texels
    w = _lobe_weight_unscaled(directions @ d.T, perceptual_roughness ** 2)
    w *= solid
    return (w @ radiance) / w.sum(axis=1, keepdims=True)


class WindowedSource:
    """The source of a windowed texel sum (PREFILTER_WINDOW): an equirect image's texels
    grouped in the blocks that box_average merges into one texel of outer_width x half that,
    and those blocks' averages (the image itself, blocks of one texel, when it is not a whole
    multiple of that size)."""

    def __init__(self, image: np.ndarray, outer_width: int):
        h, w = image.shape[:2]
        outer = box_average(image, outer_width)
        rows, cols = outer.shape[:2]
        fy, fx = h // rows, w // cols
        d, solid = ref_prefilter.equirect_texels(h, w)

        def by_block(values):  # (h, w, c) -> (blocks, fy * fx, c), blocks in the outer image's order
            return values.reshape(rows, fy, cols, fx, -1).transpose(0, 2, 1, 3, 4).reshape(rows * cols, fy * fx, -1)
        self.texel_d, self.texel_solid = by_block(d), by_block(solid[..., None])[..., 0]
        self.texel_radiance = by_block(np.asarray(image, np.float64)[..., :3])
        outer_d, outer_solid = ref_prefilter.equirect_texels(rows, cols)
        self.outer = (outer_d.reshape(-1, 3), outer_solid.reshape(-1), outer.reshape(-1, 3))
        # Each block's radius: the largest angle between its centre and its texels' centres.
        cos_radius = np.einsum("bkc,bc->bk", self.texel_d, self.outer[0]).min(axis=1)
        self.block_radius = np.arccos(np.clip(cos_radius, -1.0, 1.0))

    def inside(self, directions: np.ndarray, radius_degrees: float) -> np.ndarray:
        """The blocks (bool per block) that may hold a texel within radius_degrees of one of
        the directions (M, 3), found from their centre c: every block left out lies wholly
        farther than the radius from every direction (angle(c, m) - block radius > radius
        + the directions' spread around their mean m)."""
        m = directions.sum(axis=0)
        m /= np.linalg.norm(m)
        spread = np.arccos(np.clip(directions @ m, -1.0, 1.0)).max()
        angle = np.arccos(np.clip(self.outer[0] @ m, -1.0, 1.0))
        return angle - self.block_radius <= np.radians(radius_degrees) + spread

    def texels(self, inside: np.ndarray):
        """(directions, solid angles, radiance) of the partition: the texels of the blocks
        inside, the averages of the blocks outside."""
        d, solid, radiance = self.outer
        return (np.concatenate([self.texel_d[inside].reshape(-1, 3), d[~inside]]),
                np.concatenate([self.texel_solid[inside].reshape(-1), solid[~inside]]),
                np.concatenate([self.texel_radiance[inside].reshape(-1, 3), radiance[~inside]]))


def window_tiles(edge: int, tile: int):
    """The tiles of a level's faces: (face, row slice, column slice) of tile x tile texels
    (the last tile of a row or column narrower when tile does not divide edge)."""
    spans = [slice(start, min(start + tile, edge)) for start in range(0, edge, tile)]
    return [(face, rows, cols) for face in range(6) for rows in spans for cols in spans]


def _windowed_texel_sum(edge: int, image: np.ndarray, perceptual_roughness: float, window) -> np.ndarray:
    """6 x edge x edge x 3: _texel_sum at the level's texel centres over the partition
    WindowedSource.texels makes per tile (PREFILTER_WINDOW)."""
    source = WindowedSource(image, window["outer_width"])
    directions = ref_prefilter.cube_face_directions(edge)
    out = np.empty((6, edge, edge, 3))
    for face, rows, cols in window_tiles(edge, window["tile"]):
        n = directions[face, rows, cols].reshape(-1, 3)
        texels = source.texels(source.inside(n, window["radius"]))
        out[face, rows, cols] = _weighted_mean(n, texels, perceptual_roughness).reshape(
            rows.stop - rows.start, cols.stop - cols.start, 3)
    return out


def _lobe_weight_unscaled(NdotL: np.ndarray, alpha: float) -> np.ndarray:
    """D(h) (n.l)+ times pi / alpha^2, in place of NdotL: (n.l)+ / ((n.h)^2 (alpha^2 - 1) + 1)^2
    with (n.h)^2 = (1 + n.l) / 2 (Walter et al. 2007, eq. 33; h the bisector of n and l)."""
    np.maximum(NdotL, 0.0, out=NdotL)
    q = NdotL + 1.0
    q *= 0.5 * (alpha * alpha - 1.0)
    q += 1.0
    q *= q
    NdotL /= q
    return NdotL


def _mirror_level(ctx: moderngl.Context, image: np.ndarray) -> np.ndarray:
    """Level 0 (6 x n x n x 4, faces +X .. -Z, GL row order): the image resampled (bilinear)
    at the texel directions on the GPU (prefilter.frag)."""
    source = targets.upload_texture(ctx, np.concatenate(
        [image[..., :3], np.ones(image.shape[:2] + (1,), image.dtype)], axis=2).astype(np.float32),
        srgb=False)
    source.repeat_x, source.repeat_y = True, False
    program = program_from_templates(ctx, "fullscreen.vert", "prefilter.frag", {})
    vao = ctx.vertex_array(program, [])
    edge = prefilter_level_size(0)
    faces = []
    try:
        with targets.Target(ctx, (edge, edge), "f32", depth=False) as target:
            for face in range(6):
                target.use()
                source.use(0)
                program["u_source"].value = 0
                program["u_face"].value = face
                program["u_face_size"].value = float(edge)
                vao.render(moderngl.TRIANGLES, vertices=3)
                faces.append(np.ascontiguousarray(target.read()[::-1]))  # back to GL row order
    finally:
        vao.release()
        source.release()
    return np.stack(faces)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="python -m pbrlab.gpu.ibl", description=__doc__.splitlines()[0])
    parser.add_argument("--write-dfg", action="store_true", help="recompute the DFG tables (data/dfg_lut*.npy)")
    args = parser.parse_args(argv)
    if args.write_dfg:
        DFG_LUT_FILE.parent.mkdir(exist_ok=True)
        for layout, path in DFG_LUT_FILES.items():
            outputs.write_npy(path, compute_dfg_lut(layout))
            print(path)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
