// pbr/brdf/dv_ggx_smith_correlated.glsl: GGX D times the height-correlated Smith V, as one
// quotient (the HIGH tier's specular lobe without the MIN_* guards its terms carry alone).
//
// Provides: float pbr_DV_GGX_SmithCorrelated(float nDotH, float nCrossH2, float h2,
//                                            float NdotL, float NdotV, float alpha)
//           float pbr_DV_GGX_fromLambdaSum(float nDotH, float nCrossH2, float h2, float alpha,
//                                          float lambdaSum)  (GGX times any V = 0.5 / lambdaSum)
// Include:  "pbr/brdf/dv_ggx_smith_correlated.glsl" (path relative to glsl/)
// Config macros read: none.
//
// The product of two formulas the library has separately:
//   D = alpha² / (π d²),  d = (1 - NdotH²) + (NdotH·alpha)²      (Walter et al. 2007 eq. 33,
//       in d_ggx.glsl's cancellation-free form, 1 - NdotH² = |n × h|²)
//   V = 0.5 / (lambdaV + lambdaL),                                 (Heitz 2014 eq. 99,
//       lambdaV = NdotL sqrt(NdotV² (1 - alpha²) + alpha²),         v_smith_ggx_correlated.glsl)
//       lambdaL = NdotV sqrt(NdotL² (1 - alpha²) + alpha²)
//   D · V = (alpha² / 2π) / (d² (lambdaV + lambdaL)): one reciprocal instead of two.
// h need not be normalised: for h = k·ĥ (k > 0), n·h = k n·ĥ and |n × h|² = k² |n × ĥ|², so
// dividing both squares by h2 = |h|² = k² gives 1 - NdotH² and NdotH² of the unit ĥ:
//   dn = (|n × h|² + (n·h)² alpha²) / h2 = (1 - NdotH²) + NdotH² alpha²  in [alpha², 1],
//   D · V = (alpha² / 2π) / (dn² (lambdaV + lambdaL)).
// The caller passes h = l + v as it is and saves the reciprocal square root and three
// multiplies that normalising h would cost; the one reciprocal of h2 costs what the former
// unnormalised quotient's h2² numerator cost, and unlike it keeps every intermediate in a
// fixed range however short l + v is: a grazing mirror (l + v = 2c·n, c = NdotL = NdotV)
// keeps its lobe as c -> 0 (issue 25), where d² of the unnormalised form, (4c² alpha²)²,
// left float32's normal range.
// Preconditions, which the caller (pbr_brdf_standard) establishes once for the whole BRDF,
// so none of the terms' own clamps is repeated here:
//   alpha >= PBR_MIN_PERCEPTUAL_ROUGHNESS² (2.0e-3), NdotL in (0, 1], NdotV in
//   [PBR_MIN_NDOTV, 1], nDotH = n·h, nCrossH2 = |n × h|², h2 = |h|² of one h, with h2 in
//   [2^-100, 4] (pbr_brdf_standard: n·(l + v) >= PBR_MIN_NDOT_HALF_SUM, |l + v|² capped at 4).
// nDotH enters squared: D is even in n·h, so an h below the surface (a view below the
// horizon) gives GGX at |n·ĥ|, finite, with no clamp.
// Range: dn >= alpha² >= 4.1e-6, dn² >= 1.7e-11; lambdaV + lambdaL >= NdotV alpha >= 2e-7;
// the denominator stays >= 3e-18 and D · V <= 2e11 for every h2 in the range above.
// Outside the preconditions (h = 0: 0 · Inf) the quotient is NaN and the caller must not use
// it (pbr_brdf_standard selects 0 there).
// Measured price of the terms' own guards, and the fused form's error: docs/bench.
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_BRDF_DV_GGX_SMITH_CORRELATED_GLSL
#define PBR_BRDF_DV_GGX_SMITH_CORRELATED_GLSL

#include "pbr/common/constants.glsl"

// The GGX part, for every V of the form 0.5 / lambdaSum (lambdaSum > 0).
float pbr_DV_GGX_fromLambdaSum(float nDotH, float nCrossH2, float h2, float alpha,
                               float lambdaSum) {
    float a2 = alpha * alpha;
    float dn = (nCrossH2 + nDotH * nDotH * a2) * (1.0 / h2);
    return (a2 * (0.5 * PBR_INV_PI)) / (dn * dn * lambdaSum);
}

float pbr_DV_GGX_SmithCorrelated(float nDotH, float nCrossH2, float h2, float NdotL,
                                 float NdotV, float alpha) {
    float a2 = alpha * alpha;
    float lambdaV = NdotL * sqrt(NdotV * NdotV * (1.0 - a2) + a2);
    float lambdaL = NdotV * sqrt(NdotL * NdotL * (1.0 - a2) + a2);
    return pbr_DV_GGX_fromLambdaSum(nDotH, nCrossH2, h2, alpha, lambdaV + lambdaL);
}

#endif // PBR_BRDF_DV_GGX_SMITH_CORRELATED_GLSL
