"""Half precision (binary16, GLSL mediump) study of the library's formulations.

Each formulation is written once, as a function of an arithmetic namespace ``m``, and run
three ways:

  Float64     float64 numpy: the exact value of the formulation (the reference);
  NumpyHalf   numpy float16, rounding after every operation (numpy computes +, -, *, /,
              sqrt of float16 operands in float32 and rounds once: correctly rounded);
  GlslHalf    builds a GLSL expression whose every intermediate passes through
              H(x) = unpackHalf2x16(packHalf2x16(vec2(x, 0))).x on the GPU, the in-shader
              emulation of a real half ALU (desktop llvmpipe ignores mediump).

The two half models agree bit for bit wherever only +, -, *, / and sqrt are involved
(tests/checking/hardcases/test_half.py); pow/exp2/log2 agree within 1 half ulp.
"""

from __future__ import annotations

import math

import numpy as np

from ...gpu import evaluator

# The H(p) macro (its parameter is not called x: it would replace the .x swizzle), and
# packHalf2x16/unpackHalf2x16, core only from GLSL 4.20: the evaluator's program is
# #version 330, so it requires the packing extension.
HALF_ROUND = {"H(p)": "unpackHalf2x16(packHalf2x16(vec2((p), 0.0))).x"}
HALF_EXTENSIONS = ("GL_ARB_shading_language_packing",)
HALF_MAX = 65504.0
HALF_MIN_NORMAL = 2.0 ** -14


class Float64:
    """float64 numpy arithmetic (the formulation's exact value)."""
    dtype = np.float64

    def c(self, x):
        return np.float64(x)

    def var(self, x):
        return np.asarray(x, np.float64)

    sqrt = staticmethod(np.sqrt)
    exp2 = staticmethod(np.exp2)
    minimum = staticmethod(np.minimum)
    maximum = staticmethod(np.maximum)

    def pow(self, x, y):
        with np.errstate(all="ignore"):
            return np.power(x, y)

    def where(self, cond, a, b):
        return np.where(cond, a, b)


class NumpyHalf(Float64):
    """numpy float16: every operation rounds to half (constants and inputs too)."""
    dtype = np.float16

    def c(self, x):
        return np.float16(x)

    def var(self, x):
        return np.asarray(x, np.float16)

    def sqrt(self, x):
        return np.sqrt(x).astype(np.float16)

    def exp2(self, x):
        return np.exp2(x.astype(np.float32)).astype(np.float16)

    def pow(self, x, y):
        with np.errstate(all="ignore"):
            return np.power(np.float32(x), np.float32(y)).astype(np.float16)


class G:
    """A GLSL expression whose value is already rounded to half."""

    def __init__(self, text):
        self.text = text

    def _op(self, other, op, swap=False):
        a, b = (_g(other), self) if swap else (self, _g(other))
        return G(f"H({a.text} {op} {b.text})")

    def __add__(self, o): return self._op(o, "+")
    def __radd__(self, o): return self._op(o, "+", True)
    def __sub__(self, o): return self._op(o, "-")
    def __rsub__(self, o): return self._op(o, "-", True)
    def __mul__(self, o): return self._op(o, "*")
    def __rmul__(self, o): return self._op(o, "*", True)
    def __truediv__(self, o): return self._op(o, "/")
    def __rtruediv__(self, o): return self._op(o, "/", True)
    def __neg__(self): return G(f"(-{self.text})")
    def __lt__(self, o): return G(f"({self.text} < {_g(o).text})")
    def __gt__(self, o): return G(f"({self.text} > {_g(o).text})")
    def __ge__(self, o): return G(f"({self.text} >= {_g(o).text})")
    def __le__(self, o): return G(f"({self.text} <= {_g(o).text})")


def _g(x):
    return x if isinstance(x, G) else G(f"H({float(np.float16(x))!r})")


