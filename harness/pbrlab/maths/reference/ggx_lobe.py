"""Float64 quadrature of the GGX specular lobe over reflected directions, for the
references that need the lobe itself rather than one of its integrals in closed form.

For a view v (unit, n = +z, v.z > 0) and GGX roughness alpha, the lobe
f_spec(v, l) (n.l), f_spec = D G2 / (4 n.l n.v) (Walter et al. 2007 eq. 33 for D; Heitz 2014
eqs. 72, 99 for the height-correlated G2: directional_albedo.py's lobe without Fresnel), is
sampled by drawing the half vector h from D (n.h), inverting its cumulative on a midpoint grid
of (u1, u2) (Walter 2007 eq. 35: tan^2 theta = alpha^2 u1 / (1 - u1)), reflecting v about h,
and weighting each direction by the estimator G2 (v.h) / ((n.h)(n.v)) of
f_spec (n.l) / pdf(l). Sums of weight x g(l) are then integrals of the lobe times g over the
sphere (divided by nodes^2); a discontinuous g makes the rule first order, which the users'
tests measure by halving the grid.
"""

from __future__ import annotations

import numpy as np

from . import brdf


def _half_vectors(alpha: float, nodes: int) -> np.ndarray:
    """Half vectors around n = +z on a nodes x nodes midpoint grid of D (n.h)'s cumulative."""
    u = (np.arange(nodes) + 0.5) / nodes
    u1, u2 = np.meshgrid(u, u, indexing="ij")
    tan2 = alpha * alpha * u1 / (1.0 - u1)
    cos_t = 1.0 / np.sqrt(1.0 + tan2)
    sin_t = np.sqrt(np.maximum(1.0 - cos_t * cos_t, 0.0))
    phi = 2.0 * np.pi * u2
    return np.stack([sin_t * np.cos(phi), sin_t * np.sin(phi), cos_t], -1).reshape(-1, 3)


def reflected_lobe(alpha: float, v, nodes: int = 256):
    """(l, weight): reflected directions (N x 3) and their weights (N); weight 0 below n's horizon."""
    v = np.asarray(v, np.float64)
    h = _half_vectors(alpha, nodes)
    vh = h @ v
    l = 2.0 * vh[:, None] * h - v
    nl = l[:, 2]
    g2 = brdf.G2_SmithGGXCorrelated(np.maximum(nl, 1e-150), v[2], alpha)  # squared: no underflow
    weight = np.where((nl > 0.0) & (vh > 0.0), g2 * vh / (h[:, 2] * v[2]), 0.0)
    return l, weight
