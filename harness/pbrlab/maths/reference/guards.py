"""The library's numeric guards (glsl/pbr/common/guards.glsl and the tier block of
glsl/pbr/shading/dispatch.glsl): constants shared with the GLSL (tested equal) and the float64
twins of the guard helpers, used where a reference models a guarded shader (shading.py, the
transfer and tonemap dispatchers). The raw term references (brdf.py, ...) stay exact."""

import numpy as np

FLT_MIN = 2.0 ** -126                   # PBR_FLT_MIN: smallest normal float32
SAFE_NORMALIZE_HUGE = 2.0 ** 125        # PBR_SAFE_NORMALIZE_HUGE: pre-scale the divisor above it
HALF_MAX = 65504.0                      # PBR_HALF_MAX: largest finite binary16
MIN_ALPHA = 1e-7                        # PBR_MIN_ALPHA: raw D/G/V alpha floor
MIN_NDOTV = 1e-4                        # PBR_MIN_NDOTV (Filament MIN_N_DOT_V): V cosine floor
MIN_HALF_VECTOR_LENGTH_SQUARED = 1e-10  # PBR_MIN_HALF_VECTOR_LENGTH_SQUARED: l = -v threshold
MIN_NDOT_HALF_SUM = 2.0 ** -50          # PBR_MIN_NDOT_HALF_SUM: n.(l + v) with a specular lobe
MIN_VDOTH = 5e-6                        # PBR_MIN_VDOTH = sqrt(1e-10) / 2
BECKMANN_MIN_NDOTH = 0.1                # PBR_BECKMANN_MIN_NDOTH (d_beckmann.glsl)
MAX_IOR = 2.0 ** 25                     # PBR_MAX_IOR (material/ior.glsl)


def sanitize(x, hi):
    """pbr_sanitize: NaN and negatives -> 0, +Inf and values above hi -> hi."""
    x = np.asarray(x, dtype=np.float64)
    with np.errstate(invalid="ignore"):
        return np.minimum(np.where(x > 0.0, x, 0.0), hi)


def one_minus_dot2(a, b):
    """pbr_one_minus_dot2: |a x b|^2 where a.b > 0, else 1 (last axis holds the vector)."""
    a, b = np.asarray(a, dtype=np.float64), np.asarray(b, dtype=np.float64)
    c = np.cross(a, b)
    return np.where(np.sum(a * b, axis=-1) > 0.0, np.sum(c * c, axis=-1), 1.0)


def safe_normalize(v):
    """pbr_safe_normalize: v / |v|, and the zero vector for the zero vector."""
    v = np.asarray(v, dtype=np.float64)
    length = np.linalg.norm(v, axis=-1, keepdims=True)
    with np.errstate(invalid="ignore", divide="ignore"):
        return np.where(length > 0.0, v / np.where(length > 0.0, length, 1.0), 0.0)

ACES_NARKOWICZ_MAX_INPUT = 16.0         # PBR_ACES_NARKOWICZ_MAX_INPUT (tonemap/aces.glsl)

# GLSL macro -> value, for the shared-constant test (tests/library/test_glsl_layout.py).
SHARED = {"PBR_FLT_MIN": FLT_MIN, "PBR_SAFE_NORMALIZE_HUGE": SAFE_NORMALIZE_HUGE, "PBR_HALF_MAX": HALF_MAX, "PBR_MIN_ALPHA": MIN_ALPHA,
          "PBR_MIN_NDOTV": MIN_NDOTV, "PBR_MIN_HALF_VECTOR_LENGTH_SQUARED": MIN_HALF_VECTOR_LENGTH_SQUARED,
          "PBR_MIN_VDOTH": MIN_VDOTH, "PBR_MIN_NDOT_HALF_SUM": MIN_NDOT_HALF_SUM, "PBR_BECKMANN_MIN_NDOTH": BECKMANN_MIN_NDOTH, "PBR_MAX_IOR": MAX_IOR,
          "PBR_ACES_NARKOWICZ_MAX_INPUT": ACES_NARKOWICZ_MAX_INPUT}
