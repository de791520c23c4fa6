// pbrlab stand-in for URP's ShaderLibrary/AmbientOcclusion.hlsl: AmbientOcclusionFactor,
// GetScreenSpaceAmbientOcclusion, SampleAmbientOcclusion and CreateAmbientOcclusionFactor (no SSAO
// here: URP 14's values with _SCREEN_SPACE_OCCLUSION off),
// written for pbrlab from Unity's documentation of the names and URP 12's and 14's files read for
// their names (Unity's own files are under the Unity Companion License and are not copied).
#ifndef PBRLAB_URP_AMBIENT_OCCLUSION_HLSL
#define PBRLAB_URP_AMBIENT_OCCLUSION_HLSL
#define AMBIENT_OCCLUSION_INCLUDED

#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/SurfaceData.hlsl"

// URP 14's names (its Lighting.hlsl and RealtimeLights.hlsl bring this file): the factor a pixel's
// lights and baked light are darkened by. Screen-space ambient occlusion is off here (no
// _SCREEN_SPACE_OCCLUSION keyword, no SSAO texture), so URP 14's screen-space factor is 1 for
// both the direct and the indirect light, and CreateAmbientOcclusionFactor's indirect factor is
// min(1, the material's occlusion).
struct AmbientOcclusionFactor {
    float indirectAmbientOcclusion;   // multiplies the baked (ambient) light
    float directAmbientOcclusion;     // multiplies the realtime lights (with SSAO on only)
};

// The SSAO texture's value at a screen position: no SSAO pass here, so unoccluded (1).
float SampleAmbientOcclusion(float2 normalizedScreenSpaceUV) { return 1.0; }

// SSAO's factors at a screen position; without _SCREEN_SPACE_OCCLUSION both are 1 in URP 14.
AmbientOcclusionFactor GetScreenSpaceAmbientOcclusion(float2 normalizedScreenSpaceUV) {
    AmbientOcclusionFactor aoFactor;
    aoFactor.indirectAmbientOcclusion = 1.0;
    aoFactor.directAmbientOcclusion = 1.0;
    return aoFactor;
}

// The screen-space factors with the material's occlusion folded into the indirect one (the
// smaller of the two wins, as in URP 14).
AmbientOcclusionFactor CreateAmbientOcclusionFactor(float2 normalizedScreenSpaceUV, float occlusion) {
    AmbientOcclusionFactor aoFactor = GetScreenSpaceAmbientOcclusion(normalizedScreenSpaceUV);
    aoFactor.indirectAmbientOcclusion = min(aoFactor.indirectAmbientOcclusion, occlusion);
    return aoFactor;
}

AmbientOcclusionFactor CreateAmbientOcclusionFactor(InputData inputData, SurfaceData surfaceData) {
    return CreateAmbientOcclusionFactor(inputData.normalizedScreenSpaceUV, surfaceData.occlusion);
}

#endif
