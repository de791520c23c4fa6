// pbr/brdf/v_smith_ggx_bound.hlsl: a lower bound of the height-correlated Smith V without a
// square root (the LOW tier's visibility).
//
// Provides: float pbr_V_SmithGGXBound(float NdotL, float NdotV)
// Include:  "pbr/brdf/v_smith_ggx_bound.hlsl" (path relative to hlsl_ports/)
// Config macros read: none.
//
// Heitz 2014, "Understanding the Masking-Shadowing Function in Microfacet-Based BRDFs",
// eq. 99: V = 0.5 / (NdotL sqrt(NdotV² (1 - alpha²) + alpha²) + NdotV sqrt(NdotL² (1 - alpha²)
// + alpha²)). Each square root is at most 1 (its argument is a mix of x² <= 1 and 1), so
//   V_bound = 0.5 / (NdotL + NdotV) <= V  for every alpha,
// exact at alpha = 1, and the lobe it gives reflects no more energy than the exact one (its
// white furnace is at most the Smith lobe's, itself <= 1). No square root and no roughness:
// D · V_bound costs one add for V. Error against V: V_bound / V = lambda / (NdotL + NdotV),
// 1 at alpha = 1 and at NdotL = NdotV = 1, falling to 2 NdotL NdotV / (NdotL + NdotV) as
// alpha -> 0 (half at NdotL = NdotV = 0.5): it darkens smooth lobes away from normal
// incidence, most at grazing. The idea of trading V's accuracy for a bound that keeps the
// energy is Kelemen & Szirmay-Kalos 2001's (V ≈ 1/(4 VdotH²), which does not keep it).
// Guards (pbr/common/guards.hlsl): cosines clamped to [PBR_MIN_NDOTV, 1] (V <= 2500), as the
// other V terms; pbr_DV_GGX_SmithBound, the fused form, takes them as they are.
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_BRDF_V_SMITH_GGX_BOUND_HLSL
#define PBR_BRDF_V_SMITH_GGX_BOUND_HLSL
#include "pbr/common/shim.hlsl"  // generated from glsl/pbr/brdf/v_smith_ggx_bound.glsl by harness/pbrlab/gpu/port_hlsl.py: edit the GLSL, then regenerate

#include "pbr/common/guards.hlsl"

float pbr_V_SmithGGXBound(float NdotL, float NdotV) {
    return 0.5 / (clamp(NdotL, PBR_MIN_NDOTV, 1.0) + clamp(NdotV, PBR_MIN_NDOTV, 1.0));
}

#endif // PBR_BRDF_V_SMITH_GGX_BOUND_HLSL
