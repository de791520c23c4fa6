// pbr/shading/energy_conservation.hlsl: the diffuse-specular coupling: the diffuse lobe
// receives only the light the specular lobe does not reflect.
//
// Provides: vec3 pbr_diffuse_albedo_from_diffuse_color(vec3 diffuseColor, vec3 f0)
//           vec3 pbr_coupled_diffuse_color(vec3 diffuseColor, vec3 f0, vec3 specularAlbedo)
//           PBR_MIN_ONE_MINUS_REFLECTIVITY
// Include:  "pbr/shading/energy_conservation.hlsl" (path relative to hlsl_ports/)
// Config macros read: none.
//
// Coupling (Fdez-Aguera 2019, "A Multiple-Scattering Microfacet Model for Real-Time
// Image-based Lighting", section 4: k_D = rho (1 - E_spec); Kelemen & Szirmay-Kalos 2001,
// "A Microfacet Based Coupled Specular-Matte BRDF Model with Importance Sampling", for the
// idea that the matte layer receives 1 - E_spec): with E_spec(NdotV) the directional
// albedo of the specular lobe (pbr_specular_albedo, times the multiple-scattering
// compensation where it is applied), the diffuse colour becomes rho (1 - E_spec). For any
// rho <= 1 a surface then reflects E_spec + rho (1 - E_spec) <= 1 of a white furnace, and
// exactly 1 when rho = 1 and the specular conserves energy (white metal or white dielectric
// with compensation). The weight depends on the view only (not reciprocal, unlike Kelemen's
// (1 - E(l))(1 - E(v)) / (1 - E_avg)): it needs one table fetch, shared with the split sum.
//
// rho, the diffuse albedo: the workflows of pbr/material/workflow.hlsl (and Unity's
// DiffuseAndSpecularFromMetallic / EnergyConservationBetweenDiffuseAndSpecular) already
// scale the albedo by a constant 1 - reflectivity, Unity's stand-in for what the specular
// takes. The coupling replaces that constant by the view-dependent 1 - E_spec instead of
// applying both: rho = diffuseColor / (1 - max(f0)), exactly the albedo for a dielectric
// (metallic 0, or any specular colour), at most the albedo in between (metallic m in
// (0, 1): (1 - 0.04)(1 - m) <= 1 - max(f0)). rho is capped at 1, so any diffuseColor
// conserves energy, also one that never went through a workflow.
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_SHADING_ENERGY_CONSERVATION_HLSL
#define PBR_SHADING_ENERGY_CONSERVATION_HLSL
#include "pbr/common/shim.hlsl"  // generated from glsl/pbr/shading/energy_conservation.glsl by harness/pbrlab/port_hlsl.py: edit the GLSL, then regenerate

#include "pbr/common/math.hlsl"

// Smallest 1 - max(f0) divided by: below it f0 is a metal's and diffuseColor is 0 in
// both workflows (a nonzero one is capped at rho = 1). 1e-4 is a normal half (LOW tier).
#define PBR_MIN_ONE_MINUS_REFLECTIVITY 1e-4

float3 pbr_diffuse_albedo_from_diffuse_color(float3 diffuseColor, float3 f0) {
    float oneMinusReflectivity = max(1.0 - pbr_max3(f0), PBR_MIN_ONE_MINUS_REFLECTIVITY);
    return min(diffuseColor / oneMinusReflectivity, ((float3)(1.0)));
}

// specularAlbedo: the specular lobe's directional albedo at this NdotV (per channel).
float3 pbr_coupled_diffuse_color(float3 diffuseColor, float3 f0, float3 specularAlbedo) {
    return pbr_diffuse_albedo_from_diffuse_color(diffuseColor, f0)
         * (((float3)(1.0)) - pbr_saturate(specularAlbedo));
}

#endif // PBR_SHADING_ENERGY_CONSERVATION_HLSL
