// pbrlab stand-in for the Universal Render Pipeline's ShaderLibrary/Lighting.hlsl: its lighting
// models (URP's physically based UniversalFragmentPBR, SimpleLit's Blinn-Phong, LightingData),
// written for pbrlab from Unity's documentation of the names and the model's formulas (URP's own
// files are under the Unity Companion License and are not copied). As URP 12's and 14's, it brings
// BRDF.hlsl (BRDFData), GlobalIllumination.hlsl (the ambient and reflection light),
// RealtimeLights.hlsl (the Light struct and the lights) and AmbientOcclusion.hlsl, each its own
// stand-in, so a program that includes only one of those gets only its names. The float64
// transcription of the same model is pbrlab.maths.reference.urp_brdf; tests/importers/urp/ checks
// a render against it.
//
// Lights: the scene's (RealtimeLights.hlsl). The main light is its first directional light (none:
// black); the additional lights are its other directional lights, then its point lights, then
// its spot lights, attenuated by URP's DistanceAttenuation and AngleAttenuation. No shadow maps:
// shadowAttenuation is 1. Ambient light: the scene environment's SH9 (SampleSH); reflections: its
// prefiltered radiance at URP's mip for the perceptual roughness (black without an environment).
#ifndef PBRLAB_URP_LIGHTING_HLSL
#define PBRLAB_URP_LIGHTING_HLSL

#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/RenderingLayers.hlsl"
#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/SurfaceData.hlsl"
#include "Packages/com.unity.render-pipelines.core/ShaderLibrary/CommonMaterial.hlsl"
#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/BRDF.hlsl"
#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/GlobalIllumination.hlsl"
#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/RealtimeLights.hlsl"
#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/AmbientOcclusion.hlsl"
// URP 12+'s Lighting.hlsl includes Debug/Debugging3D.hlsl, which includes DebuggingCommon.hlsl
#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Debug/DebuggingCommon.hlsl"

#define UNIVERSAL_LIGHTING_INCLUDED


float3 LightingPhysicallyBased(BRDFData brdfData, float3 lightColor, float3 lightDirectionWS, float lightAttenuation,
                               float3 normalWS, float3 viewDirectionWS) {
    float NdotL = saturate(dot(normalWS, lightDirectionWS));
    float3 radiance = lightColor * (lightAttenuation * NdotL);
    float3 brdf = brdfData.diffuse;
    brdf += brdfData.specular * DirectBRDFSpecular(brdfData, normalWS, lightDirectionWS, viewDirectionWS);
    return brdf * radiance;
}

float3 LightingPhysicallyBased(BRDFData brdfData, Light light, float3 normalWS, float3 viewDirectionWS) {
    return LightingPhysicallyBased(brdfData, light.color, light.direction,
                                   light.distanceAttenuation * light.shadowAttenuation, normalWS, viewDirectionWS);
}

float3 LightingLambert(float3 lightColor, float3 lightDir, float3 normal) {
    return lightColor * saturate(dot(normal, lightDir));
}

// Per-vertex additional lights (_ADDITIONAL_LIGHTS_VERTEX): their Lambert sum, else black.
float3 VertexLighting(float3 positionWS, float3 normalWS) {
    float3 vertexLightColor = float3(0.0, 0.0, 0.0);
#ifdef _ADDITIONAL_LIGHTS_VERTEX
    int lightCount = GetAdditionalLightsCount();
    for (int lightIndex = 0; lightIndex < lightCount; ++lightIndex) {
        Light light = GetAdditionalLight(uint(lightIndex), positionWS);
        vertexLightColor += LightingLambert(light.color * light.distanceAttenuation, light.direction, normalWS);
    }
#endif
    return vertexLightColor;
}

// Blinn-Phong's highlight: colour * specular * NdotH^smoothness (smoothness here the exponent).
float3 LightingSpecular(float3 lightColor, float3 lightDir, float3 normal, float3 viewDir, float4 specular, float smoothness) {
    float3 halfVec = SafeNormalize(lightDir + viewDir);
    float NdotH = saturate(dot(normal, halfVec));
    return lightColor * (specular.rgb * pow(NdotH, smoothness));
}

