// pbrlab stand-in for URP's Shaders/LitInput.hlsl: the Lit shader's material inputs (its
// UnityPerMaterial properties and maps) and InitializeStandardLitSurfaceData, which fills URP's
// SurfaceData from them, written for pbrlab from Unity's documentation of the Lit shader's
// properties and keywords (URP's own file is under the Unity Companion License and is not
// copied). Projects that copy URP's Lit.shader include it with LitForwardPass.hlsl.
//
// Keywords read: _SPECULAR_SETUP (specular colour from _SpecColor / _SpecGlossMap, else metallic
// from _Metallic / _MetallicGlossMap's red), _METALLICSPECGLOSSMAP (the map, its alpha times
// _Smoothness), _SMOOTHNESS_TEXTURE_ALBEDO_CHANNEL_A (smoothness from the base map's alpha),
// _OCCLUSIONMAP (green, toward white by 1 - _OcclusionStrength), _NORMALMAP, _EMISSION,
// _ALPHATEST_ON (SurfaceInput.hlsl). No parallax, detail maps or clear coat (0).
#ifndef PBRLAB_URP_LIT_INPUT_HLSL
#define PBRLAB_URP_LIT_INPUT_HLSL

#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/SurfaceInput.hlsl"

CBUFFER_START(UnityPerMaterial)
float4 _BaseMap_ST;
float4 _BaseColor;
float4 _SpecColor;
float4 _EmissionColor;
float _Cutoff;
float _Smoothness;
float _Metallic;
float _BumpScale;
float _OcclusionStrength;
float _Surface;
CBUFFER_END

TEXTURE2D(_OcclusionMap);
SAMPLER(sampler_OcclusionMap);
TEXTURE2D(_MetallicGlossMap);
SAMPLER(sampler_MetallicGlossMap);
TEXTURE2D(_SpecGlossMap);
SAMPLER(sampler_SpecGlossMap);

// Specular colour (or metallic in red) and smoothness in alpha.
float4 SampleMetallicSpecGloss(float2 uv, float albedoAlpha) {
    float4 specGloss;
#ifdef _METALLICSPECGLOSSMAP
#ifdef _SPECULAR_SETUP
    specGloss = SAMPLE_TEXTURE2D(_SpecGlossMap, sampler_SpecGlossMap, uv);
#else
    specGloss = SAMPLE_TEXTURE2D(_MetallicGlossMap, sampler_MetallicGlossMap, uv);
#endif
    specGloss.a *= _Smoothness;
#else
#ifdef _SPECULAR_SETUP
    specGloss.rgb = _SpecColor.rgb;
#else
    specGloss.rgb = float3(_Metallic, _Metallic, _Metallic);
#endif
    specGloss.a = _Smoothness;
#endif
#ifdef _SMOOTHNESS_TEXTURE_ALBEDO_CHANNEL_A
    specGloss.a = albedoAlpha * _Smoothness;
#endif
    return specGloss;
}

// The occlusion map's green, lerped from white by _OcclusionStrength (1 without the map).
float SampleOcclusion(float2 uv) {
#ifdef _OCCLUSIONMAP
    float occlusion = SAMPLE_TEXTURE2D(_OcclusionMap, sampler_OcclusionMap, uv).g;
    return 1.0 - _OcclusionStrength + occlusion * _OcclusionStrength;
#else
    return 1.0;
#endif
}

void InitializeStandardLitSurfaceData(float2 uv, out SurfaceData outSurfaceData) {
    float4 albedoAlpha = SampleAlbedoAlpha(uv, TEXTURE2D_ARGS(_BaseMap, sampler_BaseMap));
    outSurfaceData.alpha = Alpha(albedoAlpha.a, _BaseColor, _Cutoff);
    float4 specGloss = SampleMetallicSpecGloss(uv, albedoAlpha.a);
    outSurfaceData.albedo = albedoAlpha.rgb * _BaseColor.rgb;
#ifdef _SPECULAR_SETUP
    outSurfaceData.metallic = 1.0;
    outSurfaceData.specular = specGloss.rgb;
#else
    outSurfaceData.metallic = specGloss.r;
    outSurfaceData.specular = float3(0.0, 0.0, 0.0);
#endif
    outSurfaceData.smoothness = specGloss.a;
    outSurfaceData.normalTS = SampleNormal(uv, TEXTURE2D_ARGS(_BumpMap, sampler_BumpMap), _BumpScale);
    outSurfaceData.occlusion = SampleOcclusion(uv);
    outSurfaceData.emission = SampleEmission(uv, _EmissionColor.rgb, TEXTURE2D_ARGS(_EmissionMap, sampler_EmissionMap));
    outSurfaceData.clearCoatMask = 0.0;
    outSurfaceData.clearCoatSmoothness = 0.0;
}

#endif
