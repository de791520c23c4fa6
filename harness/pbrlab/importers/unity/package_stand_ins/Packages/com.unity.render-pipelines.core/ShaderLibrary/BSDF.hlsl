// pbrlab stand-in for Core RP's ShaderLibrary/BSDF.hlsl: the BRDF terms URP shaders call by
// Core RP's names, each pbrlab's own term (glsl/pbr/brdf/, in the Unity prelude) under Unity's
// name and argument order, written for pbrlab from the sources below and Unity's documentation
// of the names (Core RP's own file is under the Unity Companion License and is not copied).
// Unity's vocabulary: `roughness` is alpha (perceptual roughness squared); `u` is the cosine
// Schlick's form takes (VdotH, or NdotV where a shader uses it so).
//
// Provides: F_Schlick(f0, f90, u), F_Schlick(f0, u) for a scalar and a float3 f0
//           (Schlick 1994: f0 + (f90 - f0)(1 - u)^5, f90 1 in the short forms);
//           D_GGX(NdotH, roughness) (Walter et al. 2007, eq. 33: a^2 / (pi ((a^2 - 1) NdotH^2 + 1)^2));
//           V_SmithJointGGX(NdotL, NdotV, roughness) (Heitz 2014, eq. 99, the height-correlated
//           Smith G2 / (4 NdotL NdotV));
//           DV_SmithJointGGX(NdotH, NdotL, NdotV, roughness) (their product);
//           Lambert() (1 / pi).
#ifndef PBRLAB_CORE_RP_BSDF_HLSL
#define PBRLAB_CORE_RP_BSDF_HLSL

#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"

float3 F_Schlick(float3 f0, float f90, float u) { return pbr_F_Schlick(f0, f90, u); }
float3 F_Schlick(float3 f0, float u) { return pbr_F_Schlick(f0, u); }
float F_Schlick(float f0, float f90, float u) { return pbr_F_Schlick(float3(f0, f0, f0), f90, u).x; }
float F_Schlick(float f0, float u) { return pbr_F_Schlick(f0, u); }
float D_GGX(float NdotH, float roughness) { return pbr_D_GGX(NdotH, roughness); }
float V_SmithJointGGX(float NdotL, float NdotV, float roughness) { return pbr_V_SmithGGXCorrelated(NdotL, NdotV, roughness); }
float DV_SmithJointGGX(float NdotH, float NdotL, float NdotV, float roughness) {
    return D_GGX(NdotH, roughness) * V_SmithJointGGX(NdotL, NdotV, roughness);
}
float Lambert() { return pbr_Fd_Lambert(); }

#endif
