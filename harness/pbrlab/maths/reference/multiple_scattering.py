"""Float64 directional albedo of GGX with multiple scattering, for a coloured Schlick F0.

Two independent references of the albedo pbr_energy_compensation approximates
(glsl/pbr/ibl/environment_brdf.glsl):

* Kulla & Conty 2017, "Revisiting Physically Based Shading at Imageworks" (SIGGRAPH course,
  slides 18-20): the multiply scattered lobe f_ms(mu_o, mu_i) = (1 - E(mu_o))(1 - E(mu_i)) /
  (pi (1 - E_avg)) has albedo 1 - E(mu_o) at F = 1; for a Fresnel F it is scaled by
  F_ms = F_avg^2 E_avg / (1 - F_avg (1 - E_avg)) (the energy of the bounces after the first,
  each weighted by F_avg, over that of f_ms), with E_avg = 2 int E(mu) mu dmu and
  F_avg = 2 int F(mu) mu dmu (= F0 + (F90 - F0)/21 for Schlick). Albedo:
      E_F(mu) + F_ms (1 - E(mu)),  E_F = F0 A + F90 B, E = A + B (directional_albedo.py).
* Heitz, Hanika, d'Eon & Dachsbacher 2016, "Multiple-Scattering Microfacet BSDFs with the
  Smith Model", section 5 (the random walk on a GGX microsurface with uniformly distributed
  heights, whose single-scattering term is the height-correlated Smith lobe of
  directional_albedo.py): rays from the view direction sample heights (its eq. 27: leave
  with probability G1(w, h) = C1(h)^Lambda(w)), visible normals (sampled with Dupuy &
  Benyoub 2023, "Sampling Visible GGX Normals with Spherical Caps", valid for any direction)
  and reflect with Schlick's F of the microfacet each bounce, until the ray leaves upwards.
  A Monte Carlo estimate: its standard error is returned beside it.
"""

from __future__ import annotations

import numpy as np

from pbrlab.maths.reference import directional_albedo

SCHLICK_F_AVG_WEIGHT = 1.0 / 21.0   # 2 int_0^1 (1 - mu)^5 mu dmu = 2 B(2, 6)
E_AVG_NODES = 64                    # Gauss-Legendre nodes in t = sqrt(mu) for E_avg


def schlick_f_avg(f0, f90=1.0):
    """2 int_0^1 F(mu) mu dmu for F = f0 + (f90 - f0)(1 - mu)^5."""
    f0 = np.asarray(f0, np.float64)
    return f0 + (f90 - f0) * SCHLICK_F_AVG_WEIGHT


def e_avg(alpha):
    """E_avg = 2 int_0^1 E(mu) mu dmu = 4 int_0^1 E(t^2) t^3 dt (t = sqrt(mu): smooth where E
    has its dip of width ~alpha near mu = 0)."""
    x, w = np.polynomial.legendre.leggauss(E_AVG_NODES)
    t = 0.5 * (x + 1.0)
    ab = directional_albedo.split_sum_terms_at_alpha(t * t, alpha)
    return float(np.sum(0.5 * w * 4.0 * (ab[:, 0] + ab[:, 1]) * t ** 3))


def kulla_conty_albedo(mu, alpha, f0, f90=1.0):
    """Directional albedo (RGB) with multiple scattering, Kulla & Conty 2017 (module doc)."""
    a, b = directional_albedo.split_sum_terms_at_alpha(np.asarray([mu], np.float64), alpha)[0]
    f0 = np.asarray(f0, np.float64)
    e, eavg, favg = a + b, e_avg(alpha), schlick_f_avg(f0, f90)
    f_ms = favg * favg * eavg / (1.0 - favg * (1.0 - eavg))
    return f0 * a + f90 * b + f_ms * (1.0 - e)


def single_scattering_albedo(mu, alpha, f0, f90=1.0):
    a, b = directional_albedo.split_sum_terms_at_alpha(np.asarray([mu], np.float64), alpha)[0]
    return np.asarray(f0, np.float64) * a + f90 * b


