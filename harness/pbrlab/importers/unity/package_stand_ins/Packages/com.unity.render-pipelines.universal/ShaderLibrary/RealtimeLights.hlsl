// pbrlab stand-in for URP's ShaderLibrary/RealtimeLights.hlsl (URP 12 on): the Light struct, URP's
// DistanceAttenuation and AngleAttenuation, GetMainLight, GetAdditionalLight(s) and the per-object
// light list. As URP's, it brings AmbientOcclusion.hlsl, Input.hlsl and Shadows.hlsl, not the BRDF
// or the lighting models (Lighting.hlsl),
// written for pbrlab from Unity's documentation of the names and URP 12's and 14's files read for
// their names; Unity's own files are under the Unity Companion License and are not copied).
#ifndef PBRLAB_URP_REALTIMELIGHTS_HLSL
#define PBRLAB_URP_REALTIMELIGHTS_HLSL
#define UNIVERSAL_REALTIME_LIGHTS_INCLUDED

#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/AmbientOcclusion.hlsl"
#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Input.hlsl"
#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Shadows.hlsl"
#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/RenderingLayers.hlsl"

// The Light struct (URP's: unit direction towards the light, colour, distance and cone
// attenuation, shadow attenuation, the light's rendering layers).
struct Light {
    float3 direction;            // unit, from the shaded point to the light
    float3 color;
    float distanceAttenuation;   // the distance window (and a spot's cone), 1 for directional
    float shadowAttenuation;     // 1: no shadow maps here
    uint layerMask;
};

Light pbrlab_urp_no_light() {
    Light light;
    light.direction = float3(0.0, 0.0, 1.0);
    light.color = float3(0.0, 0.0, 0.0);
    light.distanceAttenuation = 0.0;
    light.shadowAttenuation = 1.0;
    light.layerMask = 0xFFFFFFFFu;
    return light;
}

// URP 12 RealtimeLights.hlsl, DistanceAttenuation: the inverse square times the smooth range
// window of Unity's lightmapper, (1 - (d^2 x)^2)^2 saturated, x = 1 / range^2 (the
// SHADER_HINT_NICE_QUALITY branch, URP's on desktop; _AdditionalLightsAttenuation.x above).
float DistanceAttenuation(float distanceSqr, float2 distanceAttenuation) {
    float lightAtten = rcp(distanceSqr);
    float factor = distanceSqr * distanceAttenuation.x;
    float smoothFactor = saturate(1.0 - factor * factor);
    smoothFactor = smoothFactor * smoothFactor;
    return lightAtten * smoothFactor;
}

// URP 12 RealtimeLights.hlsl, AngleAttenuation: the square of the linear ramp in the cosine
// between the spot's direction (towards the light) and the light direction, as one
// multiply-add, saturate(SdotL x + y) with x = 1 / (cos inner - cos outer), y = -cos outer x
// (_AdditionalLightsAttenuation.zw; 0 and 1 for a light without a cone: 1).
float AngleAttenuation(float3 spotDirection, float3 lightDirection, float2 spotAttenuation) {
    float SdotL = dot(spotDirection, lightDirection);
    float atten = saturate(SdotL * spotAttenuation.x + spotAttenuation.y);
    return atten * atten;
}

Light GetMainLight() {
    Light light = pbrlab_urp_no_light();
#if PBRLAB_DIRECTIONAL_COUNT > 0
    light.direction = -u_directional_direction[0];
    light.color = u_directional_radiance[0];
    light.distanceAttenuation = 1.0;
#endif
    return light;
}
Light GetMainLight(float4 shadowCoord) { return GetMainLight(); }
Light GetMainLight(float4 shadowCoord, float3 positionWS, float4 shadowMask) { return GetMainLight(); }
// A scalar shadow mask (GetMainLight(coord, positionWS, 1)): FXC splats a scalar to the half4
// parameter (HLSL's scalar-to-vector promotion); GLSL converts no scalar to a vector, so this
// overload takes it (the mask is unread here, as above).
Light GetMainLight(float4 shadowCoord, float3 positionWS, float shadowMask) { return GetMainLight(); }

