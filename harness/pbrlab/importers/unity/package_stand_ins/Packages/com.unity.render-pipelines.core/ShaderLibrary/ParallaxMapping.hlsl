// pbrlab stand-in for Core RP's ShaderLibrary/ParallaxMapping.hlsl: URP Lit's one-step parallax
// mapping (written for pbrlab from Unity's documentation of the Lit shader's Height Map and of
// these functions; Core RP's own file is under the Unity Companion License and is not copied).
// The offset is the built-in ParallaxOffset's (pbrlab's Unity layer, unity_cg: Kaneko et al.
// 2001 with Unity's 0.42 bias on z; float64 reference maths/reference/unity_cg.py
// parallax_offset); URP's Lit reads the height from the height map's green channel.
#ifndef PBRLAB_CORE_RP_PARALLAX_MAPPING_HLSL
#define PBRLAB_CORE_RP_PARALLAX_MAPPING_HLSL

#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"

// The view direction in the tangent frame of the interpolated (unnormalized) normal and
// tangent, both scaled by 1 / |normal| (the surface-gradient framework's convention, which
// keeps the MikkTSpace frame); the bitangent cross(n, t) with the sign of tangentWS.w (already
// times GetOddNegativeScale(), as URP's vertex stage gives it).
float3 GetViewDirectionTangentSpace(float4 tangentWS, float3 normalWS, float3 viewDirWS) {
    float renorm = 1.0 / length(normalWS);
    float3 bitangent = (tangentWS.w > 0.0 ? 1.0 : -1.0) * cross(normalWS, tangentWS.xyz);
    float3x3 toTangent = float3x3(renorm * tangentWS.xyz, renorm * bitangent, renorm * normalWS);
    return mul(toTangent, viewDirWS);
}

// (h - 1/2) amplitude along the unit view direction's xy / (z + 0.42)
float2 ParallaxOffset1Step(float height, float amplitude, float3 viewDirTS) {
    return ParallaxOffset(height, amplitude, viewDirTS);
}

// The UV offset from the height map's green channel at uv (scale: the Lit shader's Height
// Map strength); ParallaxMappingChannel reads another channel
float2 ParallaxMapping(TEXTURE2D_PARAM(heightMap, sampler_heightMap), float3 viewDirTS, float scale, float2 uv) {
    return ParallaxOffset1Step(SAMPLE_TEXTURE2D(heightMap, sampler_heightMap, uv).g, scale, viewDirTS);
}
float2 ParallaxMappingChannel(TEXTURE2D_PARAM(heightMap, sampler_heightMap), float3 viewDirTS, float scale, float2 uv,
                              int channel) {
    return ParallaxOffset1Step(SAMPLE_TEXTURE2D(heightMap, sampler_heightMap, uv)[channel], scale, viewDirTS);
}

#endif
