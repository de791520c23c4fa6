// pbrlab stand-in for URP's ShaderLibrary/NormalReconstruction.hlsl (the normal from the depth
// texture that URP's screen-space ambient occlusion and decals use), written for pbrlab from
// Unity's documentation of the camera depth texture; URP's own file is under the Unity Companion
// License and is not copied. Provided: its raw-depth read, GetRawDepth(uv), the camera depth
// texture's raw depth at a [0, 1] screen position (DeclareDepthTexture.hlsl's SampleSceneDepth).
// Its normal-reconstruction functions (ReconstructNormalTap3 and the like) are not provided: a
// shader calling one is refused naming it.
#ifndef PBRLAB_URP_NORMAL_RECONSTRUCTION_HLSL
#define PBRLAB_URP_NORMAL_RECONSTRUCTION_HLSL

#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/DeclareDepthTexture.hlsl"

float GetRawDepth(float2 uv) { return SampleSceneDepth(uv); }

#endif