def _lambda(wz, wx, wy, alpha):
    """Smith's Lambda of GGX for directions over the whole sphere: Lambda(-w) = -1 - Lambda(w)."""
    sin2 = np.maximum(wx * wx + wy * wy, 1e-300)
    a2 = wz * wz / (alpha * alpha * sin2)  # 1 / (alpha tan theta)^2
    return 0.5 * (-1.0 + np.sign(wz) * np.sqrt(1.0 + 1.0 / np.maximum(a2, 1e-300)))


def _sample_vndf(wx, wy, wz, alpha, u1, u2):
    """Visible normal of GGX seen from w (any direction): Dupuy & Benyoub 2023, listing 3."""
    sx, sy, sz = alpha * wx, alpha * wy, wz
    n = np.sqrt(sx * sx + sy * sy + sz * sz)
    sx, sy, sz = sx / n, sy / n, sz / n
    phi = 2.0 * np.pi * u1
    z = (1.0 - u2) * (1.0 + sz) - sz
    st = np.sqrt(np.clip(1.0 - z * z, 0.0, 1.0))
    hx, hy, hz = st * np.cos(phi) + sx, st * np.sin(phi) + sy, z + sz
    mx, my, mz = alpha * hx, alpha * hy, hz
    n = np.sqrt(mx * mx + my * my + mz * mz)
    return mx / n, my / n, mz / n


def random_walk_albedo(mu, alpha, f0, f90=1.0, paths=1_000_000, max_order=100, seed=0):
    """(albedo RGB, standard error RGB): Heitz et al. 2016's random walk (module doc) from
    the view direction at n.v = mu, conductor microfacets with Schlick's F per bounce.
    Uniform heights: C1(h) = (h + 1)/2 on [-1, 1]."""
    rng = np.random.default_rng(seed)
    f0 = np.asarray(f0, np.float64)
    # the ray travels along -v: direction d = (-sin, 0, -mu); start above the surface
    dx = np.full(paths, -np.sqrt(1.0 - mu * mu)); dy = np.zeros(paths); dz = np.full(paths, -mu)
    h = np.full(paths, 1.0)      # C1 = 1: the top of the height distribution
    weight = np.ones((paths, 3))
    out = np.zeros((paths, 3))
    alive = np.ones(paths, bool)
    for _ in range(max_order):
        idx = np.flatnonzero(alive)
        if idx.size == 0:
            break
        x, y, z, hh = dx[idx], dy[idx], dz[idx], h[idx]
        c1 = np.clip(0.5 * (hh + 1.0), 1e-300, 1.0)
        u = rng.random(idx.size)
        lam = _lambda(z, x, y, alpha)
        up = z > 0
        # upward rays leave with probability G1 = C1(h)^Lambda(d) (Heitz 2016, eq. 27)
        leave = up & (u > 1.0 - c1 ** np.where(up, lam, 1.0))
        done = idx[leave]
        out[done] = weight[done]
        alive[done] = False
        stay = ~leave
        idx, x, y, z, c1, u, lam = idx[stay], x[stay], y[stay], z[stay], c1[stay], u[stay], lam[stay]
        # next height: C1(h') = C1(h) / (1 - U)^(1/Lambda) (Lambda < 0 downwards: h' < h)
        c1n = np.clip(c1 / (1.0 - u) ** (1.0 / lam), 0.0, 1.0)
        h[idx] = 2.0 * c1n - 1.0
        mx, my, mz = _sample_vndf(-x, -y, -z, alpha, rng.random(idx.size), rng.random(idx.size))
        cos_d = -(x * mx + y * my + z * mz)         # (-d).m >= 0 for a visible normal
        fresnel = f0 + (f90 - f0) * (1.0 - np.clip(cos_d, 0.0, 1.0))[:, None] ** 5
        weight[idx] *= fresnel
        dx[idx], dy[idx], dz[idx] = x + 2 * cos_d * mx, y + 2 * cos_d * my, z + 2 * cos_d * mz
    return out.mean(axis=0), out.std(axis=0) / np.sqrt(paths)
