// pbr/brdf/g_schlick_ggx.hlsl: Schlick's approximation of Smith, matched to GGX.
//
// Provides: float pbr_G1_SchlickGGX(float NdotX, float k)
//           float pbr_G_SchlickGGX(float NdotL, float NdotV, float k)
//           float pbr_V_SchlickGGX(float NdotL, float NdotV, float k)
//           float pbr_k_SchlickGGX_from_alpha(float alpha)                  (k = alpha / 2)
//           float pbr_k_SchlickGGX_hotness(float perceptualRoughness)       (Disney "hotness")
// Include:  "pbr/brdf/g_schlick_ggx.hlsl" (path relative to hlsl_ports/)
// Config macros read: none.
//
// Schlick 1994, "An Inexpensive BRDF Model for Physically-based Rendering":
//   G1(x) = NdotX / (NdotX (1 - k) + k);   G = G1(l) · G1(v)
// (the lecture's "GGX-matched to GGX geometric term"). Karis 2013, "Real Shading in
// Unreal Engine 4", eq. 4: k = alpha / 2 matches Smith GGX ("Disney standard" in the
// lecture: k = alpha/2 = (g - 1)²/2); the Disney "hotness" remapping for analytic lights
// uses alpha = ((perceptualRoughness + 1) / 2)², i.e. k = (0.5 + perceptualRoughness/2)²/2
// (Burley 2012 §5.6; Karis 2013 p. 3).
// pbr_V_SchlickGGX = G / (4 NdotL NdotV) = 1 / (4 (NdotL(1-k)+k)(NdotV(1-k)+k)), finite as
// the cosines go to 0 when k > 0. Domain: cosines in [0, 1], k in (0, 1].
// Guards (pbr/common/guards.hlsl): cosines saturated, k clamped to [PBR_MIN_ALPHA / 2, 1]
// (k = alpha/2; k = 0 with NdotX = 0 is 0/0), V's cosines floored at PBR_MIN_NDOTV like
// every V. G1 is capped at 1: near NdotX = 1 the division rounds up to 1 + 1 ulp (found by
// the sweep). Bit-identical otherwise for cosines in [0, 1] (V: [1e-4, 1]), k in [5e-8, 1].
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_BRDF_G_SCHLICK_GGX_HLSL
#define PBR_BRDF_G_SCHLICK_GGX_HLSL
#include "pbr/common/shim.hlsl"  // generated from glsl/pbr/brdf/g_schlick_ggx.glsl by harness/pbrlab/gpu/port_hlsl.py: edit the GLSL, then regenerate

#include "pbr/common/guards.hlsl"

float pbr_G1_SchlickGGX(float NdotX, float k) {
    NdotX = pbr_saturate(NdotX);
    k = clamp(k, 0.5 * PBR_MIN_ALPHA, 1.0);
    return min(NdotX / (NdotX * (1.0 - k) + k), 1.0);
}

float pbr_G_SchlickGGX(float NdotL, float NdotV, float k) {
    return pbr_G1_SchlickGGX(NdotL, k) * pbr_G1_SchlickGGX(NdotV, k);
}

float pbr_V_SchlickGGX(float NdotL, float NdotV, float k) {
    NdotL = clamp(NdotL, PBR_MIN_NDOTV, 1.0);
    NdotV = clamp(NdotV, PBR_MIN_NDOTV, 1.0);
    k = clamp(k, 0.5 * PBR_MIN_ALPHA, 1.0);
    return 0.25 / ((NdotL * (1.0 - k) + k) * (NdotV * (1.0 - k) + k));
}

float pbr_k_SchlickGGX_from_alpha(float alpha) { return 0.5 * alpha; }

float pbr_k_SchlickGGX_hotness(float perceptualRoughness) {
    float r = 0.5 + 0.5 * perceptualRoughness;
    return 0.5 * r * r;
}

#endif // PBR_BRDF_G_SCHLICK_GGX_HLSL
