// pbr/brdf/d_ggx.glsl: the GGX / Trowbridge-Reitz normal distribution.
//
// Provides: float pbr_D_GGX(float NdotH, float alpha)
// Include:  "pbr/brdf/d_ggx.glsl" (path relative to glsl/)
// Config macros read: none.
//
// Walter, Marschner, Li, Torrance 2007, "Microfacet Models for Refraction through Rough
// Surfaces", eq. 33 (Trowbridge & Reitz 1975), in the lecture's form:
//   D_GGX = alpha² / (π · ((NdotH)² (alpha² - 1) + 1)²),   alpha = perceptualRoughness².
// Rearranged for float32 precision: (NdotH)²(alpha² - 1) + 1 = (1 - NdotH²) + (NdotH·alpha)²
// and 1 - NdotH² = (1 - NdotH)(1 + NdotH). The textbook form cancels catastrophically at
// the peak: for alpha = 1e-3, NdotH = 1 it computes 1 + (alpha² - 1) with alpha² = 1e-6
// below half an ulp of 1 and loses ~6 % (12 % after squaring); here every term is positive
// and 1 - NdotH is exact (Sterbenz) for NdotH in [0.5, 1]. Same idea as Filament's
// D_GGX (Guy & Agopian, "Physically Based Rendering in Filament", §4.4.1, which uses
// |n × h|² for mediump). Exact formula, no clamp: alpha = 0 gives 0 everywhere except
// NdotH = 1 (0/0); the shading model clamps roughness (pbr/shading/standard.glsl).
// Domain NdotH in [0, 1], alpha in (0, 1]. Normalised: ∫ D (n·h) dω_h = 1 (tested).
#ifndef PBR_BRDF_D_GGX_GLSL
#define PBR_BRDF_D_GGX_GLSL

#include "pbr/common/constants.glsl"

float pbr_D_GGX(float NdotH, float alpha) {
    float oneMinusNdotH2 = (1.0 - NdotH) * (1.0 + NdotH);
    float a = NdotH * alpha;
    float k = alpha / (oneMinusNdotH2 + a * a);
    return k * k * PBR_INV_PI;
}

#endif // PBR_BRDF_D_GGX_GLSL
