// pbrlab stand-in for the Universal Render Pipeline's ShaderLibrary/SurfaceInput.hlsl: the
// base, normal and emission maps URP's surface inputs declare, and the functions that sample
// them, written for pbrlab from Unity's documentation of the names (URP's own file is under
// the Unity Companion License and is not copied).
#ifndef PBRLAB_URP_SURFACE_INPUT_HLSL
#define PBRLAB_URP_SURFACE_INPUT_HLSL

#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/SurfaceData.hlsl"

TEXTURE2D(_BaseMap);
SAMPLER(sampler_BaseMap);
TEXTURE2D(_BumpMap);
SAMPLER(sampler_BumpMap);
TEXTURE2D(_EmissionMap);
SAMPLER(sampler_EmissionMap);

// The alpha of the base map times the colour's (unless smoothness comes from that channel),
// cut at `cutoff` when the material alpha-tests (_ALPHATEST_ON).
float Alpha(float albedoAlpha, float4 color, float cutoff) {
#if !defined(_SMOOTHNESS_TEXTURE_ALBEDO_CHANNEL_A) && !defined(_GLOSSINESS_FROM_BASE_ALPHA)
    float alpha = albedoAlpha * color.a;
#else
    float alpha = color.a;
#endif
#if defined(_ALPHATEST_ON)
    clip(alpha - cutoff);
#endif
    return alpha;
}

float4 SampleAlbedoAlpha(float2 uv, TEXTURE2D_PARAM(albedoAlphaMap, sampler_albedoAlphaMap)) {
    return SAMPLE_TEXTURE2D(albedoAlphaMap, sampler_albedoAlphaMap, uv);
}

// The tangent-space normal: the normal map's with _NORMALMAP (scaled), else straight up.
float3 SampleNormal(float2 uv, TEXTURE2D_PARAM(bumpMap, sampler_bumpMap), float scale) {
#ifdef _NORMALMAP
    return UnpackNormalScale(SAMPLE_TEXTURE2D(bumpMap, sampler_bumpMap, uv), scale);
#else
    return float3(0.0, 0.0, 1.0);
#endif
}

float3 SampleNormal(float2 uv, TEXTURE2D_PARAM(bumpMap, sampler_bumpMap)) {
    return SampleNormal(uv, TEXTURE2D_ARGS(bumpMap, sampler_bumpMap), 1.0);
}

float3 SampleEmission(float2 uv, float3 emissionColor, TEXTURE2D_PARAM(emissionMap, sampler_emissionMap)) {
#ifndef _EMISSION
    return float3(0.0, 0.0, 0.0);
#else
    return SAMPLE_TEXTURE2D(emissionMap, sampler_emissionMap, uv).rgb * emissionColor;
#endif
}

#endif
