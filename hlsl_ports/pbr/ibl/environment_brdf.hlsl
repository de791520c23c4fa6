// pbr/ibl/environment_brdf.hlsl: the split-sum environment BRDF and what surrounds it:
// specular occlusion, multiple-scattering energy compensation, prefiltered-mip choice.
//
// Provides: vec2 pbr_env_brdf_approx(float NdotV, float perceptualRoughness)
//           vec2 pbr_env_brdf(float NdotV, float perceptualRoughness)
//           vec3 pbr_specular_albedo(vec3 f0, vec2 dfg)
//           vec3 pbr_energy_compensation(vec3 f0, vec2 dfg)
//           float pbr_specular_occlusion(float NdotV, float occlusion, float alpha)
//           float pbr_ibl_lod_from_perceptual_roughness(float perceptualRoughness, float lodCount)
// Include:  "pbr/ibl/environment_brdf.hlsl" (path relative to hlsl_ports/)
// Config macros read: PBR_QUALITY (pbr/shading/dispatch.hlsl);
//           PBR_DFG_LUT_LOOKUP(NdotV, perceptualRoughness), a hook the caller may define
//           to sample its DFG table (it owns the sampler), returning vec2(A, B). Undefined,
//           or at PBR_QUALITY_LOW, the analytic fit is used.
//
// Split sum (Karis 2013, "Real Shading in Unreal Engine 4", eq. 8): the specular
// reflection of an environment is prefiltered radiance times the directional albedo of
// the BRDF, written f0 * A + f90 * B with A, B tabulated over (NdotV, roughness)
// (harness/pbrlab/ibl.py integrates the table with the library's own V term).
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_IBL_ENVIRONMENT_BRDF_HLSL
#define PBR_IBL_ENVIRONMENT_BRDF_HLSL
#include "pbr/common/shim.hlsl"  // generated from glsl/pbr/ibl/environment_brdf.glsl by harness/pbrlab/port_hlsl.py: edit the GLSL, then regenerate
#include "pbr/shading/dispatch.hlsl"

// Karis 2014, "Physically Based Shading on Mobile" (UE4's EnvBRDFApprox): a fit of the
// table for GGX + Schlick-GGX visibility; takes perceptual roughness. Its worst error
// against pbrlab's table (height-correlated Smith) is measured in tests/surface/.
float2 pbr_env_brdf_approx(float NdotV, float perceptualRoughness) {
    const float4 c0 = float4(-1.0, -0.0275, -0.572, 0.022);
    const float4 c1 = float4(1.0, 0.0425, 1.04, -0.04);
    float4 r = perceptualRoughness * c0 + c1;
    float a004 = min(r.x * r.x, exp2(-9.28 * NdotV)) * r.x + r.y;
    return float2(-1.04, 1.04) * a004 + r.zw;
}

float2 pbr_env_brdf(float NdotV, float perceptualRoughness) {
#if defined(PBR_DFG_LUT_LOOKUP) && PBR_QUALITY != PBR_QUALITY_LOW
    return PBR_DFG_LUT_LOOKUP(NdotV, perceptualRoughness);
#else
    return pbr_env_brdf_approx(NdotV, perceptualRoughness);
#endif
}

// Directional albedo of the specular lobe for F0 (f90 = 1: "everything has Fresnel").
float3 pbr_specular_albedo(float3 f0, float2 dfg) {
    return f0 * dfg.x + dfg.y;
}

// Single-scattering GGX loses energy at high roughness (up to 69 % at roughness 1, see
// glsl/README.md). Scale the specular lobe by 1 + f0 (1/E - 1), E = A + B the albedo at
// f0 = 1: Fdez-Aguera 2019, "A Multiple-Scattering Microfacet Model for Real-Time
// Image-based Lighting", as simplified in Filament ("Physically Based Rendering in
// Filament", section 5.3.4.7). A white metal in a white furnace then reflects 1.
// Lower bound of E in the division: the table's smallest E (rough, grazing) is about
// 0.3, so the guard only protects against a caller's zero dfg.
#define PBR_MIN_SPECULAR_ALBEDO 1e-4

float3 pbr_energy_compensation(float3 f0, float2 dfg) {
    return 1.0 + f0 * (1.0 / max(dfg.x + dfg.y, PBR_MIN_SPECULAR_ALBEDO) - 1.0);
}

// Specular occlusion from ambient occlusion: Lagarde & de Rousiers 2014, "Moving
// Frostbite to PBR", listing 26: saturate((NdotV + ao)^exp2(-16 alpha - 1) - 1 + ao).
float pbr_specular_occlusion(float NdotV, float occlusion, float alpha) {
    return clamp(pow(NdotV + occlusion, exp2(-16.0 * alpha - 1.0)) - 1.0 + occlusion, 0.0, 1.0);
}

// The mip of a prefiltered environment whose level i was filtered for perceptual
// roughness i / (lodCount - 1) (harness/pbrlab/ibl.py builds it that way).
float pbr_ibl_lod_from_perceptual_roughness(float perceptualRoughness, float lodCount) {
    return perceptualRoughness * (lodCount - 1.0);
}
#endif
