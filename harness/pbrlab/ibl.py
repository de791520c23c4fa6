"""Image-based lighting data the harness generates for the library:

* ``dfg_lut(n)``: the split-sum environment BRDF table (A, B) over (NdotV, perceptual
  roughness), integrated in float64 numpy with the library's own default visibility
  (exact height-correlated Smith GGX) by GGX importance sampling. Karis 2013, "Real
  Shading in Unreal Engine 4", eq. 8 and its listing "IntegrateBRDF".
* ``prefiltered_environment(ctx, image)``: an equirectangular mip chain whose level i is
  the environment convolved with the GGX lobe of perceptual roughness i / (levels - 1),
  under Karis's n = v = r assumption, computed on the GPU by GGX importance sampling with
  filtered importance sampling (Krivanek & Colbert 2008, "Real-time Shading with Filtered
  Importance Sampling", eq. 10) to avoid noise.

The GLSL side reads them through pbr/ibl/environment_brdf.glsl
(``PBR_DFG_LUT_LOOKUP`` hook, ``pbr_ibl_lod_from_perceptual_roughness``).
"""

from __future__ import annotations

from functools import lru_cache

import moderngl
import numpy as np

from . import targets
from .programs import program_from_templates
from .reference import brdf as ref_brdf

DFG_LUT_SIZE = 32          # texels per axis; sampled at texel centres with bilinear filtering
DFG_SAMPLES = 1024         # Hammersley points per texel
PREFILTER_SIZE = (256, 128)  # level 0 of the prefiltered chain (equirect 2:1)
PREFILTER_LEVELS = 6       # 256x128 ... 8x4: perceptual roughness 0, 0.2, ..., 1
PREFILTER_SAMPLES = 256    # GGX samples per texel (filtered importance sampling)


def hammersley(count: int) -> np.ndarray:
    """count x 2 Hammersley points: (i/count, base-2 radical inverse of i)."""
    i = np.arange(count, dtype=np.uint64)
    bits = i.copy()
    rev = np.zeros_like(bits)
    for b in range(32):
        rev |= ((bits >> np.uint64(b)) & np.uint64(1)) << np.uint64(31 - b)
    return np.stack([i / count, rev.astype(np.float64) / 2.0**32], axis=1)


def integrate_dfg(NdotV, perceptual_roughness, samples: int = DFG_SAMPLES) -> np.ndarray:
    """(A, B) of the split sum for arrays of NdotV and perceptual roughness (float64).

    A + B is the directional albedo of the specular lobe at f0 = 1; f0*A + B at f0.
    """
    NdotV = np.asarray(NdotV, np.float64)[..., None]
    alpha = (np.asarray(perceptual_roughness, np.float64) ** 2)[..., None]
    xi = hammersley(samples)
    # GGX half vectors (Walter et al. 2007, eqs. 35-36), tangent space with n = +z.
    phi = 2 * np.pi * xi[:, 0]
    cos_h = np.sqrt((1 - xi[:, 1]) / (1 + (alpha * alpha - 1) * xi[:, 1]))
    sin_h = np.sqrt(np.maximum(1 - cos_h * cos_h, 0))
    hx, hy, hz = sin_h * np.cos(phi), sin_h * np.sin(phi), cos_h
    vx, vz = np.sqrt(np.maximum(1 - NdotV * NdotV, 0)), NdotV  # v in the xz plane
    VdotH = vx * hx + vz * hz
    NdotL = 2 * VdotH * hz - vz  # l = 2 (v.h) h - v
    valid = (NdotL > 0) & (VdotH > 0)
    NdotL_c = np.where(valid, NdotL, 1.0)
    vis = ref_brdf.V_SmithGGXCorrelated(NdotL_c, NdotV, alpha)
    # f cos / pdf with pdf_l = D NdotH / (4 VdotH): V * F * NdotL * 4 VdotH / NdotH
    weight = np.where(valid, vis * NdotL_c * 4 * VdotH / hz, 0.0)
    fc = (1 - np.clip(VdotH, 0, 1)) ** 5
    return np.stack([np.mean((1 - fc) * weight, axis=-1), np.mean(fc * weight, axis=-1)], axis=-1)


@lru_cache(maxsize=4)
def dfg_lut(size: int = DFG_LUT_SIZE) -> np.ndarray:
    """size x size x 2 float32 table; row j is perceptual roughness (j+0.5)/size, column i
    NdotV (i+0.5)/size (texel centres), top row first = roughness 1 (image order)."""
    centres = (np.arange(size) + 0.5) / size
    rough, ndotv = np.meshgrid(centres, centres, indexing="ij")
    table = integrate_dfg(ndotv, rough)
    return table[::-1].astype(np.float32)


def dfg_texture(ctx: moderngl.Context) -> moderngl.Texture:
    tex = targets.upload_texture(ctx, dfg_lut(), srgb=False)
    tex.filter = (moderngl.LINEAR, moderngl.LINEAR)
    tex.repeat_x = tex.repeat_y = False
    return tex


def prefiltered_environment(ctx: moderngl.Context, image: np.ndarray) -> moderngl.Texture:
    """The GGX-prefiltered mip chain of an equirectangular radiance image (HxWx3, linear),
    as an RGBA32F texture with PREFILTER_LEVELS levels (see module docstring)."""
    source = targets.upload_texture(ctx, np.concatenate(
        [image[..., :3], np.ones(image.shape[:2] + (1,), image.dtype)], axis=2).astype(np.float32),
        srgb=False)
    source.repeat_x, source.repeat_y = True, False
    program = program_from_templates(ctx, "fullscreen.vert", "prefilter.frag", {})
    vao = ctx.vertex_array(program, [])
    w0, h0 = PREFILTER_SIZE
    result = ctx.texture((w0, h0), 4, dtype="f4")
    result.build_mipmaps(0, PREFILTER_LEVELS - 1)
    source_levels = 1 + int(np.floor(np.log2(max(image.shape[0], image.shape[1]))))
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
                data = target.read()[::-1]  # back to GL row order for the write
                result.write(np.ascontiguousarray(data).tobytes(), level=level)
    finally:
        vao.release()
        source.release()
    result.filter = (moderngl.LINEAR_MIPMAP_LINEAR, moderngl.LINEAR)
    result.repeat_x, result.repeat_y = True, False
    return result