// SimpleLit's light: Lambert's diffuse times the albedo, plus the highlight where the material
// has one (_SPECGLOSSMAP or _SPECULAR_COLOR), its exponent exp2(10 smoothness + 1).
float3 CalculateBlinnPhong(Light light, InputData inputData, SurfaceData surfaceData) {
    float3 attenuatedLightColor = light.color * (light.distanceAttenuation * light.shadowAttenuation);
    float3 lightDiffuseColor = LightingLambert(attenuatedLightColor, light.direction, inputData.normalWS);
    float3 lightSpecularColor = float3(0.0, 0.0, 0.0);
#if defined(_SPECGLOSSMAP) || defined(_SPECULAR_COLOR)
    float exponent = exp2(10.0 * surfaceData.smoothness + 1.0);
    lightSpecularColor += LightingSpecular(attenuatedLightColor, light.direction, inputData.normalWS,
                                           inputData.viewDirectionWS, float4(surfaceData.specular, 1.0), exponent);
#endif
#ifdef _ALPHAPREMULTIPLY_ON
    return lightDiffuseColor * surfaceData.albedo * surfaceData.alpha + lightSpecularColor;
#else
    return lightDiffuseColor * surfaceData.albedo + lightSpecularColor;
#endif
}

// SimpleLit's pixel: the ambient light times the albedo, every light's Blinn-Phong, emission.
float4 UniversalFragmentBlinnPhong(InputData inputData, SurfaceData surfaceData) {
    float3 color = inputData.bakedGI * surfaceData.albedo;
    color += CalculateBlinnPhong(GetMainLight(inputData.shadowCoord, inputData.positionWS, inputData.shadowMask),
                                 inputData, surfaceData);
#ifdef _ADDITIONAL_LIGHTS
    int lightCount = GetAdditionalLightsCount();
    for (int lightIndex = 0; lightIndex < lightCount; ++lightIndex) {
        color += CalculateBlinnPhong(GetAdditionalLight(uint(lightIndex), inputData.positionWS, inputData.shadowMask),
                                     inputData, surfaceData);
    }
#endif
    color += surfaceData.emission;
    return float4(color, surfaceData.alpha);
}

float4 UniversalFragmentBlinnPhong(InputData inputData, float3 diffuse, float4 specularGloss, float smoothness,
                                   float3 emission, float alpha, float3 normalTS) {
    SurfaceData s;
    s.albedo = diffuse;
    s.specular = specularGloss.rgb;
    s.metallic = 0.0;
    s.smoothness = smoothness;
    s.normalTS = normalTS;
    s.emission = emission;
    s.occlusion = 1.0;
    s.alpha = alpha;
    s.clearCoatMask = 0.0;
    s.clearCoatSmoothness = 1.0;
    return UniversalFragmentBlinnPhong(inputData, s);
}

float4 UniversalFragmentBlinnPhong(InputData inputData, float3 diffuse, float4 specularGloss, float smoothness,
                                   float3 emission, float alpha) {
    return UniversalFragmentBlinnPhong(inputData, diffuse, specularGloss, smoothness, emission, alpha,
                                       float3(0.0, 0.0, 1.0));
}


// URP 12's LightingData and the functions that take it; left out where the shader declares a
// struct LightingData of its own (written for an earlier URP: importers/unity/user_definitions.py).
#ifndef PBRLAB_USER_DEFINES_LightingData
// A pixel's light by kind, summed by CalculateLightingColor: the global illumination, the main
// light, the additional lights and the vertex lights, times the albedo, plus the emission.
struct LightingData {
    float3 giColor;
    float3 mainLightColor;
    float3 additionalLightsColor;
    float3 vertexLightingColor;
    float3 emissionColor;
};

