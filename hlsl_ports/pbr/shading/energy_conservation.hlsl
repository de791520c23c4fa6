// pbr/shading/energy_conservation.hlsl: the diffuse-specular coupling: the diffuse lobe
// receives only the light the specular lobe does not reflect.
//
// Provides: vec3 pbr_diffuse_albedo_from_diffuse_color(vec3 diffuseColor, vec3 coatF0)
//           vec3 pbr_coupled_diffuse_color(vec3 diffuseColor, vec3 coatF0, vec3 coatAlbedo)
//           PBR_MIN_ONE_MINUS_REFLECTIVITY
// Include:  "pbr/shading/energy_conservation.hlsl" (path relative to hlsl_ports/)
// Config macros read: none.
//
// Coupling (Fdez-Aguera 2019, "A Multiple-Scattering Microfacet Model for Real-Time
// Image-based Lighting", section 4: k_D = rho (1 - E_spec); Kelemen & Szirmay-Kalos 2001,
// "A Microfacet Based Coupled Specular-Matte BRDF Model with Importance Sampling", for the
// idea that the matte layer receives 1 - E_spec): the diffuse lies under a dielectric coat,
// and receives the light that coat does not reflect. With E_coat(NdotV) the directional
// albedo of the coat's specular lobe (pbr_specular_albedo at the coat's F0, times the
// multiple-scattering compensation where it is applied), the diffuse colour becomes
// rho (1 - E_coat). The weight depends on the view only (not reciprocal, unlike Kelemen's
// (1 - E(l))(1 - E(v)) / (1 - E_avg)): it needs the table fetch shared with the split sum.
//
// coatF0, the coat: the dielectric part's F0, which is not the surface's f0 in between the
// workflows' ends. Metallic workflow: PBR_DIELECTRIC_F0 (Unity's
// unity_ColorSpaceDielectricSpec), while f0 = mix(0.04, albedo, m) also holds the metal's
// part, which has no diffuse under it; specular workflow: the specular colour (coat and
// f0 are the same). A metallic m in (0, 1) then reflects, per channel,
//   (1 - m) [rho (1 - E_coat) + E_coat] + m E_metal <= 1     (rho <= 1),
// the dielectric and the metal side by side (Burley 2012's linear blend of the two).
//
// rho, the diffuse albedo: the workflows of pbr/material/workflow.hlsl (and Unity's
// DiffuseAndSpecularFromMetallic / EnergyConservationBetweenDiffuseAndSpecular) scale the
// albedo by a constant 1 - reflectivity, Unity's stand-in for what the specular takes. The
// coupling replaces that constant by the view-dependent 1 - E_coat instead of applying
// both: rho = diffuseColor / (1 - max(coatF0)), the albedo for a dielectric and
// albedo (1 - m) for a metallic m, the dielectric's share. rho is capped at 1, so any
// diffuseColor conserves energy, also one that never went through a workflow.
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_SHADING_ENERGY_CONSERVATION_HLSL
#define PBR_SHADING_ENERGY_CONSERVATION_HLSL
#include "pbr/common/shim.hlsl"  // generated from glsl/pbr/shading/energy_conservation.glsl by harness/pbrlab/gpu/port_hlsl.py: edit the GLSL, then regenerate

#include "pbr/common/math.hlsl"

// Smallest 1 - max(coatF0) divided by: below it the coat is a mirror and diffuseColor is 0
// in the specular workflow (a nonzero one is capped at rho = 1). 1e-4 is a normal half (LOW tier).
#define PBR_MIN_ONE_MINUS_REFLECTIVITY 1e-4

float3 pbr_diffuse_albedo_from_diffuse_color(float3 diffuseColor, float3 coatF0) {
    float oneMinusReflectivity = max(1.0 - pbr_max3(coatF0), PBR_MIN_ONE_MINUS_REFLECTIVITY);
    return min(diffuseColor / oneMinusReflectivity, ((float3)(1.0)));
}

// coatAlbedo: the coat's specular directional albedo at this NdotV (per channel), i.e.
// pbr_specular_albedo(coatF0, dfg) and its variants.
float3 pbr_coupled_diffuse_color(float3 diffuseColor, float3 coatF0, float3 coatAlbedo) {
    return pbr_diffuse_albedo_from_diffuse_color(diffuseColor, coatF0)
         * (((float3)(1.0)) - pbr_saturate(coatAlbedo));
}

#endif // PBR_SHADING_ENERGY_CONSERVATION_HLSL
