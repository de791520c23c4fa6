// pbrlab stand-in for Core RP's ShaderLibrary/Tessellation.hlsl: the tessellation factors and
// Phong tessellation URP tessellation shaders call (written for pbrlab from the papers named
// below and Unity's documentation of the names; Core RP's own file is under the Unity
// Companion License and is not copied).
#ifndef PBRLAB_CORE_RP_TESSELLATION_HLSL
#define PBRLAB_CORE_RP_TESSELLATION_HLSL

#include "Packages/com.unity.render-pipelines.core/ShaderLibrary/GeometricTools.hlsl"

// A domain stage's output member from the patch's three inputs at the barycentric coordinates
#define TESSELLATION_INTERPOLATE_BARY(name, bary) output.name = input0.name * bary.x + input1.name * bary.y + input2.name * bary.z

// Phong tessellation (Boubekeur and Alexa 2008): the flat point projected on each corner's
// tangent plane, the projections blended barycentrically, then shape (0: flat, 1: full)
float3 PhongTessellation(float3 positionWS, float3 p0, float3 p1, float3 p2, float3 n0, float3 n1, float3 n2,
                         float3 baryCoords, float shape) {
    float3 phong = baryCoords.x * ProjectPointOnPlane(positionWS, p0, n0)
                 + baryCoords.y * ProjectPointOnPlane(positionWS, p1, n1)
                 + baryCoords.z * ProjectPointOnPlane(positionWS, p2, n2);
    return lerp(positionWS, phong, shape);
}

// Each edge's factor in [0, 1] from its length on screen in pixels over triangleSize (edge x is
// the one facing p0: p1 p2; y: p0 p2; z: p0 p1)
float3 GetScreenSpaceTessFactor(float3 p0, float3 p1, float3 p2, float4x4 viewProjectionMatrix, float4 screenSize,
                                float triangleSize) {
    float2 s0 = ComputeNormalizedDeviceCoordinates(p0, viewProjectionMatrix) * screenSize.xy;
    float2 s1 = ComputeNormalizedDeviceCoordinates(p1, viewProjectionMatrix) * screenSize.xy;
    float2 s2 = ComputeNormalizedDeviceCoordinates(p2, viewProjectionMatrix) * screenSize.xy;
    return saturate(float3(distance(s1, s2), distance(s0, s2), distance(s0, s1)) / triangleSize);
}

// Each edge's factor from its midpoint's distance to the camera: 1 nearer than tessMinDist,
// 0 beyond tessMaxDist, linear between (the same edge order)
float3 GetDistanceBasedTessFactor(float3 p0, float3 p1, float3 p2, float3 cameraPosWS, float tessMinDist,
                                  float tessMaxDist) {
    float3 d = float3(distance(0.5 * (p1 + p2), cameraPosWS), distance(0.5 * (p0 + p2), cameraPosWS),
                      distance(0.5 * (p0 + p1), cameraPosWS));
    return saturate(1.0 - (d - tessMinDist) / (tessMaxDist - tessMinDist));
}

// A triangle patch's factors: the three edges' and the inside one, their mean
float4 CalcTriTessFactorsFromEdgeTessFactors(float3 triVertexFactors) {
    return float4(triVertexFactors, (triVertexFactors.x + triVertexFactors.y + triVertexFactors.z) / 3.0);
}

#endif
