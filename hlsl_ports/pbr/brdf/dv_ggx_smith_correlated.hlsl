// pbr/brdf/dv_ggx_smith_correlated.hlsl: GGX D times the height-correlated Smith V, as one
// quotient (the HIGH tier's specular lobe without the MIN_* guards its terms carry alone).
//
// Provides: float pbr_DV_GGX_SmithCorrelated(float nDotH, float nCrossH2, float h2,
//                                            float NdotL, float NdotV, float alpha)
//           float pbr_DV_GGX_fromLambdaSum(float nDotH, float nCrossH2, float h2, float alpha,
//                                          float lambdaSum)  (GGX times any V = 0.5 / lambdaSum)
// Include:  "pbr/brdf/dv_ggx_smith_correlated.hlsl" (path relative to hlsl_ports/)
// Config macros read: none.
//
// The product of two formulas the library has separately:
//   D = alpha² / (π d²),  d = (1 - NdotH²) + (NdotH·alpha)²      (Walter et al. 2007 eq. 33,
//       in d_ggx.hlsl's cancellation-free form, 1 - NdotH² = |n × h|²)
//   V = 0.5 / (lambdaV + lambdaL),                                 (Heitz 2014 eq. 99,
//       lambdaV = NdotL sqrt(NdotV² (1 - alpha²) + alpha²),         v_smith_ggx_correlated.hlsl)
//       lambdaL = NdotV sqrt(NdotL² (1 - alpha²) + alpha²)
//   D · V = (alpha² / 2π) / (d² (lambdaV + lambdaL)): one reciprocal instead of two.
// h need not be normalised: for h = k·ĥ (k > 0), |n × h|² = k² |n × ĥ|², so dividing it by
// h2 = |h|² = k² gives 1 - NdotH² = sin²θh of the unit ĥ. With NdotH² = 1 - sin²θh,
//   dn = (1 - NdotH²) + NdotH² alpha² = alpha² + (1 - alpha²) sin²θh
//      = alpha² + |n × h|² · (1/h2 - alpha²/h2)      in [alpha², 1],
//   D · V = (alpha² / 2π) / (dn² (lambdaV + lambdaL)):
// a sum of two non-negative terms, so no cancellation however close to the mirror (sin²θh
// carries |n × h|²'s relative error, and alpha² is added to it exactly as the exact D does),
// and two fused multiply-adds (1/h2 - alpha²/h2, then the product plus alpha²) where the form
// (|n × h|² + (n·h)² alpha²) / h2 needed a square, a product and a multiply more
// (issue 25: one RDNA3/RDNA2/GCN5 instruction fewer, docs/bench).
// lambda = NdotX sqrt((NdotY - NdotY alpha²) NdotY + alpha²): Filament's arrangement of the
// same radicand (Guy & Agopian, "Physically Based Rendering in Filament", §4.4.2), two fused
// multiply-adds with no 1 - alpha² (one instruction fewer; NdotY - NdotY alpha² >= 0, so no
// cancellation either).
// The caller passes h = l + v as it is and saves the reciprocal square root and three
// multiplies that normalising h would cost; the one reciprocal of h2 keeps every
// intermediate in a fixed range however short l + v is: a grazing mirror (l + v = 2c·n,
// c = NdotL = NdotV) keeps its lobe as c -> 0 (issue 25), where d² of the unnormalised form,
// (4c² alpha²)², left float32's normal range.
// Preconditions, which the caller (pbr_brdf_standard) establishes once for the whole BRDF,
// so none of the terms' own clamps is repeated here:
//   alpha >= PBR_MIN_PERCEPTUAL_ROUGHNESS² (2.0e-3), NdotL in [0, 1], NdotV in
//   [PBR_MIN_NDOTV, 1], nCrossH2 = |n × h|² >= 0, h2 = |h|² >= PBR_FLT_MIN (pbr_brdf_standard
//   adds PBR_FLT_MIN to |l + v|²: pbr_length2_nonzero).
// Range: 1/h2 <= 2^126 is finite, so dn >= alpha² >= 4.1e-6 is finite or +Inf (a
// nCrossH2 / h2 that overflows: then D · V = 0, never NaN); lambdaV + lambdaL >= NdotV alpha
// >= 2e-7 > 0; the denominator stays >= 3e-18 and D · V <= 2e11. So the quotient is finite
// and non-negative for every input the caller gives, whether or not h is the half vector of
// a lit direction (pbr_brdf_standard selects where it is: χ+ of n·h).
// nDotH is not read (pbr_brdf_standard's χ+ selection uses it); it stays in the signature so
// every D · V that pbr_specular_DV selects takes the same arguments.
// Measured price of the terms' own guards, and the fused form's error: docs/bench.
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_BRDF_DV_GGX_SMITH_CORRELATED_HLSL
#define PBR_BRDF_DV_GGX_SMITH_CORRELATED_HLSL
#include "pbr/common/shim.hlsl"  // generated from glsl/pbr/brdf/dv_ggx_smith_correlated.glsl by harness/pbrlab/gpu/port_hlsl.py: edit the GLSL, then regenerate

#include "pbr/common/constants.hlsl"

// The GGX part, for every V of the form 0.5 / lambdaSum (lambdaSum > 0).
float pbr_DV_GGX_fromLambdaSum(float nDotH, float nCrossH2, float h2, float alpha,
                               float lambdaSum) {
    float a2 = alpha * alpha;
    float invH2 = 1.0 / h2;
    float dn = nCrossH2 * (invH2 - invH2 * a2) + a2;  // alpha² + (1 - alpha²) sin²θh
    return (a2 * (0.5 * PBR_INV_PI)) / (dn * dn * lambdaSum);
}

float pbr_DV_GGX_SmithCorrelated(float nDotH, float nCrossH2, float h2, float NdotL,
                                 float NdotV, float alpha) {
    float a2 = alpha * alpha;
    float lambdaV = NdotL * sqrt((NdotV - NdotV * a2) * NdotV + a2);
    float lambdaL = NdotV * sqrt((NdotL - NdotL * a2) * NdotL + a2);
    return pbr_DV_GGX_fromLambdaSum(nDotH, nCrossH2, h2, alpha, lambdaV + lambdaL);
}

#endif // PBR_BRDF_DV_GGX_SMITH_CORRELATED_HLSL
