"""Argument kinds of the library's public functions: each kind has a typical value, the edge
values the catalogue names (with why each is hard), and a randomised sampler that mixes its
normal domain with adversarial float32 values (0, ±0, denormals, tiny, 1 ± ulp, huge,
negative, and for colours NaN and ±Inf).

The domain of a kind is what a caller may pass (documented in glsl/README.md, "Hard cases"):
cosines and roughness any finite float (the library clamps them); reflectances [0, 1];
light radiance [0, 65504]; HDR colours into the tonemappers and the sRGB encode anything,
NaN and ±Inf included.
"""

from __future__ import annotations

import math

from dataclasses import dataclass

import numpy as np

F32 = np.float32
ULP_BELOW_ONE = float(np.nextafter(F32(1.0), F32(0.0)))   # 1 - 2^-24
ULP_ABOVE_ONE = float(np.nextafter(F32(1.0), F32(2.0)))   # 1 + 2^-23
DENORMAL = 1e-40                                          # float32 denormal (< 2^-126)
SMALLEST_DENORMAL = float(np.float32(1.4e-45))            # 2^-149
FLT_MAX = float(np.finfo(np.float32).max)


@dataclass(frozen=True)
class Edge:
    """A named edge value of a kind and the reason it is hard."""
    name: str
    value: float
    why: str


@dataclass(frozen=True)
class Kind:
    name: str
    typical: float
    edges: tuple[Edge, ...]          # catalogued (one case each per argument)
    adversarial: tuple[float, ...]   # extra values the sweep mixes in (with the edges)
    normal: object                   # rng, count -> float64 samples of the normal domain

    def pool(self) -> np.ndarray:
        return np.array([e.value for e in self.edges] + list(self.adversarial), np.float64)

    def sample(self, rng: np.random.Generator, count: int, adversarial_fraction: float = 0.3) -> np.ndarray:
        """float32-exact samples: the normal domain, with ``adversarial_fraction`` of them
        replaced by values of the adversarial pool."""
        out = np.asarray(self.normal(rng, count), np.float64)
        mask = rng.random(count) < adversarial_fraction
        pool = self.pool()
        out[mask] = pool[rng.integers(0, len(pool), int(mask.sum()))]
        return out.astype(np.float32)


_COSINE_EDGES = (
    Edge("0", 0.0, "exactly grazing: the cosine divides V and the classic Blinn-Phong, or makes 0/0"),
    Edge("denormal", DENORMAL, "a denormal flushes to 0 on many GPUs, so a divisor that is not 0 becomes 0"),
    Edge("tiny", 1e-7, "within float32 rounding of the horizon: 1/cosine is ~1e7 and products of two are ~1e14"),
    Edge("1", 1.0, "the peak: 1 - cos² cancels completely and D, F, G reach their extremes"),
    Edge("1 + ulp", ULP_ABOVE_ONE, "interpolated normals are not unit length: the dot product exceeds 1 and "
         "1 - x, sqrt(1 - x²) go negative"),
    Edge("1.01", 1.01, "a 1 % unnormalised normal (interpolated across a coarse mesh)"),
    Edge("-tiny", -1e-7, "back-facing by one rounding: negative where the maths wants >= 0"),
    Edge("negative", -0.5, "a back-facing or normal-mapped normal: the direction is below the surface"),
)

_ALPHA_EDGES = (
    Edge("0", 0.0, "a perfect mirror: D is a Dirac, D_GGX(1, 0) is 0/0 and Blinn-Phong's power 2/alpha² is 2/0"),
    Edge("denormal", DENORMAL, "alpha² underflows to 0 (and flushes on GPUs): the same 0/0 as alpha = 0"),
    Edge("tiny", 1e-10, "below float32 direction resolution: D's peak 1/(π alpha²) ~ 3e19 overflows when squared"),
    Edge("1", 1.0, "the roughest surface: alpha² - 1 = 0 makes D constant and Blinn-Phong's power 0 (pow(0, 0))"),
)

_ROUGHNESS_EDGES = (
    Edge("0", 0.0, "smoothness 1: alpha = 0, the Dirac mirror the shading model must clamp"),
    Edge("tiny", 1e-10, "alpha = r² = 1e-20 is a float32 denormal"),
    Edge("1", 1.0, "smoothness 0: the roughest lobe"),
    Edge("negative", -0.5, "a texture or slider outside [0, 1]: r² would wrongly turn it into a valid roughness"),
)


