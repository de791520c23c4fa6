// pbr/material/workflow.hlsl: metallic and specular workflows (diffuse colour and F0).
//
// Provides: PBR_DIELECTRIC_F0, pbr_f0_from_metallic, pbr_diffuse_from_metallic,
//           pbr_f0_from_metallic_dielectric, pbr_diffuse_from_metallic_dielectric,
//           pbr_f90_from_metallic,
//           pbr_diffuse_from_specular (monochrome), pbr_diffuse_from_specular_per_channel.
// Include:  "pbr/material/workflow.hlsl" (path relative to hlsl_ports/)
// Config macros read: none.
//
// Lecture, "Metals vs. dielectrics": dielectrics have a white (grey) specular and a
// diffuse; metals are purely specular with a coloured F0. Both workflows give
// (diffuseColor, f0) for pbr/shading/standard.hlsl. float64 twin: reference/material.py.
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_MATERIAL_WORKFLOW_HLSL
#define PBR_MATERIAL_WORKFLOW_HLSL
#include "pbr/common/shim.hlsl"  // generated from glsl/pbr/material/workflow.glsl by harness/pbrlab/gpu/port_hlsl.py: edit the GLSL, then regenerate

#include "pbr/common/math.hlsl"

// F0 of the common dielectric: 0.04 = ((1.5 - 1) / (1.5 + 1))², glass of IOR 1.5. Lagarde
// 2011 ("Feeding a physically based shading model", the lecture's F0 table: Glass 0.04);
// Karis 2013 and Unity's unity_ColorSpaceDielectricSpec (linear) use the same value.
// Shared with reference/material.py DIELECTRIC_F0.
#define PBR_DIELECTRIC_F0 0.04

// Metallic workflow with the dielectric's own F0 (KHR_materials_specular, "Implementation":
// F0 = lerp(dielectric_f0, baseColor, metallic), dielectric_f0 = min(((ior - 1) / (ior + 1))²
// · specularColor, 1) · specular; KHR_materials_ior for the ior). The metal's share reflects
// its albedo, the dielectric's share its own dielectricF0 (linear RGB, each channel <= 1).
float3 pbr_f0_from_metallic_dielectric(float3 albedo, float metallic, float3 dielectricF0) {
    return lerp(dielectricF0, albedo, metallic);
}

// Diffuse colour of the metallic workflow with the dielectric's own F0: Unity's form below
// with 0.04 generalised to the dielectric's monochrome reflectivity, as Unity's specular
// workflow weighs its diffuse (EnergyConservationBetweenDiffuseAndSpecular,
// UNITY_CONSERVE_ENERGY_MONOCHROME):
//   diffuse = albedo · (1 - max(dielectricF0.r, .g, .b)) · (1 - metallic).
// metallic = 0 is the specular workflow with specular = dielectricF0 (pbr_diffuse_from_specular),
// dielectricF0 = vec3(0.04) is pbr_diffuse_from_metallic, both exactly (tested). The
// Khronos Sample Renderer instead weighs the diffuse by 1 - F_dielectric per channel and per
// light (its mix(diffuse, specular, F_Schlick(f0, f90, VdotH))): docs/gltf.md names the difference.
float3 pbr_diffuse_from_metallic_dielectric(float3 albedo, float metallic, float3 dielectricF0) {
    return albedo * ((1.0 - pbr_max3(dielectricF0)) * (1.0 - metallic));
}

// F90 of the metallic workflow whose dielectric has its own F90 (KHR_materials_specular,
// "Implementation": F90 = lerp(dielectric_f90, 1, metallic), dielectric_f90 = specular): a
// metal reflects everything at grazing incidence.
float pbr_f90_from_metallic(float dielectricF90, float metallic) {
    return lerp(dielectricF90, 1.0, metallic);
}

// Metallic workflow (Burley 2012, the "metallic" parameter; Karis 2013, "Material Model"):
// F0 = lerp(0.04, albedo, metallic): the dielectric's F0 is PBR_DIELECTRIC_F0.
float3 pbr_f0_from_metallic(float3 albedo, float metallic) {
    return pbr_f0_from_metallic_dielectric(albedo, metallic, ((float3)(PBR_DIELECTRIC_F0)));
}

// Diffuse colour of the metallic workflow, in Unity's form (UnityStandardUtils.cginc,
// DiffuseAndSpecularFromMetallic / OneMinusReflectivityFromMetallic):
//   diffuse = albedo · (1 - 0.04) · (1 - metallic).
// Metals get no diffuse; a dielectric keeps 1 - F0 of its albedo, so that metallic = 0
// equals the specular workflow with specular = 0.04 exactly (tested).
float3 pbr_diffuse_from_metallic(float3 albedo, float metallic) {
    return pbr_diffuse_from_metallic_dielectric(albedo, metallic, ((float3)(PBR_DIELECTRIC_F0)));
}

// Specular workflow, energy conservation between diffuse and specular, monochrome form
// (Unity's EnergyConservationBetweenDiffuseAndSpecular with UNITY_CONSERVE_ENERGY_MONOCHROME,
// the Standard shader's default): diffuse = albedo · (1 - max(specular.r, .g, .b)).
// Keeps the diffuse hue; guarantees diffuse + specular <= 1 in every channel when
// albedo <= 1 (the lecture's "practical need M_diff + M_spec < 1").
float3 pbr_diffuse_from_specular(float3 albedo, float3 specular) {
    return albedo * (1.0 - pbr_max3(specular));
}

// Per-channel form (Unity's same function without UNITY_CONSERVE_ENERGY_MONOCHROME):
// diffuse = albedo · (1 - specular). Tighter per channel but shifts the diffuse hue
// towards the complement of the specular colour.
float3 pbr_diffuse_from_specular_per_channel(float3 albedo, float3 specular) {
    return albedo * (((float3)(1.0)) - specular);
}

#endif // PBR_MATERIAL_WORKFLOW_HLSL
