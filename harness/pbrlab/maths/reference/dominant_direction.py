"""Float64 centroid of the GGX specular lobe, the direction a prefiltered environment is best
read along (pbr/ibl/dominant_direction.glsl), and that file's closed form.

The centroid is the normalised first moment of the lobe over reflected directions,
int l f_spec(v, l) (n.l) dl (ggx_lobe.py's quadrature): for a lobe that the prefilter
treats as symmetric about the read direction, the direction that keeps its first moment.
"""

from __future__ import annotations

import numpy as np

from . import ggx_lobe


def lobe_centroid(alpha: float, v, nodes: int = 256) -> np.ndarray:
    l, weight = ggx_lobe.reflected_lobe(alpha, v, nodes)
    m = (weight[:, None] * l).sum(0)
    return m / np.linalg.norm(m)


def specular_dominant_direction(n, r, alpha):
    """Filament's mix(r, n, alpha), normalised (n where that vanishes)."""
    d = np.asarray(r, np.float64) + (np.asarray(n, np.float64) - np.asarray(r, np.float64)) * alpha
    length = np.linalg.norm(d, axis=-1, keepdims=True)
    return np.where(length > 1e-6, d / np.maximum(length, 1e-300), np.asarray(n, np.float64))