def _uniform(lo, hi):
    return lambda rng, n: rng.uniform(lo, hi, n)


def _log_uniform(lo, hi):
    return lambda rng, n: np.exp(rng.uniform(np.log(lo), np.log(hi), n))


KINDS: dict[str, Kind] = {k.name: k for k in (
    Kind("cosine", 0.5, _COSINE_EDGES,
         (-0.0, -DENORMAL, SMALLEST_DENORMAL, 1e-30, 1e-4, float(np.nextafter(F32(1e-4), F32(0))),
          ULP_BELOW_ONE, -1.0, 1e30, -1e30), _uniform(0.0, 1.0)),
    Kind("alpha", 0.25, _ALPHA_EDGES,
         (-0.0, SMALLEST_DENORMAL, 1e-30, 1e-7, float(np.nextafter(F32(1e-7), F32(0))), 0.045 ** 2, 0.089 ** 2,
          ULP_BELOW_ONE, ULP_ABOVE_ONE, 2.0, 1e30, -0.5), _log_uniform(1e-4, 1.0)),
    Kind("roughness", 0.5, _ROUGHNESS_EDGES,
         (-0.0, DENORMAL, 1e-30, 0.045, 0.089, float(np.nextafter(F32(0.045), F32(0))), ULP_BELOW_ONE,
          ULP_ABOVE_ONE, 2.0, 1e30, -1e30), _uniform(0.0, 1.0)),
    Kind("k", 0.125, (
        Edge("0", 0.0, "k = alpha/2 = 0 makes Schlick's G1 = NdotX/NdotX, 0/0 at grazing"),
        Edge("tiny", 1e-10, "G1 jumps from 0 to 1 within 1e-10 of the horizon"),
        Edge("1", 1.0, "the largest k: G1 = NdotX"),
    ), (-0.0, DENORMAL, 1e-30, ULP_ABOVE_ONE, 2.0, 1e30, -0.5), _log_uniform(1e-4, 0.5)),
    Kind("specPower", 64.0, (
        Edge("0", 0.0, "pow(NdotH, 0) is pow(0, 0) at NdotH = 0: undefined in GLSL"),
        Edge("8192", 8192.0, "gloss 1 (Call of Duty's maximum): pow near 1 loses ln2·s·2^-21 and NdotH^s "
             "underflows a few degrees off the peak"),
        Edge("4.9e5", 4.9e5, "the power pbr_specPower_from_alpha gives at the minimum roughness"),
        Edge("huge", 1e30, "(s + 8)/(8π) and s·log2(NdotH) must not overflow"),
    ), (SMALLEST_DENORMAL, 1e-30, 0.5, 1.0, float(np.nextafter(F32(8192), F32(0))), 2e14, 3e38, -1.0),
        _log_uniform(1.0, 8192.0)),
    Kind("unit", 0.5, (
        Edge("0", 0.0, "F0, albedo or metallic 0: no reflection, exact zeros downstream"),
        Edge("1", 1.0, "F0, albedo or metallic 1: a perfect reflector (metal F0 = 1)"),
    ), (-0.0, SMALLEST_DENORMAL, DENORMAL, 1e-30, ULP_BELOW_ONE), _uniform(0.0, 1.0)),
    Kind("eta", 1.5, (
        Edge("1", 1.0, "no interface: F = 0, but at grazing the formula is 0/0"),
        Edge("1 + ulp", ULP_ABOVE_ONE, "eta² - 1 cancels to one rounding"),
        Edge("inside glass", 1.0 / 1.5, "total internal reflection beyond the critical angle, infinite slope at it"),
    ), (ULP_BELOW_ONE, 1.0 / 16.0, 16.0, 1.5), _log_uniform(1.0 / 3.0, 3.0)),
    Kind("thickness", 400.0, (
        Edge("0", 0.0, "no film: the thin-film model is undefined at zero thickness (decided: the base Fresnel)"),
        Edge("fade", 0.03, "the end of the film-IOR fade (smoothstep over 0..0.03 nm): the film appears"),
        Edge("denormal", DENORMAL, "a denormal thickness flushes to 0 on many GPUs: the no-film branch or not"),
        Edge("1200", 1200.0, "a thick film: phase arguments of ~1e2 rad lose float32 precision in cos"),
        Edge("huge", 1e30, "phase² would overflow float32: the optical path must be capped"),
        Edge("negative", -100.0, "a texture or slider below 0: no physical film"),
    ), (-0.0, 1e-30, 1.0, 1e5, 1e10, -1e30), _uniform(0.0, 1200.0)),
    Kind("distance", 1.0, (
        Edge("0", 0.0, "no path through the volume: nothing absorbed, even by a black attenuation colour"),
        Edge("denormal", DENORMAL, "a denormal path flushes to 0 on many GPUs: d / D may be 0 or not"),
        Edge("huge", 1e30, "d / D overflows float32 for small D: the exponent must saturate to 0, never NaN"),
    ), (-0.0, -1.0, 1e-30, 3e38), _log_uniform(1e-3, 1e3)),
    Kind("phase", 0.0, (
        Edge("0", 0.0, "no phase shift: S at its largest, |S| up to 1.2 per channel"),
        Edge("pi", float(np.float32(np.pi)), "a half-wave shift: S changes sign"),
        Edge("4 pi", float(np.float32(4 * np.pi)), "the largest shift the film uses (m = 2, φ = 2π)"),
    ), (-1.0, 100.0, 1e4), _uniform(0.0, 4 * np.pi)),
    Kind("hdr", 0.5, (
        Edge("0", 0.0, "black: the toe of every curve; Hable and ACES fits go slightly negative"),
        Edge("1e-30", 1e-30, "far below display precision; products underflow to denormals"),
        Edge("65504", 65504.0, "the largest half: an HDR sun in an RGBA16F buffer"),
        Edge("1e30", 1e30, "beyond half: x² overflows float32 in Hable and ACES"),
        Edge("+Inf", np.inf, "an overflowed light or a division by zero upstream: Inf/Inf is NaN"),
        Edge("-Inf", -np.inf, "an overflowed negative lobe (e.g. a ringing filter)"),
        Edge("NaN", np.nan, "a NaN from upstream: spreads through bloom and temporal filters as a sparkle"),
        Edge("negative", -1.0, "negative colour from a ringing filter or a wide-gamut conversion"),
    ), (-0.0, SMALLEST_DENORMAL, DENORMAL, 1.0, 11.2, 65520.0, 1e5, FLT_MAX, -1e30), _log_uniform(1e-4, 1e4)),
    Kind("radiance", 1.0, (
        Edge("0", 0.0, "a light switched off"),
        Edge("1e-30", 1e-30, "a light attenuated to nothing: products underflow"),
        Edge("65504", 65504.0, "an HDR sun at the largest half value"),
    ), (SMALLEST_DENORMAL, 1e4), _log_uniform(1e-3, 1e2)),
    Kind("ev", 0.0, (
        Edge("0", 0.0, "no exposure: must be the identity"),
        Edge("+64", 64.0, "2^64 scales 65504 to 1.2e24, still finite"),
        Edge("-64", -64.0, "2^-64 scales to denormals"),
    ), (0.5, -0.5), _uniform(-16.0, 16.0)),
    Kind("whitePoint", 4.0, (
        Edge("small", 1e-3, "white point below the input: color / white² is huge"),
        Edge("W", 11.2, "Hable's white point"),
        Edge("65504", 65504.0, "white at the half maximum: the curve is Reinhard eq. 3"),
    ), (0.5, 1.0), _log_uniform(0.5, 100.0)),
    Kind("coordinate", 0.5, (
        Edge("0", 0.0, "the zero vector has no direction: normalize() divides by 0"),
        Edge("denormal", DENORMAL, "dot(v, v) underflows to 0 (and denormals flush): normalize() gives Inf or NaN"),
        Edge("huge", 1e30, "dot(v, v) overflows to Inf: normalize() gives 0 (a camera 1e30 away)"),
        Edge("negative", -1.0, "a direction with negative components"),
    ), (-0.0, -DENORMAL, 1e-30, 1e19, -1e30, FLT_MAX / 2, 2.0), _uniform(-2.0, 2.0)),
    Kind("signed", 0.5, (
        Edge("0", 0.0, "zero: the lower clamp boundary"),
        Edge("negative", -1.0, "below the clamp range"),
        Edge("huge", 1e19, "x² approaches float32's maximum (3.4e38)"),
    ), (-0.0, DENORMAL, -DENORMAL, 2.0, -1e19), _uniform(-2.0, 2.0)),
    # a distant source's angular radius, radians (the sun: 4.65e-3; Blender's sunrise disc: 9.8e-3)
    Kind("angle", 9.8e-3, (
        Edge("0", 0.0, "a point source: the lobe must be left exactly as it is"),
        Edge("negative", -9.8e-3, "a sign error upstream: the width enters squared, so its sign must not matter"),
        Edge("pi", math.pi, "a source as wide as the sky: the widened alpha must stay at most 1"),
        Edge("huge", 1e19, "r² approaches float32's maximum: the widened alpha must still be finite"),
    ), (-0.0, DENORMAL, 1e-30, 1e30, -1e30), _log_uniform(1e-4, 0.1)),
)}


