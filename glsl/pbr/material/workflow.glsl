// pbr/material/workflow.glsl: metallic and specular workflows (diffuse colour and F0).
//
// Provides: PBR_DIELECTRIC_F0, pbr_f0_from_metallic, pbr_diffuse_from_metallic,
//           pbr_diffuse_from_specular (monochrome), pbr_diffuse_from_specular_per_channel.
// Include:  "pbr/material/workflow.glsl" (path relative to glsl/)
// Config macros read: none.
//
// Lecture, "Metals vs. dielectrics": dielectrics have a white (grey) specular and a
// diffuse; metals are purely specular with a coloured F0. Both workflows give
// (diffuseColor, f0) for pbr/shading/standard.glsl. float64 twin: reference/material.py.
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_MATERIAL_WORKFLOW_GLSL
#define PBR_MATERIAL_WORKFLOW_GLSL

#include "pbr/common/math.glsl"

// F0 of the common dielectric: 0.04 = ((1.5 - 1) / (1.5 + 1))², glass of IOR 1.5. Lagarde
// 2011 ("Feeding a physically based shading model", the lecture's F0 table: Glass 0.04);
// Karis 2013 and Unity's unity_ColorSpaceDielectricSpec (linear) use the same value.
// Shared with reference/material.py DIELECTRIC_F0.
#define PBR_DIELECTRIC_F0 0.04

// Metallic workflow (Burley 2012, the "metallic" parameter; Karis 2013, "Material Model"):
// F0 = lerp(0.04, albedo, metallic).
vec3 pbr_f0_from_metallic(vec3 albedo, float metallic) {
    return mix(vec3(PBR_DIELECTRIC_F0), albedo, metallic);
}

// Diffuse colour of the metallic workflow, in Unity's form (UnityStandardUtils.cginc,
// DiffuseAndSpecularFromMetallic / OneMinusReflectivityFromMetallic):
//   diffuse = albedo · (1 - 0.04) · (1 - metallic).
// Metals get no diffuse; a dielectric keeps 1 - F0 of its albedo, so that metallic = 0
// equals the specular workflow with specular = 0.04 exactly (tested).
vec3 pbr_diffuse_from_metallic(vec3 albedo, float metallic) {
    return albedo * ((1.0 - PBR_DIELECTRIC_F0) * (1.0 - metallic));
}

// Specular workflow, energy conservation between diffuse and specular, monochrome form
// (Unity's EnergyConservationBetweenDiffuseAndSpecular with UNITY_CONSERVE_ENERGY_MONOCHROME,
// the Standard shader's default): diffuse = albedo · (1 - max(specular.r, .g, .b)).
// Keeps the diffuse hue; guarantees diffuse + specular <= 1 in every channel when
// albedo <= 1 (the lecture's "practical need M_diff + M_spec < 1").
vec3 pbr_diffuse_from_specular(vec3 albedo, vec3 specular) {
    return albedo * (1.0 - pbr_max3(specular));
}

// Per-channel form (Unity's same function without UNITY_CONSERVE_ENERGY_MONOCHROME):
// diffuse = albedo · (1 - specular). Tighter per channel but shifts the diffuse hue
// towards the complement of the specular colour.
vec3 pbr_diffuse_from_specular_per_channel(vec3 albedo, vec3 specular) {
    return albedo * (vec3(1.0) - specular);
}

#endif // PBR_MATERIAL_WORKFLOW_GLSL