class GlslHalf:
    """Builds the half-emulating GLSL expression (variables are evaluator inputs)."""

    def c(self, x):
        return _g(x)

    def var(self, name):
        return G(name)

    def sqrt(self, x): return G(f"H(sqrt({x.text}))")
    def exp2(self, x): return G(f"H(exp2({x.text}))")
    def pow(self, x, y): return G(f"H(pow({_g(x).text}, {_g(y).text}))")
    def minimum(self, a, b): return G(f"H(min({_g(a).text}, {_g(b).text}))")
    def maximum(self, a, b): return G(f"H(max({_g(a).text}, {_g(b).text}))")
    def where(self, cond, a, b): return G(f"(({cond.text}) ? {_g(a).text} : {_g(b).text})")


# ---- formulations -----------------------------------------------------------------------

def _dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def _clamp(m, x, lo, hi):
    return m.minimum(m.maximum(x, m.c(lo)), m.c(hi))


def d_ggx_textbook(m, n, h, alpha):
    """The lecture's form: alpha² / (π ((n·h)² (alpha² - 1) + 1)²)."""
    c = _dot(n, h)
    a2 = alpha * alpha
    d = c * c * (a2 - m.c(1.0)) + m.c(1.0)
    return a2 / (m.c(math.pi) * d * d)


def d_ggx_factored(m, n, h, alpha):
    """pbr_D_GGX(NdotH, alpha): 1 - NdotH² as (1 - NdotH)(1 + NdotH) of the rounded cosine."""
    c = _clamp(m, _dot(n, h), 0.0, 1.0)
    k = alpha / m.maximum((m.c(1.0) - c) * (m.c(1.0) + c) + (c * alpha) * (c * alpha), alpha * alpha)
    return k * k * m.c(1.0 / math.pi)


def d_ggx_cross(m, n, h, alpha):
    """pbr_D_GGX(n, h, alpha): 1 - NdotH² = |n x h|² (Filament's mediump form)."""
    c = _clamp(m, _dot(n, h), 0.0, 1.0)
    x = (n[1] * h[2] - n[2] * h[1], n[2] * h[0] - n[0] * h[2], n[0] * h[1] - n[1] * h[0])
    s2 = _dot(x, x)
    k = alpha / m.maximum(s2 + (c * alpha) * (c * alpha), alpha * alpha)
    return k * k * m.c(1.0 / math.pi)


def blinn_phong_pow(m, n, h, s):
    """pbr_D_BlinnPhong's lobe: (s + 2)/(2π) · pow(n·h, s)."""
    c = _clamp(m, _dot(n, h), 0.0, 1.0)
    return (s + m.c(2.0)) * m.c(0.5 / math.pi) * m.pow(c, s)


def blinn_phong_cross(m, n, h, s):
    """The same lobe from |n x h|²: (n·h)^s = (1 - s2)^(s/2) = exp2((s/2) log2(1 - s2)),
    with log2(1 - s2) ≈ -(s2 + s2²/2)/ln 2 (relative error < s2²/3, below half precision
    for s2 < 0.03, i.e. wherever a power >= 256 is above 1e-4 of its peak)."""
    x = (n[1] * h[2] - n[2] * h[1], n[2] * h[0] - n[0] * h[2], n[0] * h[1] - n[1] * h[0])
    s2 = _dot(x, x)
    return (s + m.c(2.0)) * m.c(0.5 / math.pi) * m.exp2(-(s * m.c(0.5 / math.log(2.0))) * (s2 + s2 * s2 * m.c(0.5)))


def tonemap_reinhard(m, x):
    x = _clamp(m, x, 0.0, HALF_MAX)
    return x / (m.c(1.0) + x)


def tonemap_hable(m, x):
    """pbr_tonemap_hable on one channel: input capped at W = 11.2 (hable.glsl)."""
    A, B, C, D, E, F, W = 0.15, 0.50, 0.10, 0.20, 0.02, 0.30, 11.2
    def curve(v):
        return ((v * (m.c(A) * v + m.c(C * B)) + m.c(D * E)) / (v * (m.c(A) * v + m.c(B)) + m.c(D * F))
                - m.c(E / F))
    return _clamp(m, curve(_clamp(m, x, 0.0, W)) / curve(m.c(W)), 0.0, 1.0)