def unit_vectors(rng: np.random.Generator, count: int) -> np.ndarray:
    v = rng.normal(size=(count, 3))
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def shading_geometry(rng: np.random.Generator, count: int) -> dict[str, np.ndarray]:
    """n, v, l for the shading model: random unit vectors (v and l mostly above the surface),
    with 75 % of them replaced, one twelfth each, by the catalogue's hard configurations:
    v = -l, v ≈ -l, mirror (NdotH = 1), l = v, |n| = 1.01, |n| = 1 + ulp, l = 0 (a light at
    the point), v = 0, an exact axis normal, NdotL = 0 exactly (float32)."""
    n, v, l = unit_vectors(rng, count), unit_vectors(rng, count), unit_vectors(rng, count)
    for d in (v, l):
        flip = (np.einsum("ij,ij->i", d, n) < 0) & (rng.random(count) < 0.8)
        d[flip] *= -1.0
    which = rng.integers(0, 12, count)
    s = which == 0; v[s] = -l[s]                                                  # V = -L
    s = which == 1; v[s] = -l[s] + rng.normal(0.0, 1e-6, (int(s.sum()), 3))       # V ≈ -L
    s = which == 2                                                                # mirror: NdotH = 1
    v[s] = 2.0 * np.einsum("ij,ij->i", l[s], n[s])[:, None] * n[s] - l[s]
    s = which == 3; v[s] = l[s]                                                   # retro-reflection
    s = which == 4; n[s] *= 1.01                                                  # unnormalised normal
    s = which == 5; n[s] *= ULP_ABOVE_ONE                                         # |n| = 1 + ulp
    s = which == 6; l[s] = 0.0                                                    # light at the point
    s = which == 7; v[s] = 0.0                                                    # camera at the point
    s = (which == 8) | (which == 9); n[s] = (0.0, 0.0, 1.0)                       # exact axis normal
    s = which == 9; l[s, 2] = 0.0                                                 # NdotL = 0 exactly
    l[s] /= np.maximum(np.linalg.norm(l[s], axis=-1, keepdims=True), 1e-30)
    return {"n": n.astype(np.float32), "v": v.astype(np.float32), "l": l.astype(np.float32)}


def transmission_geometry(rng: np.random.Generator, count: int) -> dict[str, np.ndarray]:
    """n, v, l for light through a surface: shading_geometry's with l mirrored through the
    surface's plane (lights mostly below it, its hard configurations kept in mirror image),
    and a third of them replaced, half each, by the straight line l = -v (an index-matched
    interface's Dirac) and l within 1e-6 of it."""
    g = shading_geometry(rng, count)
    n, v, l = (g[k].astype(np.float64) for k in "nvl")
    unit_n = n / np.maximum(np.linalg.norm(n, axis=-1, keepdims=True), 1e-30)
    l = l - 2.0 * np.einsum("ij,ij->i", l, unit_n)[:, None] * unit_n
    which = rng.integers(0, 6, count)
    s = which == 0; l[s] = -v[s]                                                  # straight through
    s = which == 1; l[s] = -v[s] + rng.normal(0.0, 1e-6, (int(s.sum()), 3))       # nearly so
    return {"n": n.astype(np.float32), "v": v.astype(np.float32), "l": l.astype(np.float32)}
