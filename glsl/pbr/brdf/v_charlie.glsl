// pbr/brdf/v_charlie.glsl: sheen visibility terms of KHR_materials_sheen.
//
// Provides: float pbr_sheen_lambda_exponent(float x, float alpha)   (the fit L of Λ)
//           float pbr_sheen_lambda(float cosTheta, float alpha)     (Λ)
//           float pbr_V_Charlie(float NdotL, float NdotV, float alpha)
//           float pbr_V_Neubelt(float NdotL, float NdotV)           (cheap, not a Smith V)
//           PBR_SHEEN_LAMBDA_R1_A .. _E, PBR_SHEEN_LAMBDA_R0_A .. _E (the fit's table)
// Include:  "pbr/brdf/v_charlie.glsl" (path relative to glsl/)
// Config macros read: none (pbr/shading/sheen.glsl selects one through PBR_SHEEN_V).
//
// V = G / (4 NdotL NdotV) as every V_ of the library.
// Charlie: Estevez & Kulla 2017, "Production Friendly Microfacet Sheen BRDF", §3: the
// height-correlated Smith G2 = 1 / (1 + Λ(v) + Λ(l)) of their distribution (d_charlie.glsl)
// with Λ fitted as
//   Λ(cos θ) = exp(L(cos θ))                   for cos θ < 1/2,
//            = exp(2 L(1/2) - L(1 - cos θ))    for cos θ >= 1/2,
//   L(x) = a / (1 + b x^c) + d x + e,   each of a..e = mix(its r = 1 value, its r = 0 value, (1 - r)²),
// r = alpha (table 1 of the paper; the values and the mix are KHR_materials_sheen's, which
// calls L "l" and Λ "lambda_sheen"). So
//   V_Charlie = 1 / ((1 + Λ(NdotV) + Λ(NdotL)) · 4 NdotV NdotL).
// Terminator softening (the paper's Λ'(cos θ) = Λ(cos θ)^(1 + 2 (1 - cos θ)^8)) is NOT applied:
// KHR_materials_sheen defines the visibility without it, so the shipped albedo table and a
// glTF viewer agree; the softening is not reciprocal when applied to the light only, as the
// paper does, and it changes the albedo by up to 1.0 (E at r = 0.07 and grazing view drops
// from 2.94 to 1.94; applied to both directions it removes the lobe, E <= 0.45) — measured
// with harness/pbrlab/maths/reference/sheen.py sheen_lambda_softened.
// Accuracy of the fit (measured, float64, against Λ integrated from D by Smith's relation
// 1 + Λ(v) = ∫ D(h) <v·h>+ dω_h / NdotV, cosines 1e-3, 0.01, 0.1, 0.5, 0.9): at alpha = 1
// within 4.3 % for cosines >= 0.01 (15 % high at 1e-3); at alpha = 0.25, 13 to 35 % high; at the
// floor alpha = 0.0049, 3.1 to 6.3 times too low. Too little masking means
// too much sheen at grazing: the white sheen's directional albedo E exceeds 1 at grazing
// views for perceptual roughness below 0.27, up to 2.94 (perceptual roughness 0.07, NdotV
// 1.7e-3; harness/pbrlab/gpu/sheen_table.py). The layering clamps its albedo scaling to [0, 1]
// (pbr/shading/sheen.glsl).
// Neubelt: Ashikhmin & Premoze 2007, "Distribution-based BRDFs", in the form of Neubelt &
// Pettineo 2013, "Crafting a Next-Gen Material Pipeline for The Order: 1886":
//   V_Neubelt = 1 / (4 (NdotL + NdotV - NdotL NdotV)),
// KHR's cheaper option ("not energy conserving with albedo scaling"). Cost and error of both
// against each other: the sheen report in the header of pbr/shading/sheen.glsl.
// Guards (pbr/common/guards.glsl): cosines clamped to [PBR_MIN_NDOTV, 1] (V ~ 1/(NdotV NdotL)
// and L has x^c, whose pow is undefined at 0); alpha to [PBR_SHEEN_MIN_ALPHA, 1], the floor of
// the distribution; 1 - cos θ reaches 0 at cos θ = 1, raised by pbr_pow_safe (limit 0).
// Largest values: Λ(1e-4) = 2.1e4 at the alpha floor, 8138 at alpha = 1; V_Charlie <= 1536
// (both cosines at the floor, alpha = 1), V_Neubelt <= 1250.
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_BRDF_V_CHARLIE_GLSL
#define PBR_BRDF_V_CHARLIE_GLSL