def tonemap_narkowicz(m, x, cap=16.0):
    """pbr_tonemap_aces_narkowicz on one channel: input capped at PBR_ACES_NARKOWICZ_MAX_INPUT
    (16; cap=HALF_MAX is the uncapped curve, which overflows half above x ~ 160)."""
    x = _clamp(m, x, 0.0, cap)
    return _clamp(m, x * (m.c(2.51) * x + m.c(0.03)) / (x * (m.c(2.43) * x + m.c(0.59)) + m.c(0.14)), 0.0, 1.0)


# The LOW tier's guards (dispatch.glsl / guards.glsl), as the half model sees them.
LOW_MIN_PERCEPTUAL_ROUGHNESS = 0.089
MIN_NDOTV = 1e-4
LOW_MIN_HALF_VECTOR_LENGTH_SQUARED = HALF_MIN_NORMAL


def brdf_low(m, n, v, l, diffuse, specular, roughness, min_roughness=LOW_MIN_PERCEPTUAL_ROUGHNESS,
             d_form=None, lobe_cap=HALF_MAX, min_half=LOW_MIN_HALF_VECTOR_LENGTH_SQUARED):
    """One colour channel of pbr_brdf_standard at the LOW tier where floats may be 16-bit
    (GGX times Hammon's fast V, fused in half's range from h = l + v unnormalised:
    pbr_DV_GGX_SmithCorrelatedFast_half; Schlick F with F90 from F0; Lambert), line for line
    with standard.glsl. ``d_form`` (n, h, alpha) replaces the fused D by D of a normalised h
    (the study's other forms)."""
    NdotL = _dot(n, l)
    NdotV = _clamp(m, _dot(n, v), MIN_NDOTV, 1.0)
    r = _clamp(m, roughness, min_roughness, 1.0)
    alpha = r * r
    hs = (l[0] + v[0], l[1] + v[1], l[2] + v[2])
    hl2 = _dot(hs, hs)
    LdotH = m.c(0.5) * m.sqrt(hl2)
    diffuse_part = diffuse * m.c(1.0 / math.pi)
    lambdas = m.c(2.0) * NdotL * NdotV * (m.c(1.0) - alpha) + (NdotL + NdotV) * alpha  # mix(...)
    if d_form is None:
        c = _dot(n, hs)
        cross = (n[1] * hs[2] - n[2] * hs[1], n[2] * hs[0] - n[0] * hs[2], n[0] * hs[1] - n[1] * hs[0])
        inv_h2 = m.c(1.0) / m.minimum(hl2, m.c(4.0))
        dn = _dot(cross, cross) * inv_h2 + (c * c * inv_h2) * (alpha * alpha)
        k = alpha / dn
        DV = k * k * (m.c(0.5 / math.pi) / m.maximum(lambdas, m.c(HALF_MIN_NORMAL)))
    else:
        inv = m.c(1.0) / m.sqrt(m.maximum(hl2, m.c(min_half)))
        DV = d_form(m, n, (hs[0] * inv, hs[1] * inv, hs[2] * inv), alpha) * (m.c(0.5) / lambdas)
    w = m.c(1.0) - _clamp(m, LdotH, 0.0, 1.0)
    w2 = w * w
    f90 = m.minimum(specular * m.c(3.0 * 16.5), m.c(1.0))  # pbr_f90_from_f0 of a grey f0
    F = specular + (f90 - specular) * (w2 * w2 * w)
    lobe = (DV if lobe_cap is None else m.minimum(DV, m.c(lobe_cap))) * F
    with_lobe = m.where(_dot(n, hs) > m.c(0.0), diffuse_part + lobe, diffuse_part)  # χ+(n·h)
    # The study forms l + v in half, where a short l + v has no direction left (half's
    # rounding of a component of 1 is 2^-11), so it keeps a threshold on |l + v|² (min_half,
    # 2^-14 by default). The library forms l + v in float32 and tests n·(l + v) instead
    # (PBR_MIN_NDOT_HALF_SUM); min_half = 0 is its selection (the two differ only where
    # 0 < n·(l + v) < 2^-50).
    lit = m.where(hl2 >= m.c(min_half), with_lobe, diffuse_part)
    return m.where(NdotL > m.c(0.0), lit, m.c(0.0))


