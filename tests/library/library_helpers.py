"""Shared grids, tolerances, comparison and quadrature helpers for tests/library.

Imported by the test modules as ``library_helpers`` (a plain module: a conftest.py cannot be
imported by name here, tests/conftest.py already owns that module name). conftest.py adds
the fixtures and prints the measured-error table recorded by ``assert_close``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from pbrlab import evaluate, vec3  # noqa: F401  (re-exported for the tests)
from pbrlab.maths.reference import remap, shading

# float32 unit roundoff: the relative error of one correctly rounded float32 operation.
F32_EPS = 2.0 ** -24
# Default relative tolerance for well-conditioned terms: a handful of float32 operations
# (each <= 1 ulp on llvmpipe/GPUs, the GLSL spec allows ~3 ulp for division and more for
# pow/exp) accumulate to a few 1e-7; 1e-5 leaves ~100x headroom yet catches any formula
# change (a wrong constant or exponent is >= 1e-3 off).
RTOL_WELL_CONDITIONED = 1e-5

# The smallest alpha the shading model uses (PBR_MIN_PERCEPTUAL_ROUGHNESS²).
MIN_ALPHA = shading.MIN_PERCEPTUAL_ROUGHNESS ** 2


@dataclass
class Measured:
    max_abs: float
    max_rel: float
    where: str


MEASURED: dict[str, Measured] = {}


def cosines(n: int = 2049) -> np.ndarray:
    """Cosines in [0, 1]: uniform, plus points crowded at both ends (float32-exact)."""
    uniform = np.linspace(0.0, 1.0, n)
    near_one = 1.0 - np.geomspace(1e-7, 1e-1, 64)
    near_zero = np.geomspace(1e-7, 1e-1, 64)
    return np.unique(np.concatenate([uniform, near_one, near_zero]).astype(np.float32)).astype(np.float64)


def v_cosines(n: int = 257) -> np.ndarray:
    """Cosines where the V terms are unguarded, [PBR_MIN_NDOTV, 1]: every V clamps NdotL
    and NdotV below 1e-4 (guards.glsl; the guard itself is tested in tests/checking/hardcases)."""
    c = cosines(n)
    return c[c >= shading.MIN_NDOTV]


def alphas(n: int = 33) -> np.ndarray:
    """alpha from the shading model's minimum to 1, log-spaced (float32-exact)."""
    return np.geomspace(MIN_ALPHA, 1.0, n).astype(np.float32).astype(np.float64)


def perceptual_roughnesses(n: int = 17) -> np.ndarray:
    return np.linspace(0.0, 1.0, n).astype(np.float32).astype(np.float64)


def grid(*axes):
    """Open-mesh broadcastable grids (like np.ix_, float32-exact float64)."""
    return [np.asarray(a, np.float32).astype(np.float64) for a in np.ix_(*axes)]


def as_f32(x) -> np.ndarray:
    """The float64 value of x rounded to float32: what the GPU actually receives."""
    return np.asarray(x, dtype=np.float32).astype(np.float64)


def seeded_rng(purpose: str) -> np.random.Generator:
    """A generator seeded from ``purpose`` alone, so each test's samples do not depend on
    which other tests ran first."""
    return np.random.default_rng(sum(ord(c) * 131 ** i for i, c in enumerate(purpose)) % 2 ** 63)


def unit_vectors(rng: np.random.Generator, count: int, min_z: float | None = None) -> np.ndarray:
    """Uniform random unit vectors (float32-representable, renormalised in float64),
    optionally restricted to z >= min_z (z is the normal axis in these tests)."""
    out = np.empty((0, 3))
    while len(out) < count:
        v = rng.normal(size=(count * 3, 3))
        v /= np.linalg.norm(v, axis=-1, keepdims=True)
        if min_z is not None:
            v = v[v[:, 2] >= min_z]
        out = np.concatenate([out, v])
    return as_f32(out[:count])