#include "pbr/common/guards.glsl"
#include "pbr/brdf/d_charlie.glsl"

// Estevez & Kulla 2017 table 1 (as KHR_materials_sheen prints it): the fit's parameters at
// r = 1 and r = 0. Shared with harness/pbrlab/maths/reference/sheen.py LAMBDA_AT_R1 / LAMBDA_AT_R0.
#define PBR_SHEEN_LAMBDA_R1_A 21.5473
#define PBR_SHEEN_LAMBDA_R1_B 3.82987
#define PBR_SHEEN_LAMBDA_R1_C 0.19823
#define PBR_SHEEN_LAMBDA_R1_D -1.97760
#define PBR_SHEEN_LAMBDA_R1_E -4.32054
#define PBR_SHEEN_LAMBDA_R0_A 25.3245
#define PBR_SHEEN_LAMBDA_R0_B 3.32435
#define PBR_SHEEN_LAMBDA_R0_C 0.16801
#define PBR_SHEEN_LAMBDA_R0_D -1.27393
#define PBR_SHEEN_LAMBDA_R0_E -4.85967

// L(x) for x in [0, 1/2] (x = 0 gives a + e, the limit), alpha as given (clamped to [0, 1]).
float pbr_sheen_lambda_exponent(float x, float alpha) {
    float r = pbr_saturate(alpha);
    float t = (1.0 - r) * (1.0 - r);
    float a = mix(PBR_SHEEN_LAMBDA_R1_A, PBR_SHEEN_LAMBDA_R0_A, t);
    float b = mix(PBR_SHEEN_LAMBDA_R1_B, PBR_SHEEN_LAMBDA_R0_B, t);
    float c = mix(PBR_SHEEN_LAMBDA_R1_C, PBR_SHEEN_LAMBDA_R0_C, t);
    float d = mix(PBR_SHEEN_LAMBDA_R1_D, PBR_SHEEN_LAMBDA_R0_D, t);
    float e = mix(PBR_SHEEN_LAMBDA_R1_E, PBR_SHEEN_LAMBDA_R0_E, t);
    x = clamp(x, 0.0, 0.5);
    return a / (1.0 + b * pbr_pow_safe(x, c)) + d * x + e;
}

float pbr_sheen_lambda(float cosTheta, float alpha) {
    cosTheta = clamp(cosTheta, PBR_MIN_NDOTV, 1.0);
    alpha = clamp(alpha, PBR_SHEEN_MIN_ALPHA, 1.0);
    bool below = cosTheta < 0.5;
    float L = pbr_sheen_lambda_exponent(below ? cosTheta : 1.0 - cosTheta, alpha);
    return exp(below ? L : 2.0 * pbr_sheen_lambda_exponent(0.5, alpha) - L);
}

float pbr_V_Charlie(float NdotL, float NdotV, float alpha) {
    NdotL = clamp(NdotL, PBR_MIN_NDOTV, 1.0);
    NdotV = clamp(NdotV, PBR_MIN_NDOTV, 1.0);
    float g2inv = 1.0 + pbr_sheen_lambda(NdotV, alpha) + pbr_sheen_lambda(NdotL, alpha);
    return 1.0 / (g2inv * 4.0 * NdotV * NdotL);
}

float pbr_V_Neubelt(float NdotL, float NdotV) {
    NdotL = clamp(NdotL, PBR_MIN_NDOTV, 1.0);
    NdotV = clamp(NdotV, PBR_MIN_NDOTV, 1.0);
    return 1.0 / (4.0 * (NdotL + NdotV - NdotL * NdotV));
}

#endif // PBR_BRDF_V_CHARLIE_GLSL
