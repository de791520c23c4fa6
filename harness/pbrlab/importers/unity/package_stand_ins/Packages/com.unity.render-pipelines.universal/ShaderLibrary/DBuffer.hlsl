// pbrlab stand-in for URP's ShaderLibrary/DBuffer.hlsl: the decal buffer a lit pass blends into
// its surface with _DBUFFER_MRT1/2/3. No decals here: ApplyDecal and ApplyDecalToSurfaceData
// leave the surface as it is (written for pbrlab from Unity's documentation of URP's Decal
// Renderer Feature; URP's own file is under the Unity Companion License and is not copied).
#ifndef PBRLAB_URP_DBUFFER_HLSL
#define PBRLAB_URP_DBUFFER_HLSL

#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Lighting.hlsl"

void ApplyDecalToSurfaceData(float4 positionCS, inout SurfaceData surfaceData, inout InputData inputData) {}
void ApplyDecalToBaseColor(float4 positionCS, inout float3 baseColor) {}

#endif
