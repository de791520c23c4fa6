// pbrlab stand-in for URP's ShaderLibrary/AmbientOcclusion.hlsl: the AmbientOcclusionFactor,
// CreateAmbientOcclusionFactor, GetScreenSpaceAmbientOcclusion and SampleAmbientOcclusion (no SSAO
// here: URP 14's values with _SCREEN_SPACE_OCCLUSION off), which pbrlab's stand-in Lighting.hlsl
// defines beside the InputData they take (written for pbrlab from the names and behaviour of URP
// 14; Unity's own file is under the Unity Companion License and is not copied).
#ifndef PBRLAB_URP_AMBIENT_OCCLUSION_HLSL
#define PBRLAB_URP_AMBIENT_OCCLUSION_HLSL

#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Lighting.hlsl"

#endif
