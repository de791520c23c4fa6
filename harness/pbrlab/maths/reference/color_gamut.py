"""HDR display encodings, float64: the reference for the built-in pipeline's UnityColorGamut.cginc
names in pbrlab's Unity stand-in (importers/unity/cginc/UnityColorGamut.cginc). Sources:

- PQ: SMPTE ST 2084:2014 (= ITU-R BT.2100-2, Table 4): m1 = 2610/16384, m2 = 2523/4096 x 128,
  c1 = 3424/4096, c2 = 2413/4096 x 32, c3 = 2392/4096 x 32; the EOTF maps the signal E' to
  Y = (max(E'^(1/m2) - c1, 0) / (c2 - c3 E'^(1/m2)))^(1/m1) (luminance / 10000 nits), the
  inverse EOTF Y to E' = ((c1 + c2 Y^m1) / (1 + c3 Y^m1))^m2;
- primaries: ITU-R BT.709-6 item 1.3, ITU-R BT.2020-2 Table 3, P3-D65 SMPTE EG 432-1, all with
  D65 white; RGB -> XYZ from primaries as SMPTE RP 177 (aces_colorspaces.rgb_to_xyz);
- sRGB: IEC 61966-2-1 (color.linear_to_srgb / srgb_to_linear);
- Unity's composition (SimpleHDRDisplayToneMapAndOETF and its inverse: which gamut code takes
  which path, paper white in nits, 80-nit Rec.709 reference white off Metal): Unity's built-in
  shaders' UnityColorGamut.cginc, read for its behaviour.

Colours on the last axis; matrices act on column vectors (``M @ rgb``).
"""

from __future__ import annotations

import numpy as np

from .aces_colorspaces import D65, REC709, rgb_to_xyz
from .color import linear_to_srgb, srgb_to_linear

REC2020 = ((0.708, 0.292), (0.170, 0.797), (0.131, 0.046))
P3 = ((0.680, 0.320), (0.265, 0.690), (0.150, 0.060))

PQ_M1 = 2610.0 / 16384.0
PQ_M2 = 2523.0 / 4096.0 * 128.0
PQ_C1 = 3424.0 / 4096.0
PQ_C2 = 2413.0 / 4096.0 * 32.0
PQ_C3 = 2392.0 / 4096.0 * 32.0
PQ_PEAK_NITS = 10000.0
REC709_REFERENCE_WHITE_NITS = 80.0  # Unity's kReferenceLuminanceWhiteForRec709 off Metal

# Unity's gamut codes (ColorGamut.h, as UnityColorGamut.cginc lists them)
SRGB, REC709_CODE, REC2020_CODE, DISPLAY_P3, HDR10, DOLBY_HDR, P3D65_G22 = range(7)


def gamut_matrix(source, target) -> np.ndarray:
    """Linear RGB in ``source`` primaries to linear RGB in ``target`` primaries (both D65)."""
    return np.linalg.solve(rgb_to_xyz(target, D65), rgb_to_xyz(source, D65))


REC709_TO_REC2020 = gamut_matrix(REC709, REC2020)
REC2020_TO_REC709 = gamut_matrix(REC2020, REC709)
REC709_TO_P3 = gamut_matrix(REC709, P3)
P3_TO_REC709 = gamut_matrix(P3, REC709)


def pq_inverse_eotf(y):
    """ST 2084: normalised luminance Y (nits / 10000, >= 0) to the PQ signal."""
    p = np.asarray(y, np.float64) ** PQ_M1
    return ((PQ_C1 + PQ_C2 * p) / (1.0 + PQ_C3 * p)) ** PQ_M2


def pq_eotf(e):
    """ST 2084: the PQ signal in [0, 1] to normalised luminance (nits / 10000)."""
    r = np.asarray(e, np.float64) ** (1.0 / PQ_M2)
    return (np.maximum(r - PQ_C1, 0.0) / (PQ_C2 - PQ_C3 * r)) ** (1.0 / PQ_M1)


def display_encode(scene, gamut: int, paper_white: float, max_nits: float):
    """SimpleHDRDisplayToneMapAndOETF for a linear scene in linear colour space."""
    scene = np.asarray(scene, np.float64)
    if gamut == SRGB:
        return linear_to_srgb(scene)
    if gamut == HDR10:
        return pq_inverse_eotf(REC709_TO_REC2020 @ scene * (paper_white / PQ_PEAK_NITS))
    if gamut == P3D65_G22:
        return (REC709_TO_P3 @ scene * (paper_white / max_nits)) ** (1.0 / 2.2)
    return scene * (paper_white / REC709_REFERENCE_WHITE_NITS)


def display_decode(signal, gamut: int, paper_white: float, max_nits: float):
    """InverseSimpleHDRDisplayToneMapAndOETF in linear colour space: the inverse of display_encode."""
    signal = np.asarray(signal, np.float64)
    if gamut == SRGB:
        return srgb_to_linear(signal)
    if gamut == HDR10:
        return REC2020_TO_REC709 @ (pq_eotf(signal) / (paper_white / PQ_PEAK_NITS))
    if gamut == P3D65_G22:
        return P3_TO_REC709 @ (np.abs(signal) ** 2.2 / (paper_white / max_nits))
    return signal / (paper_white / REC709_REFERENCE_WHITE_NITS)
