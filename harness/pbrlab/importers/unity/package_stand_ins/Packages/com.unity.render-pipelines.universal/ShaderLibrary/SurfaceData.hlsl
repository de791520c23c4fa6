// pbrlab stand-in for URP's ShaderLibrary/SurfaceData.hlsl: the SurfaceData struct (a surface's
// albedo, specular, metallic, smoothness, tangent-space normal, emission, occlusion, alpha and
// clear coat), which URP's SurfaceInput.hlsl and Lighting.hlsl include, written for pbrlab from
// Unity's documentation of the names (Unity's own file is under the Unity Companion License and
// is not copied).
// Guarded by Unity's own name for the file (URP's SurfaceData.hlsl: UNIVERSAL_SURFACE_DATA_INCLUDED):
// a project's own SurfaceData.hlsl under that guard, which pbrlab compiles as written (projects
// change its fields), and this stand-in are one file to the preprocessor, as the project's copy
// and URP's are in Unity: whichever comes first defines the struct, once.
#ifndef UNIVERSAL_SURFACE_DATA_INCLUDED
#define UNIVERSAL_SURFACE_DATA_INCLUDED
#define PBRLAB_URP_SURFACEDATA_HLSL

#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"

struct SurfaceData {
    float3 albedo;
    float3 specular;
    float metallic;
    float smoothness;
    float3 normalTS;
    float3 emission;
    float occlusion;
    float alpha;
    float clearCoatMask;
    float clearCoatSmoothness;
};

#endif
