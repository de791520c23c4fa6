"""Float64 share of an environment's light that the geometric surface blocks under a normal map.

The shading normal n (a normal map's) is tilted from the geometric normal Ng. For a view v
and GGX roughness alpha, the specular environment light reflected towards v is, in a
uniform environment of radiance 1,

    E = int f_spec(v, l) (n.l)+ dl,   f_spec = D G2 / (4 n.l n.v)

(Walter et al. 2007 eq. 33 for D; Heitz 2014 eqs. 72, 99 for the height-correlated G2: the
lobe of directional_albedo.py without Fresnel). Light arriving from below the geometric
surface (l.Ng < 0) would pass through the object; the visible share is

    share = int f_spec (n.l)+ [l.Ng > 0] dl / E,

what a path tracer computes (Cycles evaluates no reflection below Ng) and what
pbr/ibl/horizon_occlusion.glsl approximates. Quadrature: ggx_lobe.py's; the indicator of
l.Ng > 0 makes the rule first order, so the tests measure its floor by halving the grid.

``lobe_share_above``, ``specular_horizon_occlusion`` and ``diffuse_horizon_occlusion`` are the
float64 twins of the GLSL closed forms (their derivation is in that file's header).
"""

from __future__ import annotations

import numpy as np

from . import ggx_lobe


def visible_share(alpha: float, v: np.ndarray, ng: np.ndarray, nodes: int = 256) -> float:
    """The share of the specular lobe at view v (unit, n = +z, v.z > 0) above the plane of ng."""
    l, weight = ggx_lobe.reflected_lobe(alpha, v, nodes)
    return float((weight * ((l @ np.asarray(ng, np.float64)) > 0.0)).sum() / weight.sum())


def lobe_share_above(c, alpha):
    """1/2 (1 + c / sqrt(4 alpha^2 + c^2)) (horizon_occlusion.glsl)."""
    c = np.asarray(c, np.float64)
    return 0.5 + 0.5 * c / np.sqrt(np.maximum(4.0 * alpha * alpha + c * c, 1e-300))


def specular_horizon_occlusion(RdotNg, NdotV, alpha):
    return np.minimum(lobe_share_above(RdotNg, alpha) / lobe_share_above(NdotV, alpha), 1.0)


def filament_horizon_occlusion(RdotNg):
    """Filament section 5.6.2.1 (after Russell 2015): min(1 + r.Ng, 1)^2, clamped at 0."""
    return np.clip(1.0 + np.asarray(RdotNg, np.float64), 0.0, 1.0) ** 2


def diffuse_horizon_occlusion(NdotNg):
    """The sky view factor of a plane tilted from the sky's: (1 + n.Ng) / 2."""
    return np.clip(0.5 + 0.5 * np.asarray(NdotNg, np.float64), 0.0, 1.0)


def diffuse_visible_share(n: np.ndarray, ng: np.ndarray, nodes: int = 512) -> float:
    """The share of the cosine lobe around n above the plane of ng (uniform environment),
    by a midpoint rule over the lobe's cumulative (cos^2 theta = 1 - u1)."""
    n = np.asarray(n, np.float64)
    ng = np.asarray(ng, np.float64)
    u = (np.arange(nodes) + 0.5) / nodes
    u1, u2 = np.meshgrid(u, u, indexing="ij")
    sin_t = np.sqrt(u1)
    cos_t = np.sqrt(1.0 - u1)
    phi = 2.0 * np.pi * u2
    local = np.stack([sin_t * np.cos(phi), sin_t * np.sin(phi), cos_t], -1).reshape(-1, 3)
    helper = np.array([1.0, 0.0, 0.0]) if abs(n[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
    t = np.cross(helper, n)
    t /= np.linalg.norm(t)
    b = np.cross(n, t)
    l = local @ np.stack([t, b, n])
    return float(np.mean((l @ ng) > 0.0))
