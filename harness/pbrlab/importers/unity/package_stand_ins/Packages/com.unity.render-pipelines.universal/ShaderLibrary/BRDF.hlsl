// pbrlab stand-in for URP's ShaderLibrary/BRDF.hlsl: kDielectricSpec, BRDFData, InitializeBRDFData,
// DirectBRDFSpecular and the environment BRDF. As URP's, it brings Core RP's CommonMaterial.hlsl and
// SurfaceData.hlsl, not the lights,
// written for pbrlab from Unity's documentation of the names and URP 12's and 14's files read for
// their names (Unity's own files are under the Unity Companion License and are not copied).
#ifndef PBRLAB_URP_BRDF_HLSL
#define PBRLAB_URP_BRDF_HLSL
#define UNIVERSAL_BRDF_INCLUDED

#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
#include "Packages/com.unity.render-pipelines.core/ShaderLibrary/CommonMaterial.hlsl"
#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/SurfaceData.hlsl"

// URP's dielectric F0 and 1 - F0 (kDielectricSpec: 0.04 in linear space).
#define kDielectricSpec float4(0.04, 0.04, 0.04, 1.0 - 0.04)
// The name URP 7 to 10 spelled it with (kDieletricSpec), which shaders of that time use.
#define kDieletricSpec kDielectricSpec

struct BRDFData {
    float3 albedo;
    float3 diffuse;
    float3 specular;
    float reflectivity;
    float perceptualRoughness;
    float roughness;
    float roughness2;
    float grazingTerm;
    float normalizationTerm;    // roughness * 4 + 2
    float roughness2MinusOne;   // roughness^2 - 1
};

float OneMinusReflectivityMetallic(float metallic) { return kDielectricSpec.a - metallic * kDielectricSpec.a; }
float ReflectivitySpecular(float3 specular) { return max(max(specular.r, specular.g), specular.b); }

// URP's BRDF setup: diffuse and F0 from the workflow; roughness = (1 - smoothness)^2 floored
// at HALF_MIN_SQRT, its square at HALF_MIN; premultiplied alpha scales the diffuse.
void InitializeBRDFDataDirect(float3 albedo, float3 diffuse, float3 specular, float reflectivity,
                              float oneMinusReflectivity, float smoothness, inout float alpha, out BRDFData outBRDFData) {
    outBRDFData.albedo = albedo;
    outBRDFData.diffuse = diffuse;
    outBRDFData.specular = specular;
    outBRDFData.reflectivity = reflectivity;
    outBRDFData.perceptualRoughness = 1.0 - smoothness;
    outBRDFData.roughness = max(outBRDFData.perceptualRoughness * outBRDFData.perceptualRoughness, HALF_MIN_SQRT);
    outBRDFData.roughness2 = max(outBRDFData.roughness * outBRDFData.roughness, HALF_MIN);
    outBRDFData.grazingTerm = saturate(smoothness + reflectivity);
    outBRDFData.normalizationTerm = outBRDFData.roughness * 4.0 + 2.0;
    outBRDFData.roughness2MinusOne = outBRDFData.roughness2 - 1.0;
#ifdef _ALPHAPREMULTIPLY_ON
    outBRDFData.diffuse *= alpha;
    alpha = alpha * oneMinusReflectivity + reflectivity;
#endif
}

void InitializeBRDFData(float3 albedo, float metallic, float3 specular, float smoothness, inout float alpha,
                        out BRDFData outBRDFData) {
#ifdef _SPECULAR_SETUP
    float reflectivity = ReflectivitySpecular(specular);
    float oneMinusReflectivity = 1.0 - reflectivity;
    float3 brdfDiffuse = albedo * (float3(1.0, 1.0, 1.0) - specular);
    float3 brdfSpecular = specular;
#else
    float oneMinusReflectivity = OneMinusReflectivityMetallic(metallic);
    float reflectivity = 1.0 - oneMinusReflectivity;
    float3 brdfDiffuse = albedo * oneMinusReflectivity;
    float3 brdfSpecular = lerp(kDielectricSpec.rgb, albedo, metallic);
#endif
    InitializeBRDFDataDirect(albedo, brdfDiffuse, brdfSpecular, reflectivity, oneMinusReflectivity, smoothness,
                             alpha, outBRDFData);
}

void InitializeBRDFData(inout SurfaceData surfaceData, out BRDFData brdfData) {
    InitializeBRDFData(surfaceData.albedo, surfaceData.metallic, surfaceData.specular, surfaceData.smoothness,
                       surfaceData.alpha, brdfData);
}

// URP's direct specular: D * V * F folded into r^2 / ((d^2) max(0.1, LdotH^2) (4r + 2)), with
// d = NdotH^2 (r^2 - 1) + 1.00001 (Unity, "Optimizing PBR for mobile", Siggraph 2015).
float DirectBRDFSpecular(BRDFData brdfData, float3 normalWS, float3 lightDirectionWS, float3 viewDirectionWS) {
    float3 halfDir = SafeNormalize(lightDirectionWS + viewDirectionWS);
    float NoH = saturate(dot(normalWS, halfDir));
    float LoH = saturate(dot(lightDirectionWS, halfDir));
    float d = NoH * NoH * brdfData.roughness2MinusOne + 1.00001;
    float LoH2 = LoH * LoH;
    return brdfData.roughness2 / ((d * d) * max(0.1, LoH2) * brdfData.normalizationTerm);
}

// URP's environment BRDF: (1 / (roughness^2 + 1)) lerp(F0, grazing, (1 - NdotV)^4).
float3 EnvironmentBRDFSpecular(BRDFData brdfData, float fresnelTerm) {
    float surfaceReduction = 1.0 / (brdfData.roughness2 + 1.0);
    return surfaceReduction * lerp(brdfData.specular, float3(brdfData.grazingTerm, brdfData.grazingTerm, brdfData.grazingTerm), fresnelTerm);
}

float3 EnvironmentBRDF(BRDFData brdfData, float3 indirectDiffuse, float3 indirectSpecular, float fresnelTerm) {
    float3 c = indirectDiffuse * brdfData.diffuse;
    c += indirectSpecular * EnvironmentBRDFSpecular(brdfData, fresnelTerm);
    return c;
}

#endif