# ---- running a formulation three ways ---------------------------------------------------

def run_three_ways(formulation, inputs: dict[str, np.ndarray], evaluate=evaluator.evaluate, **fixed):
    """(float64 value, numpy half value, GLSL half-emulation value) of ``formulation`` for the
    inputs (float arrays, rounded to half first; names ending in a digit 0-2 are vector
    components: n0 n1 n2 -> n). ``fixed`` are Python constants (rounded to half)."""
    with np.errstate(over="ignore"):  # values above 65504 become +Inf in half: intended
        half_inputs = {k: np.asarray(v, np.float16) for k, v in inputs.items()}

    def args(m, get):
        out = {}
        for name in sorted(half_inputs):
            base, comp = (name[:-1], name[-1]) if name[-1] in "012" else (name, None)
            if comp is None:
                out[base] = get(m, name)
            else:
                out.setdefault(base, [None] * 3)[int(comp)] = get(m, name)
        return out | {k: m.c(v) for k, v in fixed.items()}

    with np.errstate(all="ignore"):
        exact = formulation(Float64(), **args(Float64(), lambda m, k: m.var(half_inputs[k].astype(np.float64))))
        half = formulation(NumpyHalf(), **args(NumpyHalf(), lambda m, k: m.var(half_inputs[k])))
    expression = formulation(GlslHalf(), **args(GlslHalf(), lambda m, k: m.var(k))).text
    gpu = evaluate(expression, ("pbr/common/math.glsl",), defines=HALF_ROUND, extensions=HALF_EXTENSIONS,
                   **{k: v.astype(np.float32) for k, v in half_inputs.items()})
    return np.asarray(exact, np.float64), np.asarray(half, np.float64), np.asarray(gpu, np.float64)


def relative_error(value, exact, floor):
    """max |value - exact| / |exact| where |exact| > floor (non-finite values count as inf)."""
    keep = np.abs(exact) > floor
    with np.errstate(all="ignore"):
        err = np.abs(value[keep] - exact[keep]) / np.abs(exact[keep])
    err = np.where(np.isfinite(err), err, np.inf)
    return float(err.max(initial=0.0))


# ---- the study's configurations -----------------------------------------------------------

def near_peak_geometry(rng, count, max_one_minus_cos):
    """Random unit normals n and half vectors h with 1 - n·h uniform in [0, max_one_minus_cos]."""
    n = rng.normal(size=(count, 3)); n /= np.linalg.norm(n, axis=-1, keepdims=True)
    t = rng.normal(size=(count, 3)); t -= np.sum(t * n, -1, keepdims=True) * n
    t /= np.linalg.norm(t, axis=-1, keepdims=True)
    theta = np.arccos(1.0 - rng.uniform(0.0, max_one_minus_cos, count))
    h = n * np.cos(theta)[:, None] + t * np.sin(theta)[:, None]
    return {**{f"n{i}": n[:, i] for i in range(3)}, **{f"h{i}": h[:, i] for i in range(3)}}


def shading_configurations(rng, count):
    """Random shading configurations (unit n, v, l above the surface, mirror directions for a
    third of them, roughness over [0, 1]) for the LOW-tier BRDF."""
    from .domains import unit_vectors
    n, v, l = unit_vectors(rng, count), unit_vectors(rng, count), unit_vectors(rng, count)
    for d in (v, l):
        d[np.sum(d * n, -1) < 0] *= -1.0
    mirror = rng.random(count) < 1 / 3
    v[mirror] = 2.0 * np.sum(l[mirror] * n[mirror], -1, keepdims=True) * n[mirror] - l[mirror]
    out = {f"{name}{i}": d[:, i] for name, d in (("n", n), ("v", v), ("l", l)) for i in range(3)}
    return out | {"diffuse": rng.uniform(0, 1, count), "specular": rng.uniform(0, 1, count),
                  "roughness": rng.uniform(0, 1, count)}
