"""Mip chains built on the CPU, so that no texture level depends on the host CPU.

Why not ``glGenerateMipmap``: llvmpipe writes each level of an sRGB texture through its
float -> sRGB8 encode (gallivm ``lp_build_linear_to_srgb``), which takes x^0.5 and x^0.375
from raw RSQRTPS, a 12-bit lookup whose bits differ between Intel and AMD processors. The
mips of a colour texture then differ by one code between vendors, and textured goldens with
them (docs/goldens.md, "Goldens"). Here every level is computed in float64 with a stated
filter and an exact encode, and uploaded as it is; sampling still decodes sRGB in hardware.

The filter: each level halves each side (GL's ``floor(n / 2)``, at least 1) with an
area-weighted box. An even side averages pairs; an odd side ``n = 2m + 1`` gives ``m``
texels, texel ``x`` weighting source texels ``2x, 2x+1, 2x+2`` by ``(m - x) / n``,
``m / n``, ``(x + 1) / n`` (the exact box over the footprint ``[x, x+1) * n / m``).

Colour (``srgb=True``): RGB decoded exactly (IEC 61966-2-1), filtered in linear light,
encoded by rounding to the nearest code of the exact curve; alpha is linear and filtered
as it is. Linear 8-bit data: filtered and rounded to nearest (halves up). Float data:
filtered in float64, stored as float32.
"""

from __future__ import annotations

import numpy as np

from . import srgb8


def level_count(width: int, height: int) -> int:
    """Levels of a full chain down to 1x1: 1 + floor(log2(max side))."""
    return int(max(width, height)).bit_length()


def _halve_axis(data: np.ndarray, axis: int) -> np.ndarray:
    n = data.shape[axis]
    if n == 1:
        return data
    m = n // 2
    take = lambda start: np.take(data, np.arange(start, start + 2 * m, 2), axis=axis)
    if n % 2 == 0:
        return 0.5 * (take(0) + take(1))
    shape = [1] * data.ndim
    shape[axis] = m
    x = np.arange(m, dtype=np.float64).reshape(shape)
    return ((m - x) * take(0) + m * take(1) + (x + 1) * take(2)) / n


def halve(data: np.ndarray) -> np.ndarray:
    """One level down: HxWxC float64 -> floor(H/2)xfloor(W/2)xC (each side at least 1)."""
    return _halve_axis(_halve_axis(data, 0), 1)


def mip_chain(image: np.ndarray, *, srgb: bool) -> list[np.ndarray]:
    """Every level of ``image`` (HxWxC, uint8 or float), level 0 first, each in the input's
    dtype (float input -> float32). Row order is kept: the filter is symmetric.

    8-bit data is filtered in code units (averages of integers: exact in float64, so
    "ties up" holds); sRGB colour channels are filtered as linear light."""
    colour = slice(0, 3) if (srgb and image.dtype == np.uint8) else slice(0, 0)
    work = image.astype(np.float64)
    if srgb and image.dtype == np.uint8:
        work[..., colour] = srgb8.DECODE_TABLE[image[..., colour]]
    levels = [image if image.dtype == np.uint8 else image.astype(np.float32)]
    for _ in range(1, level_count(image.shape[1], image.shape[0])):
        work = halve(work)
        if image.dtype != np.uint8:
            levels.append(work.astype(np.float32))
            continue
        level = np.clip(np.floor(work + 0.5), 0, 255).astype(np.uint8)
        level[..., colour] = srgb8.encode(work[..., colour])
        levels.append(level)
    return levels
