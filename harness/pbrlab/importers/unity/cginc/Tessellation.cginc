// pbrlab stand-in for Unity's Tessellation.cginc (tessellation factors for surface shaders
// with tessellate:).
//
// Provides: UnityCalcDistanceTessFactor, UnityCalcTriEdgeTessFactors, UnityCalcEdgeTessFactor,
//   UnityDistanceFromPlane, UnityWorldViewFrustumCull, UnityDistanceBasedTess,
//   UnityEdgeLengthBasedTess, UnityEdgeLengthBasedTessCull.
// Unity's file: the same functions (Tessellation.cginc, Unity 2019.4 built-in shaders), read
//   for their behaviour and written here anew. Only the functions: whether a tessellate:
//   shader is tessellated is the front end's business (harness/pbrlab/importers/unity/), not this file's.
// Differences: Unity's frustum test reads the camera's world-space planes
//   (unity_CameraWorldClipPlanes, set by the engine); here the four side planes are taken from
//   unity_MatrixVP (Gribb & Hartmann 2001, "Fast Extraction of Viewing Frustum Planes from the
//   World-View-Projection Matrix"), normalised to world units as Unity's are, in the order
//   left, right, bottom, top.
// Cg text in the plain subset harness/pbrlab/importers/unity/port.py ports to GLSL.
#ifndef PBRLAB_TESSELLATION_CGINC
#define PBRLAB_TESSELLATION_CGINC

// 1 at minDist from the camera or nearer, falling linearly to 0.01 at maxDist, times tess
// (Tessellation.cginc).
float UnityCalcDistanceTessFactor(float4 vertex, float minDist, float maxDist, float tess)
{
    float3 worldPos = mul(unity_ObjectToWorld, vertex).xyz;
    float dist = distance(worldPos, _WorldSpaceCameraPos);
    return clamp(1.0 - (dist - minDist) / (maxDist - minDist), 0.01, 1.0) * tess;
}

// Per-vertex factors to a triangle's: each edge the mean of its two vertices (edge i is
// opposite vertex i), inside the mean of all three (Tessellation.cginc).
float4 UnityCalcTriEdgeTessFactors(float3 triVertexFactors)
{
    float3 f = triVertexFactors;
    return float4(0.5 * (f.y + f.z), 0.5 * (f.x + f.z), 0.5 * (f.x + f.y), (f.x + f.y + f.z) / 3.0);
}

// An edge's on-screen length in pixels (its length over its distance, times the screen
// height) over the wanted length edgeLen, at least 1 (Tessellation.cginc).
float UnityCalcEdgeTessFactor(float3 wpos0, float3 wpos1, float edgeLen)
{
    float dist = distance(0.5 * (wpos0 + wpos1), _WorldSpaceCameraPos);
    float len = distance(wpos0, wpos1);
    return max(len * _ScreenParams.y / (edgeLen * dist), 1.0);
}

float UnityDistanceFromPlane(float3 pos, float4 plane)
{
    return dot(float4(pos, 1.0), plane);
}

// The side planes of the view frustum (xyz inward normal, w offset; world units): the affine
// clip-space functions w + x, w - x, w + y, w - y evaluated at the origin and the three axes give
// each plane's coefficients without indexing the matrix (rows and columns differ by language).
float4 PbrlabFrustumSides(float4 clip)
{
    return float4(clip.w + clip.x, clip.w - clip.x, clip.w + clip.y, clip.w - clip.y);
}

float4 PbrlabFrustumPlane(float4 at0, float4 atX, float4 atY, float4 atZ, int side)
{
    float4 s0 = PbrlabFrustumSides(at0);
    float4 sx = PbrlabFrustumSides(atX) - s0;
    float4 sy = PbrlabFrustumSides(atY) - s0;
    float4 sz = PbrlabFrustumSides(atZ) - s0;
    float4 plane = float4(sx.x, sy.x, sz.x, s0.x);
    if (side == 1)
        plane = float4(sx.y, sy.y, sz.y, s0.y);
    if (side == 2)
        plane = float4(sx.z, sy.z, sz.z, s0.z);
    if (side == 3)
        plane = float4(sx.w, sy.w, sz.w, s0.w);
    return plane / length(plane.xyz);
}

// True when the triangle lies entirely outside one side plane by more than cullEps
// (Tessellation.cginc, UnityWorldViewFrustumCull).
bool UnityWorldViewFrustumCull(float3 wpos0, float3 wpos1, float3 wpos2, float cullEps)
{
    float4 at0 = mul(unity_MatrixVP, float4(0.0, 0.0, 0.0, 1.0));
    float4 atX = mul(unity_MatrixVP, float4(1.0, 0.0, 0.0, 1.0));
    float4 atY = mul(unity_MatrixVP, float4(0.0, 1.0, 0.0, 1.0));
    float4 atZ = mul(unity_MatrixVP, float4(0.0, 0.0, 1.0, 1.0));
    bool culled = false;
    for (int side = 0; side < 4; side++)
    {
        float4 plane = PbrlabFrustumPlane(at0, atX, atY, atZ, side);
        float inside = (UnityDistanceFromPlane(wpos0, plane) > -cullEps ? 1.0 : 0.0)
                     + (UnityDistanceFromPlane(wpos1, plane) > -cullEps ? 1.0 : 0.0)
                     + (UnityDistanceFromPlane(wpos2, plane) > -cullEps ? 1.0 : 0.0);
        if (inside == 0.0)
            culled = true;
    }
    return culled;
}

// Factors that fall off with the distance from the camera (Tessellation.cginc).
float4 UnityDistanceBasedTess(float4 v0, float4 v1, float4 v2, float minDist, float maxDist, float tess)
{
    float3 f = float3(UnityCalcDistanceTessFactor(v0, minDist, maxDist, tess),
                      UnityCalcDistanceTessFactor(v1, minDist, maxDist, tess),
                      UnityCalcDistanceTessFactor(v2, minDist, maxDist, tess));
    return UnityCalcTriEdgeTessFactors(f);
}

// Factors that make every edge about edgeLength pixels long on screen (Tessellation.cginc).
float4 UnityEdgeLengthBasedTess(float4 v0, float4 v1, float4 v2, float edgeLength)
{
    float3 p0 = mul(unity_ObjectToWorld, v0).xyz;
    float3 p1 = mul(unity_ObjectToWorld, v1).xyz;
    float3 p2 = mul(unity_ObjectToWorld, v2).xyz;
    float e0 = UnityCalcEdgeTessFactor(p1, p2, edgeLength);
    float e1 = UnityCalcEdgeTessFactor(p2, p0, edgeLength);
    float e2 = UnityCalcEdgeTessFactor(p0, p1, edgeLength);
    return float4(e0, e1, e2, (e0 + e1 + e2) / 3.0);
}

// The same, and 0 (no triangle) for one outside the frustum by more than maxDisplacement
// (Tessellation.cginc).
float4 UnityEdgeLengthBasedTessCull(float4 v0, float4 v1, float4 v2, float edgeLength, float maxDisplacement)
{
    float3 p0 = mul(unity_ObjectToWorld, v0).xyz;
    float3 p1 = mul(unity_ObjectToWorld, v1).xyz;
    float3 p2 = mul(unity_ObjectToWorld, v2).xyz;
    float4 tess = float4(0.0, 0.0, 0.0, 0.0);
    if (!UnityWorldViewFrustumCull(p0, p1, p2, maxDisplacement))
        tess = UnityEdgeLengthBasedTess(v0, v1, v2, edgeLength);
    return tess;
}

#endif