def assert_close(label: str, gpu, ref, *, rtol: float, atol: float = 0.0, where=None):
    """|gpu - ref| <= atol + rtol |ref| elementwise; finite where ref is finite; records
    the worst errors under ``label``. ``where`` (bool mask) restricts the comparison."""
    gpu = np.asarray(gpu, dtype=np.float64)
    ref = np.asarray(ref, dtype=np.float64)
    gpu, ref, rtol_arr, atol_arr = np.broadcast_arrays(gpu, ref, np.asarray(rtol, np.float64),
                                                       np.asarray(atol, np.float64))
    if where is not None:
        mask = np.asarray(where)
        mask = np.broadcast_to(mask.reshape(mask.shape + (1,) * (ref.ndim - mask.ndim)), ref.shape)
    else:
        mask = np.ones(ref.shape, bool)
    gpu, ref, rtol_arr, atol_arr = gpu[mask], ref[mask], rtol_arr[mask], atol_arr[mask]
    finite = np.isfinite(ref)
    assert np.isfinite(gpu[finite]).all(), f"{label}: GPU value not finite where the reference is"
    gpu, ref, rtol_arr, atol_arr = gpu[finite], ref[finite], rtol_arr[finite], atol_arr[finite]
    err = np.abs(gpu - ref)
    bound = atol_arr + rtol_arr * np.abs(ref)
    # relative error reported where |ref| is above the absolute floor (else it is noise)
    significant = np.abs(ref) > np.maximum(atol_arr, np.finfo(np.float64).tiny)
    rel = np.where(significant, err / np.where(significant, np.abs(ref), 1.0), 0.0)
    tolerance_text = (f"rtol={_describe(rtol)} atol={_describe(atol)}")
    record(label, float(err.max(initial=0.0)), float(rel.max(initial=0.0)), tolerance_text)
    if not (err <= bound).all():
        worst = int(np.argmax(err - bound))
        raise AssertionError(
            f"{label}: {int((err > bound).sum())} of {err.size} values off by more than "
            f"atol + rtol·|ref| ({tolerance_text}); worst: gpu {gpu[worst]!r} vs ref {ref[worst]!r} "
            f"(abs err {err[worst]:.3g}, allowed {bound[worst]:.3g})")


def _describe(tol) -> str:
    tol = np.asarray(tol, np.float64)
    return f"{float(tol):g}" if tol.ndim == 0 else f"per-element {tol.min():.2g}..{tol.max():.2g}"


def record(label: str, max_abs: float, max_rel: float, where: str = ""):
    old = MEASURED.get(label)
    if old is None or max_abs > old.max_abs or max_rel > old.max_rel:
        MEASURED[label] = Measured(max(max_abs, old.max_abs if old else 0.0),
                                   max(max_rel, old.max_rel if old else 0.0), where)


# ---- hemisphere quadrature ----------------------------------------------------------

def theta_quadrature(width: float, panels: int = 48, order: int = 16):
    """Gauss-Legendre nodes/weights on θ in [0, π/2], with panel breakpoints spaced
    geometrically from width·1e-3 so a lobe of angular width ``width`` around θ = 0 is
    resolved whatever its size."""
    x, w = np.polynomial.legendre.leggauss(order)
    breaks = np.concatenate([[0.0], np.geomspace(max(width, 1e-6) * 1e-3, math.pi / 2, panels)])
    a, b = breaks[:-1, None], breaks[1:, None]
    nodes = (0.5 * (b - a) * x + 0.5 * (b + a)).ravel()
    weights = (0.5 * (b - a) * w).ravel()
    return nodes, weights


def phi_quadrature(count: int = 96):
    """Trapezoid nodes on φ in [0, 2π): spectrally accurate for smooth periodic integrands."""
    return np.arange(count) * (2.0 * math.pi / count), np.full(count, 2.0 * math.pi / count)


__all__ = ["F32_EPS", "RTOL_WELL_CONDITIONED", "MIN_ALPHA", "assert_close", "record", "cosines",
           "alphas", "v_cosines", "perceptual_roughnesses", "grid", "as_f32", "unit_vectors", "evaluate", "vec3",
           "theta_quadrature", "phi_quadrature", "remap"]
