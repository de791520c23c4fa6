// pbrlab stand-in for URP's ShaderLibrary/AmbientOcclusion.hlsl: no screen-space ambient
// occlusion here (both factors 1), written for pbrlab from Unity's documentation of the names
// (URP's own file is under the Unity Companion License).
#ifndef PBRLAB_URP_AMBIENT_OCCLUSION_HLSL
#define PBRLAB_URP_AMBIENT_OCCLUSION_HLSL

struct AmbientOcclusionFactor {
    float indirectAmbientOcclusion;
    float directAmbientOcclusion;
};

float SampleAmbientOcclusion(float2 normalizedScreenSpaceUV) { return 1.0; }

AmbientOcclusionFactor GetScreenSpaceAmbientOcclusion(float2 normalizedScreenSpaceUV) {
    AmbientOcclusionFactor aoFactor;
    aoFactor.indirectAmbientOcclusion = 1.0;
    aoFactor.directAmbientOcclusion = 1.0;
    return aoFactor;
}

#endif