LightingData CreateLightingData(InputData inputData, SurfaceData surfaceData) {
    LightingData lightingData;
    lightingData.giColor = inputData.bakedGI;
    lightingData.mainLightColor = float3(0.0, 0.0, 0.0);
    lightingData.additionalLightsColor = float3(0.0, 0.0, 0.0);
    lightingData.vertexLightingColor = float3(0.0, 0.0, 0.0);
    lightingData.emissionColor = surfaceData.emission;
    return lightingData;
}

float3 CalculateLightingColor(LightingData lightingData, float3 albedo) {
    float3 light = lightingData.giColor + lightingData.mainLightColor + lightingData.additionalLightsColor
                 + lightingData.vertexLightingColor;
    return light * albedo + lightingData.emissionColor;
}

float4 CalculateFinalColor(LightingData lightingData, float alpha) {
    return float4(CalculateLightingColor(lightingData, float3(1.0, 1.0, 1.0)), alpha);
}

float4 CalculateFinalColor(LightingData lightingData, float3 albedo, float alpha, float fogCoord) {
    return float4(CalculateLightingColor(lightingData, albedo), alpha);  // no fog here
}
#endif

// The lit pixel: ambient and reflections, the main light, every additional light, emission.
float4 UniversalFragmentPBR(InputData inputData, SurfaceData surfaceData) {
    BRDFData brdfData;
    InitializeBRDFData(surfaceData.albedo, surfaceData.metallic, surfaceData.specular, surfaceData.smoothness,
                       surfaceData.alpha, brdfData);
    float3 color = GlobalIllumination(brdfData, inputData.bakedGI, surfaceData.occlusion, inputData.positionWS,
                                      inputData.normalWS, inputData.viewDirectionWS);
    Light mainLight = GetMainLight(inputData.shadowCoord, inputData.positionWS, inputData.shadowMask);
    color += LightingPhysicallyBased(brdfData, mainLight, inputData.normalWS, inputData.viewDirectionWS);
#ifdef _ADDITIONAL_LIGHTS
    int lightCount = GetAdditionalLightsCount();
    for (int lightIndex = 0; lightIndex < lightCount; ++lightIndex) {
        Light light = GetAdditionalLight(uint(lightIndex), inputData.positionWS, inputData.shadowMask);
        color += LightingPhysicallyBased(brdfData, light, inputData.normalWS, inputData.viewDirectionWS);
    }
#endif
    color += surfaceData.emission;
    return float4(color, surfaceData.alpha);
}

float4 UniversalFragmentPBR(InputData inputData, float3 albedo, float metallic, float3 specular, float smoothness,
                            float occlusion, float3 emission, float alpha) {
    SurfaceData s;
    s.albedo = albedo;
    s.specular = specular;
    s.metallic = metallic;
    s.smoothness = smoothness;
    s.normalTS = float3(0.0, 0.0, 1.0);
    s.emission = emission;
    s.occlusion = occlusion;
    s.alpha = alpha;
    s.clearCoatMask = 0.0;
    s.clearCoatSmoothness = 1.0;
    return UniversalFragmentPBR(inputData, s);
}

// The Lightweight Render Pipeline's name (URP before 7.0) for UniversalFragmentPBR.
float4 LightweightFragmentPBR(InputData inputData, float3 albedo, float metallic, float3 specular, float smoothness,
                              float occlusion, float3 emission, float alpha) {
    return UniversalFragmentPBR(inputData, albedo, metallic, specular, smoothness, occlusion, emission, alpha);
}

// URP's Lighting.hlsl includes GlobalIllumination.hlsl, which includes Core RP's
// ImageBasedLighting.hlsl (URP 14.0.9): UNITY_SPECCUBE_LOD_STEPS and the mip <-> roughness
// converters reach a program that includes Lighting.hlsl (its include of this file is skipped).
#include "Packages/com.unity.render-pipelines.core/ShaderLibrary/ImageBasedLighting.hlsl"

#endif

