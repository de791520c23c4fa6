"""Exact 8-bit sRGB on the CPU: code -> linear by table, linear -> nearest code.

The hardware paths of llvmpipe approximate both directions (its encode takes x^0.5 and
x^0.375 from RSQRTPS, whose bits differ between CPU vendors), so everything a golden is made
of that needs an 8-bit sRGB value (texture mip levels, the display PNG) is computed here:
IEC 61966-2-1 in float64 (``pbrlab.reference.color``), rounded to the nearest code.
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
    """Linear values (any shape; NaN and values <= 0 give 0, >= 1 give 255) -> uint8 codes."""
    linear = np.nan_to_num(np.asarray(linear, dtype=np.float64), nan=0.0)
    return np.searchsorted(ENCODE_EDGES, linear, side="right").astype(np.uint8)
