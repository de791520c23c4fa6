// pbr/brdf/g_smith_ggx.hlsl: the exact separable Smith masking-shadowing for GGX.
//
// Provides: float pbr_G1_SmithGGX(float NdotX, float alpha)
//           float pbr_G_SmithGGX(float NdotL, float NdotV, float alpha)
//           float pbr_V_SmithGGX(float NdotL, float NdotV, float alpha)
// Include:  "pbr/brdf/g_smith_ggx.hlsl" (path relative to hlsl_ports/)
// Config macros read: none.
//
// Walter et al. 2007, "Microfacet Models for Refraction through Rough Surfaces", eq. 34:
//   G1(x) = 2 / (1 + sqrt(1 + alpha² tan²θx)),
// multiplied by cos θx / cos θx to avoid the tangent (the lecture's "GGX-based geometric
// term", used in The Order: 1886, Neubelt & Pettineo 2013):
//   G1(x) = 2 NdotX / (NdotX + sqrt(alpha² + (1 - alpha²) NdotX²)),
//   G = G1(l) · G1(v)  (separable: masking and shadowing assumed uncorrelated).
// pbr_V_SmithGGX = G / (4 NdotL NdotV), the lecture's Viz_GGX-R, written without the
// cosines so it stays finite as NdotL, NdotV -> 0:
//   V = 1 / ((NdotV + sqrt(alpha² + (1 - alpha²) NdotV²)) (NdotL + sqrt(...NdotL...))).
// Domain: cosines in [0, 1], alpha in [0, 1]. Guards (pbr/common/guards.hlsl): cosines
// saturated, alpha clamped to [PBR_MIN_ALPHA, 1] (G1(0, 0) is 0/0; decided 0: no light
// reaches along the horizon), V's cosines floored at PBR_MIN_NDOTV, G1 capped at 1 against
// rounding (2c / (c + sqrt(c²)) at alpha -> 0 may round to 1 + 1 ulp). Bit-identical for
// cosines in [0, 1] (V: [1e-4, 1]) and alpha in [1e-7, 1].
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_BRDF_G_SMITH_GGX_HLSL
#define PBR_BRDF_G_SMITH_GGX_HLSL
#include "pbr/common/shim.hlsl"  // generated from glsl/pbr/brdf/g_smith_ggx.glsl by harness/pbrlab/gpu/port_hlsl.py: edit the GLSL, then regenerate

#include "pbr/common/guards.hlsl"

// NdotX + sqrt(alpha² + (1 - alpha²) NdotX²): the common denominator of G1 and V
// (NdotX in [0, 1], alpha in [PBR_MIN_ALPHA, 1]: >= 1e-7).
float pbr_SmithGGX_denominator(float NdotX, float alpha) {
    float a2 = alpha * alpha;
    return NdotX + sqrt(a2 + (1.0 - a2) * NdotX * NdotX);
}

float pbr_G1_SmithGGX(float NdotX, float alpha) {
    NdotX = pbr_saturate(NdotX);
    return min(2.0 * NdotX / pbr_SmithGGX_denominator(NdotX, clamp(alpha, PBR_MIN_ALPHA, 1.0)), 1.0);
}

float pbr_G_SmithGGX(float NdotL, float NdotV, float alpha) {
    return pbr_G1_SmithGGX(NdotL, alpha) * pbr_G1_SmithGGX(NdotV, alpha);
}

float pbr_V_SmithGGX(float NdotL, float NdotV, float alpha) {
    alpha = clamp(alpha, PBR_MIN_ALPHA, 1.0);
    return 1.0 / (pbr_SmithGGX_denominator(clamp(NdotV, PBR_MIN_NDOTV, 1.0), alpha)
                * pbr_SmithGGX_denominator(clamp(NdotL, PBR_MIN_NDOTV, 1.0), alpha));
}

#endif // PBR_BRDF_G_SMITH_GGX_HLSL
