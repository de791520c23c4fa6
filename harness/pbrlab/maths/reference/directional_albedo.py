"""Float64 directional albedo of the GGX specular lobe, written from the integral.

For a view direction at mu = n.v and GGX roughness alpha (Walter et al. 2007, "Microfacet
Models for Refraction through Rough Surfaces", eq. 33) with Heitz's height-correlated Smith
masking-shadowing (Heitz 2014, "Understanding the Masking-Shadowing Function in
Microfacet-Based BRDFs", eqs. 72, 99), the split-sum terms (Karis 2013, "Real Shading in
Unreal Engine 4", eq. 8) are

    A(mu, alpha) = int_{H2} f_spec(l, v) (1 - (1 - v.h)^5) (n.l) dl
    B(mu, alpha) = int_{H2} f_spec(l, v) (1 - v.h)^5 (n.l) dl,   f_spec = D G2 / (4 n.l n.v),

so a Schlick Fresnel F0 + (F90 - F0)(1 - v.h)^5 reflects F0 A + F90 B and A + B is the
albedo at F = 1.

Quadrature (independent of the table code in harness/pbrlab/gpu/ibl.py): over the half
vector h = (theta, phi) around n, with dl = 4 (v.h) dh. Then the integrand is
D G2 F (v.h) / (n.v) sin(theta), and the horizon n.l > 0 is, for each theta, the closed
phi interval |phi| < phi_max(theta) (v in the xz plane):
    n.l = 2 (v.h)(n.h) - n.v > 0  <=>  cos(phi) > -cos(theta_v) cos(2 theta) / (sin(theta_v) sin(2 theta)),
full circle for theta < pi/4 - theta_v/2, empty past pi/4 + theta_v/2. theta is split into
panels at those two angles and at alpha * 4^k (D's scale, so every panel sees a smooth
lobe even at alpha = 0.002) and at the first of those angles times 4^k and below pi/2 by
(pi/2 - theta_end) 4^k (phi_max opens and closes on those scales when v grazes); each panel is Gauss-Legendre after x = a + (b - a)(1 - cos(pi t))/2,
which clusters nodes at both ends and removes the square-root behaviour of phi_max there;
phi is Gauss-Legendre on [0, phi_max]. Doubling every node count changes no value by
more than 1e-10 (tests/library/test_directional_albedo.py).
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np

THETA_NODES = 32   # Gauss-Legendre nodes per theta panel
PHI_NODES = 48     # Gauss-Legendre nodes on [0, phi_max]
PANEL_RATIO = 4.0  # successive theta panel edges alpha * 4^k


def _gl(n):
    x, w = np.polynomial.legendre.leggauss(n)
    return 0.5 * (x + 1.0), 0.5 * w  # nodes and weights on [0, 1]


def _D_ggx(cos_t, sin_t, alpha):
    """Walter 2007 eq. 33: alpha^2 / (pi (cos^2 (alpha^2 - 1) + 1)^2), written with
    cos^2 alpha^2 + sin^2 so that it has no cancellation near the peak."""
    a2 = alpha * alpha
    s = cos_t * cos_t * a2 + sin_t * sin_t
    return a2 / (np.pi * s * s)


def _lambda_ggx(mu, alpha):
    """Heitz 2014 eq. 72: Lambda = (-1 + sqrt(1 + alpha^2 tan^2)) / 2."""
    mu = np.maximum(mu, 1e-300)
    tan2 = np.maximum(1.0 - mu * mu, 0.0) / (mu * mu)
    return 0.5 * (np.sqrt(1.0 + alpha * alpha * tan2) - 1.0)


def _panels(alpha, theta_full, theta_end):
    edges = [0.0, theta_full, theta_end]
    for edge in (alpha, theta_full):  # D's scale; the scale on which phi_max opens up
        while 0.0 < edge < theta_end:
            edges.append(edge)
            edge *= PANEL_RATIO
    gap = 0.5 * np.pi - theta_end  # and mirrored below theta_end, where phi_max closes
    while 0.0 < gap < theta_end:
        edges.append(0.5 * np.pi - gap)
        gap *= PANEL_RATIO
    edges = np.unique(np.clip(edges, 0.0, theta_end))
    return edges[:-1], edges[1:]


def _half_vector_nodes(mu, alpha, theta_nodes, phi_nodes):
    """Nodes (theta, phi >= 0) of the half vector over the region n.l > 0 and their weights
    in dtheta dphi (times 2 for the mirrored phi < 0 half), with v = (sin theta_v, 0, mu)."""
    theta_v = np.arccos(mu)
    sin_v = np.sin(theta_v)
    theta_full = 0.25 * np.pi - 0.5 * theta_v
    theta_end = 0.25 * np.pi + 0.5 * theta_v
    t_nodes, t_weights = _gl(theta_nodes)
    p_nodes, p_weights = _gl(phi_nodes)
    lo, hi = _panels(alpha, theta_full, theta_end)
    # theta = lo + (hi - lo)(1 - cos(pi t)) / 2, dtheta = (hi - lo) pi sin(pi t) / 2 dt
    theta = lo[:, None] + (hi - lo)[:, None] * 0.5 * (1.0 - np.cos(np.pi * t_nodes))
    dtheta = (hi - lo)[:, None] * 0.5 * np.pi * np.sin(np.pi * t_nodes) * t_weights
    theta, dtheta = theta.ravel(), dtheta.ravel()
    with np.errstate(divide="ignore", invalid="ignore"):
        c = -mu * np.cos(2 * theta) / (sin_v * np.sin(2 * theta))
    c = np.where(theta < theta_full, -1.0, np.where(np.isnan(c), 1.0, c))
    phi_max = np.arccos(np.clip(c, -1.0, 1.0))
    phi = phi_max[:, None] * p_nodes[None, :]
    weight = 2.0 * dtheta[:, None] * phi_max[:, None] * p_weights[None, :]
    return theta[:, None] * np.ones_like(phi), phi, weight, sin_v


def light_quadrature(mu, alpha, theta_nodes=THETA_NODES, phi_nodes=PHI_NODES):
    """A quadrature over the light directions of the upper hemisphere, adapted to the GGX
    lobe of alpha seen from v = (sqrt(1 - mu^2), 0, mu), n = +z: unit l (N, 3) and weights
    (N,) in steradians such that int_{H2} g(l) dl ~ sum w g(l) for g symmetric about the
    plane of n and v (isotropic BRDFs). The nodes of split_sum_terms mapped through
    l = 2 (v.h) h - v, dl = 4 (v.h) dh."""
    mu, alpha = float(mu), float(alpha)
    theta, phi, weight, sin_v = _half_vector_nodes(mu, alpha, theta_nodes, phi_nodes)
    h = np.stack([np.sin(theta) * np.cos(phi), np.sin(theta) * np.sin(phi), np.cos(theta)], -1)
    v = np.array([sin_v, 0.0, mu])
    VdotH = h @ v
    l = 2.0 * VdotH[..., None] * h - v
    keep = l[..., 2] > 0.0
    return l[keep], (weight * np.sin(theta) * 4.0 * VdotH)[keep]


def split_sum_terms(mu, alpha, theta_nodes=THETA_NODES, phi_nodes=PHI_NODES):
    """(A, B) in float64 for one mu in (0, 1] and one alpha in (0, 1]."""
    mu, alpha = float(mu), float(alpha)
    if not (0.0 < mu <= 1.0 and 0.0 < alpha <= 1.0):
        raise ValueError(f"mu={mu}, alpha={alpha}: expected 0 < mu <= 1, 0 < alpha <= 1")
    theta, phi, weight, sin_v = _half_vector_nodes(mu, alpha, theta_nodes, phi_nodes)
    sin_t, cos_t = np.sin(theta), np.cos(theta)
    VdotH = sin_v * sin_t * np.cos(phi) + mu * cos_t
    NdotL = 2.0 * VdotH * cos_t - mu
    G2 = 1.0 / (1.0 + _lambda_ggx(mu, alpha) + _lambda_ggx(NdotL, alpha))
    G2 = np.where(NdotL > 0.0, G2, 0.0)
    # D V F (n.l) dl = D G2 F / (4 n.v) 4 (v.h) sin(theta) dtheta dphi
    base = _D_ggx(cos_t, sin_t, alpha) * sin_t * weight * G2 * VdotH / mu
    fc = (1.0 - np.clip(VdotH, 0.0, 1.0)) ** 5
    return float(np.sum(base * (1.0 - fc))), float(np.sum(base * fc))


def split_sum_terms_grid(mu, alpha, **kwargs):
    """split_sum_terms over broadcast arrays: (..., 2) float64."""
    mu, alpha = np.broadcast_arrays(np.asarray(mu, np.float64), np.asarray(alpha, np.float64))
    out = np.empty(mu.shape + (2,))
    for index in np.ndindex(mu.shape):
        out[index] = split_sum_terms(mu[index], alpha[index], **kwargs)
    return out


def specular_albedo(mu, alpha, f0, f90):
    """Directional albedo of the single-scattering GGX lobe with Schlick's F0, F90."""
    ab = split_sum_terms_grid(mu, alpha)
    return np.asarray(f0, np.float64) * ab[..., 0:1] + np.asarray(f90, np.float64) * ab[..., 1:2]


CURVE_NODES = 513       # nodes of t = sqrt(mu) on [0, 1] per alpha for the spline below
CURVE_MIN_MU = 1e-9     # mu of the t = 0 node (the mu -> 0 limit; E moves ~1e-6 there)


@lru_cache(maxsize=64)
def _curve(alpha: float):
    from scipy.interpolate import CubicSpline

    t = np.linspace(0.0, 1.0, CURVE_NODES)
    mu = np.maximum(t * t, CURVE_MIN_MU)
    values = np.array([split_sum_terms(m, alpha, theta_nodes=20, phi_nodes=24) for m in mu])
    return CubicSpline(t, values, axis=0)


def split_sum_terms_at_alpha(mu, alpha):
    """(A, B) (..., 2) for many mu at one alpha: a cubic spline in sqrt(mu) through
    CURVE_NODES exact values (20 x 24 nodes per panel, converged to 2e-8), cached per
    alpha. Its error against split_sum_terms is below 1e-6 (tested); for renderers."""
    return _curve(float(alpha))(np.sqrt(np.clip(np.asarray(mu, np.float64), 0.0, 1.0)))