// URP 12's count of the object's additional lights, min(_AdditionalLightsCount.x,
// unity_LightData.y): every additional light of the scene reaches every object here.
int GetAdditionalLightsCount() { return PBRLAB_URP_ADDITIONAL_LIGHT_COUNT; }

// URP 12 RealtimeLights.hlsl, GetAdditionalPerObjectLight (the uniform-array path, without
// structured buffers): the light's vector is position - positionWS w (a directional light's
// position is its direction, w 0), its squared length floored at HALF_MIN; the attenuation is
// DistanceAttenuation times AngleAttenuation of the light's _AdditionalLightsAttenuation and
// _AdditionalLightsSpotDir. No shadow maps here: shadowAttenuation 1.
Light GetAdditionalPerObjectLight(int perObjectLightIndex, float3 positionWS) {
    float4 lightPositionWS = pbrlab_urp_additional_light_position(perObjectLightIndex);
    float4 distanceAndSpotAttenuation = pbrlab_urp_additional_light_attenuation(perObjectLightIndex);
    float4 spotDirection = pbrlab_urp_additional_light_spot_direction(perObjectLightIndex);
    float3 lightVector = lightPositionWS.xyz - positionWS * lightPositionWS.w;
    float distanceSqr = max(dot(lightVector, lightVector), HALF_MIN);
    Light light = pbrlab_urp_no_light();
    light.direction = lightVector * rsqrt(distanceSqr);
    light.distanceAttenuation = DistanceAttenuation(distanceSqr, distanceAndSpotAttenuation.xy)
                              * AngleAttenuation(spotDirection.xyz, light.direction, distanceAndSpotAttenuation.zw);
    light.color = pbrlab_urp_additional_light_color(perObjectLightIndex).rgb;
    return light;
}
// An unsigned index (a loop counter of type uint passed on as it is): FXC converts it to the int
// parameter; GLSL converts no uint to int, so this overload takes it.
Light GetAdditionalPerObjectLight(uint perObjectLightIndex, float3 positionWS) {
    return GetAdditionalPerObjectLight(int(perObjectLightIndex), positionWS);
}

// URP's per-object light list (unity_LightIndices): every light reaches every object here, in
// the order of _AdditionalLightsPosition, so the i-th light's index is i.
int GetPerObjectLightIndex(uint index) { return int(index); }
int GetPerObjectLightIndex(int index) { return index; }
uint GetPerObjectLightIndexOffset() { return 0u; }

Light GetAdditionalLight(uint i, float3 positionWS) {
    return GetAdditionalPerObjectLight(GetPerObjectLightIndex(i), positionWS);
}
Light GetAdditionalLight(uint i, float3 positionWS, float4 shadowMask) { return GetAdditionalLight(i, positionWS); }
// The mesh's rendering layers, as RenderingLayers.hlsl's GetMeshRenderingLayer (every layer).
uint GetMeshRenderingLightLayer() { return 0xFFFFFFFFu; }

// URP 14's RealtimeLights.hlsl overloads that take the factor: the light as without it (the
// direct factor darkens a light only with SSAO on).
Light GetMainLight(InputData inputData, float4 shadowMask, AmbientOcclusionFactor aoFactor) {
    return GetMainLight(inputData.shadowCoord, inputData.positionWS, shadowMask);
}
Light GetAdditionalLight(uint i, InputData inputData, float4 shadowMask, AmbientOcclusionFactor aoFactor) {
    return GetAdditionalLight(i, inputData.positionWS, shadowMask);
}

// Clustered (Forward+) light lists: none here; the additional lights are one loop over
// GetAdditionalLightsCount(), lightIndex its counter (LIGHT_LOOP_BEGIN / LIGHT_LOOP_END).
#define USE_FORWARD_PLUS 0
#define USE_CLUSTERED_LIGHTING 0
#define LIGHT_LOOP_BEGIN(lightCount) for (uint lightIndex = 0u; lightIndex < uint(lightCount); lightIndex++) {
#define LIGHT_LOOP_END }

// The shadow mask a pixel's baked shadows come from: none here (no lightmaps), every channel 1.
float4 CalculateShadowMask(InputData inputData) { return float4(1.0, 1.0, 1.0, 1.0); }

#endif
