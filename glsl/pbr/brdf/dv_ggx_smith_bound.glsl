// pbr/brdf/dv_ggx_smith_bound.glsl: GGX D times the square-root-free bound of the
// height-correlated Smith V, as one quotient (the LOW tier's specular lobe).
//
// Provides: float pbr_DV_GGX_SmithBound(float nDotH, float nCrossH2, float h2, float NdotL,
//                                       float NdotV, float alpha)
// Include:  "pbr/brdf/dv_ggx_smith_bound.glsl" (path relative to glsl/)
// Config macros read: none.
//
// D = alpha² / (π dn²), dn = alpha² + (1 - alpha²) sin²θh (Walter et al. 2007 eq. 33), with
// sin²θh = |n × h|² / |h|² from an unnormalised h (dv_ggx_smith_correlated.glsl: the same
// two fmas, a sum of non-negative terms); V = 0.5 / (NdotL + NdotV) (v_smith_ggx_bound.glsl,
// Heitz 2014 eq. 99 with each square root bounded by 1). For h = l + v, NdotL + NdotV =
// n·(l + v) = nDotH (= 2 LdotH NdotH: V = 1 / (4 LdotH NdotH), Kelemen & Szirmay-Kalos 2001's
// 1 / (4 LdotH²) with one LdotH replaced by NdotH), so
//   D · V = (alpha² / 2π) / (dn² n·(l + v)),
// with n·v as it is (no clamp: n·(l + v) >= PBR_MIN_NDOT_HALF_SUM wherever the caller uses
// the lobe). NdotL and NdotV are not read (the dispatcher's common signature).
// Cheaper than the other tiers' lobes (issue 25, measured: docs/bench): no square root in V,
// and V from n·(l + v), which the caller has (no add, no clamp of NdotV).
// Why sin²θh from |n × h|², not 1 - NdotH² (1 - alpha²) (issue 35; the form issue 25 chose,
// 4 RDNA3 instructions cheaper): the cancelling form takes NdotH² = (n·h)² / |h|², whose
// float32 error is first order in the rounding of n·l and n·v (3 ulps of 1 each: 3 · 2^-24
// absolute); at a grazing mirror n·h = NdotL + NdotV = 2c, so NdotH² is off by about 6 · 2^-24 / c
// absolute, and dn >= alpha² by up to that over alpha² (0.57 of itself at c = 0.01 on the LOW
// floor, alpha² = 6.3e-5: D by 1.1), and where NdotH² rounds to 1 off the peak D jumps to its
// peak 1/(π alpha²).
// Measured in randomly rotated frames (10^6 grazing-mirror samples, tests/checking/hardcases/
// test_rotated_frames.py): worst 9.3e4 relative against the float64 model (14 at c in
// [1e-5, 1e-4), 0.14 at c in [0.01, 0.05)), 1.7 % of samples over the stated 1e-2; only with n
// on an axis, where n·l and n·v are exact, does it hold 4.4e-3. The rejection (l + v) - n n·(l + v)
// moves only along n when n·(l + v) is rounded, so |n × h|² changes in second order: the same
// sweep's worst is 0.069, the float32 rounding of the cosines themselves (V's 1 / n·(l + v)),
// which every tier shares; the test bounds it per sample from that rounding (the test's own
// draw of rotations: the cancelling form 304 relative, 7.5 % of samples over that bound).
// Preconditions (pbr_brdf_standard establishes them): alpha >= PBR_MIN_PERCEPTUAL_ROUGHNESS_MEDIUMP²,
// h = l + v with l, v unit, h2 = |h|² in [2^-126, 4], nCrossH2 = |n × h|² (any value >= 0:
// below the horizon, where NdotL = 0 stands in n·(l + v), it may exceed h2; dn stays >= alpha²),
// nDotH = n·h >= PBR_MIN_NDOT_HALF_SUM (elsewhere the caller does not select the value).
// Range: dn >= alpha², D · V <= 1 / (2π alpha² n·(l + v)) <= 2.8e18.
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_BRDF_DV_GGX_SMITH_BOUND_GLSL
#define PBR_BRDF_DV_GGX_SMITH_BOUND_GLSL

#include "pbr/common/constants.glsl"

float pbr_DV_GGX_SmithBound(float nDotH, float nCrossH2, float h2, float NdotL, float NdotV,
                            float alpha) {
    float a2 = alpha * alpha;
    float invH2 = 1.0 / h2;
    float dn = nCrossH2 * (invH2 - invH2 * a2) + a2;
    return (a2 * (0.5 * PBR_INV_PI)) / (dn * dn * nDotH);
}

#endif // PBR_BRDF_DV_GGX_SMITH_BOUND_GLSL
