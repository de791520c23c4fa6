// pbr/brdf/g_cook_torrance.hlsl: the original Cook-Torrance geometric attenuation.
//
// Provides: float pbr_G_CookTorrance(float NdotL, float NdotV, float NdotH, float VdotH)
//           float pbr_V_CookTorrance(float NdotL, float NdotV, float NdotH, float VdotH)
// Include:  "pbr/brdf/g_cook_torrance.hlsl" (path relative to hlsl_ports/)
// Config macros read: none.
//
// Blinn 1977 (V-groove derivation); Cook & Torrance 1982, "A Reflectance Model for
// Computer Graphics", ACM ToG 1(1), the geometrical attenuation factor G:
//   G_CT = min(1, 2 NdotH NdotV / VdotH, 2 NdotH NdotL / LdotH),  LdotH == VdotH.
// V_CookTorrance = G_CT / (4 NdotL NdotV) (the visibility convention). Domain: cosines in
// (0, 1]. Guards (pbr/common/guards.hlsl): cosines saturated, VdotH floored at
// PBR_MIN_VDOTH (VdotH -> 0 only as l -> -v), V's NdotL, NdotV floored at PBR_MIN_NDOTV.
// Bit-identical for cosines in [0, 1], VdotH >= 5e-6 (G) and NdotL, NdotV >= 1e-4 (V).
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_BRDF_G_COOK_TORRANCE_HLSL
#define PBR_BRDF_G_COOK_TORRANCE_HLSL
#include "pbr/common/shim.hlsl"  // generated from glsl/pbr/brdf/g_cook_torrance.glsl by harness/pbrlab/gpu/port_hlsl.py: edit the GLSL, then regenerate

#include "pbr/common/guards.hlsl"

float pbr_G_CookTorrance(float NdotL, float NdotV, float NdotH, float VdotH) {
    float VdotHSafe = clamp(VdotH, PBR_MIN_VDOTH, 1.0);
    return min(1.0, 2.0 * pbr_saturate(NdotH) * pbr_saturate(min(NdotV, NdotL)) / VdotHSafe);
}

float pbr_V_CookTorrance(float NdotL, float NdotV, float NdotH, float VdotH) {
    return pbr_G_CookTorrance(NdotL, NdotV, NdotH, VdotH)
         / (4.0 * clamp(NdotL, PBR_MIN_NDOTV, 1.0) * clamp(NdotV, PBR_MIN_NDOTV, 1.0));
}

#endif // PBR_BRDF_G_COOK_TORRANCE_HLSL
