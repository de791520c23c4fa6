"""Exact 8-bit sRGB on the CPU: code -> linear by table, linear -> nearest code.

The hardware paths of llvmpipe approximate both directions (its encode takes x^0.5 and
x^0.375 from RSQRTPS, whose bits differ between CPU vendors), so everything a golden is made
of that needs an 8-bit sRGB value (texture mip levels, the display PNG) is computed here:
IEC 61966-2-1 in float64 (``pbrlab.maths.reference.color``), rounded to the nearest code.
"""

from __future__ import annotations

import numpy as np

from .reference.color import srgb_to_linear

DECODE_TABLE = srgb_to_linear(np.arange(256) / 255.0)  # linear value of each code
# Code k is chosen for linear values in [ENCODE_EDGES[k-1], ENCODE_EDGES[k]): the edges are
# the linear values of the code-space midpoints (k + 0.5) / 255, so this is rounding to the
# nearest code on the exact curve, ties up. Comparisons only: the same on every machine.
ENCODE_EDGES = srgb_to_linear((np.arange(255) + 0.5) / 255.0)


def encode(linear) -> np.ndarray:
    """Linear values (any shape; NaN and values <= 0 give 0, >= 1 give 255) -> uint8 codes.

    The same codes as ``np.searchsorted(ENCODE_EDGES, x, side="right")`` (tested), about 20x
    faster on a display image: the value's float32 bit pattern, shifted, indexes a table of
    the code at the start of each run of 2^12 float32s (no run spans two edges: a run is at
    most 2^-11 of its value wide, a code at least 0.9 % of its value, or 3e-4 absolute on the
    linear segment), then one comparison with each neighbouring edge, in float64, settles it."""
    x = np.clip(np.nan_to_num(np.asarray(linear, dtype=np.float64), nan=0.0), 0.0, 1.0)
    code = _RUN_CODE[x.astype(np.float32).view(np.uint32) >> _RUN_SHIFT].astype(np.int32)
    code += x >= _EDGE_ABOVE[code]    # past the edge above: one code up
    code -= x < _EDGE_BELOW[code]     # below the edge under it: one code down
    return code.astype(np.uint8)


# _EDGE_ABOVE[k]: the lowest linear value of code k + 1 (inf for 255); _EDGE_BELOW[k]: the
# lowest of code k (-inf for 0). A code is right when _EDGE_BELOW[k] <= x < _EDGE_ABOVE[k].
_EDGE_ABOVE = np.concatenate([ENCODE_EDGES, [np.inf]])
_EDGE_BELOW = np.concatenate([[-np.inf], ENCODE_EDGES])
_RUN_SHIFT = 12
_RUN_START = (np.arange((0x3F800000 >> _RUN_SHIFT) + 1, dtype=np.uint32) << _RUN_SHIFT).view(np.float32)
_RUN_CODE = np.searchsorted(ENCODE_EDGES, _RUN_START.astype(np.float64), side="right").astype(np.uint8)
