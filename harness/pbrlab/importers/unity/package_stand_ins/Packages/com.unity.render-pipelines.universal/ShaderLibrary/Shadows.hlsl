// pbrlab stand-in for URP's ShaderLibrary/Shadows.hlsl: the shadow maps' declarations and the
// shadow functions, without shadow maps (every light unshadowed: 1). As URP's, it brings Core.hlsl
// only, not the lights (RealtimeLights.hlsl), so a program that includes it may define its own Light,
// written for pbrlab from Unity's documentation of the names and URP 12's and 14's files read for
// their names (Unity's own files are under the Unity Companion License and are not copied).
#ifndef PBRLAB_URP_SHADOWS_HLSL
#define PBRLAB_URP_SHADOWS_HLSL
#define UNIVERSAL_SHADOWS_INCLUDED

#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"

// URP 14's Shadows.hlsl (which its Lighting.hlsl brings) asks every lit pass for the world
// position varying: a pass copied from URP's Lit reads input.positionWS under this name.
#ifndef REQUIRES_WORLD_SPACE_POS_INTERPOLATOR
#define REQUIRES_WORLD_SPACE_POS_INTERPOLATOR 1
#endif

// Shadows (Shadows.hlsl's names): no shadow maps here, so every light is unshadowed (1).
float MainLightRealtimeShadow(float4 shadowCoord) { return 1.0; }
// The main light's shadow map and the parameters URP's SampleShadowmap reads (URP 12's
// ShadowSamplingData: the soft-shadow tap offsets and the map's size; _MainLightShadowParams:
// strength, soft flag, fade scale and bias). No shadow map here: every texel of it would read
// lit (1), so SampleShadowmap's attenuation, lerp(1, map, strength), is 1 for any strength (the
// main light's is 0, as URP's with shadows off).
// The maps are declared as URP's Shadows.hlsl declares them, depth textures with comparison
// samplers (TEXTURE2D_SHADOW, SAMPLER_CMP), so a program's own SAMPLE_TEXTURE2D_SHADOW of them
// compiles; pbrlab binds each to URP's empty shadow map (importers/unity/shadow_maps.py: one
// texel at the far plane's depth, which every comparison passes: 1, lit), what URP binds while
// no light casts shadows.
struct ShadowSamplingData {
    float4 shadowOffset0;
    float4 shadowOffset1;
    float4 shadowOffset2;
    float4 shadowOffset3;
    float4 shadowmapSize;
};
TEXTURE2D_SHADOW(_MainLightShadowmapTexture);
SAMPLER_CMP(sampler_MainLightShadowmapTexture);
TEXTURE2D_SHADOW(_AdditionalLightsShadowmapTexture);
SAMPLER_CMP(sampler_AdditionalLightsShadowmapTexture);
ShadowSamplingData GetMainLightShadowSamplingData() {
    ShadowSamplingData data;
    data.shadowOffset0 = float4(0.0, 0.0, 0.0, 0.0);
    data.shadowOffset1 = float4(0.0, 0.0, 0.0, 0.0);
    data.shadowOffset2 = float4(0.0, 0.0, 0.0, 0.0);
    data.shadowOffset3 = float4(0.0, 0.0, 0.0, 0.0);
    data.shadowmapSize = float4(1.0, 1.0, 1.0, 1.0);
    return data;
}
float4 GetMainLightShadowParams() { return float4(0.0, 0.0, 0.0, 0.0); }
// URP's test for a shadow coordinate outside the shadow map's depth range (beyond the shadow
// distance: lit), z at or before the near end or at or past the far end of [0, 1].
// SampleShadowmap reads the map it is given as URP's does: the coordinate divided by w for a
// perspective (spot) projection, one hardware comparison (URP's soft-shadow taps read the same
// map around it: the empty map passes them all alike), the result moved towards 1 by 1 - strength
// (shadowParams.x), and 1 beyond the map's depth range (BEYOND_SHADOW_FAR). It samples the map so
// that spirv-cross types the texture a caller passes on as a comparison sampler everywhere.
#define BEYOND_SHADOW_FAR(shadowCoord) ((shadowCoord).z <= 0.0 || (shadowCoord).z >= 1.0)
float SampleShadowmap(TEXTURE2D_SHADOW_PARAM(ShadowMap, sampler_ShadowMap), float4 shadowCoord, ShadowSamplingData samplingData,
                      float4 shadowParams, bool isPerspectiveProjection) {
    if (isPerspectiveProjection)
        shadowCoord.xyz /= shadowCoord.w;
    float attenuation = SAMPLE_TEXTURE2D_SHADOW(ShadowMap, sampler_ShadowMap, shadowCoord.xyz);
    attenuation = 1.0 + (attenuation - 1.0) * shadowParams.x;
    return BEYOND_SHADOW_FAR(shadowCoord) ? 1.0 : attenuation;
}
float MainLightShadow(float4 shadowCoord, float3 positionWS, float4 shadowMask, float4 occlusionProbeChannels) { return 1.0; }
// The main light's channel of the baked shadow mask (URP's _MainLightOcclusionProbes, a one-hot
// mask URP sets for a light with baked occlusion): none here, a realtime light's (0, 0, 0, 0).
#define _MainLightOcclusionProbes float4(0.0, 0.0, 0.0, 0.0)
float AdditionalLightRealtimeShadow(int lightIndex, float3 positionWS) { return 1.0; }
float AdditionalLightRealtimeShadow(int lightIndex, float3 positionWS, float3 lightDirection) { return 1.0; }
float AdditionalLightShadow(int lightIndex, float3 positionWS, float3 lightDirection, float4 shadowMask,
                            float4 occlusionProbeChannels) { return 1.0; }
// URP 10's form, before the light's direction was a parameter.
float AdditionalLightShadow(int lightIndex, float3 positionWS, float4 shadowMask, float4 occlusionProbeChannels) {
    return 1.0;
}
float4 GetShadowCoord(VertexPositionInputs vertexInput) { return float4(0.0, 0.0, 0.0, 0.0); }
float3 ApplyShadowBias(float3 positionWS, float3 normalWS, float3 lightDirection) { return positionWS; }

#endif
