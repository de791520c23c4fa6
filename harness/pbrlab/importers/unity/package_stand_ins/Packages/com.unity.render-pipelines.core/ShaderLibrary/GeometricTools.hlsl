// pbrlab stand-in for Core RP's ShaderLibrary/GeometricTools.hlsl: the geometry helpers URP
// shaders call (written for pbrlab from the textbook formulas each names and Unity's
// documentation of the names; Core RP's own file is under the Unity Companion License and is
// not copied). Not provided: the frustum and back-face culling tests, the ray-cone and
// sphere-box tests.
#ifndef PBRLAB_CORE_RP_GEOMETRIC_TOOLS_HLSL
#define PBRLAB_CORE_RP_GEOMETRIC_TOOLS_HLSL

#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"

// position rotated by angle (radians) about the axis through pivot (Rodrigues' formula on the
// offset from the axis' closest point)
float3 Rotate(float3 pivot, float3 position, float3 rotationAxis, float angle) {
    float3 k = normalize(rotationAxis);
    float3 onAxis = pivot + k * dot(k, position - pivot);
    float3 r = position - onAxis;
    return onAxis + r * cos(angle) + cross(k, r) * sin(angle);
}

// The rotation matrix about the unit axis A (Rodrigues: c I + s [A]x + (1 - c) A A^T), applied
// as mul(M, v)
float3x3 RotationFromAxisAngle(float3 A, float sinAngle, float cosAngle) {
    float c = cosAngle, s = sinAngle, t = 1.0 - cosAngle;
    return float3x3(t * A.x * A.x + c, t * A.x * A.y - s * A.z, t * A.x * A.z + s * A.y,
                    t * A.x * A.y + s * A.z, t * A.y * A.y + c, t * A.y * A.z - s * A.x,
                    t * A.x * A.z - s * A.y, t * A.y * A.z + s * A.x, t * A.z * A.z + c);
}

// The real roots of a t^2 + b t + c = 0, smaller first (whatever a's sign); false when the
// discriminant is negative (the roots are then NaN)
bool SolveQuadraticEquation(float a, float b, float c, out float2 roots) {
    float discriminant = b * b - 4.0 * a * c;
    float s = (a >= 0.0 ? 1.0 : -1.0) * sqrt(discriminant);
    roots = float2(-b - s, -b + s) / (2.0 * a);
    return discriminant >= 0.0;
}

// The ray start + t dir against the sphere of the radius about the origin: the two t
bool IntersectRaySphere(float3 start, float3 dir, float radius, out float2 intersections) {
    return SolveQuadraticEquation(dot(dir, dir), 2.0 * dot(dir, start), dot(start, start) - radius * radius,
                                  intersections);
}

// The same for a unit dir from inside the sphere: the far root, the distance to the surface
float IntersectRaySphereSimple(float3 start, float3 dir, float radius) {
    float b = 2.0 * dot(dir, start);
    float c = dot(start, start) - radius * radius;
    return abs(sqrt(b * b - 4.0 * c) - b) * 0.5;
}

// The point where the ray meets the plane through planeOrigin with the normal
float3 IntersectRayPlane(float3 rayOrigin, float3 rayDirection, float3 planeOrigin, float3 planeNormal) {
    return rayOrigin + rayDirection * (dot(planeNormal, planeOrigin - rayOrigin) / dot(planeNormal, rayDirection));
}

// The ray's parameter t there, and whether it meets the plane ahead (t >= 0); t = -1 and false
// for a ray parallel to it (|n.d| <= 1e-5)
bool IntersectRayPlane(float3 rayOrigin, float3 rayDirection, float3 planePosition, float3 planeNormal, out float t) {
    float facing = dot(planeNormal, rayDirection);
    t = -1.0;
    if (abs(facing) <= 1e-5)
        return false;
    t = dot(planePosition - rayOrigin, planeNormal) / facing;
    return t >= 0.0;
}

// The distance from a point to an axis-aligned box (0 inside)
float DistancePointBox(float3 position, float3 boxMin, float3 boxMax) {
    return length(max(max(position - boxMax, boxMin - position), float3(0.0, 0.0, 0.0)));
}

// The point's orthogonal projection on the plane through planePosition with the unit normal
float3 ProjectPointOnPlane(float3 position, float3 planePosition, float3 planeNormal) {
    return position - dot(position - planePosition, planeNormal) * planeNormal;
}

// The signed distance of p from the plane (n, d) (n.x + d = 0, n unit): positive in front
float DistanceFromPlane(float3 p, float4 plane) {
    return dot(plane.xyz, p) + plane.w;
}

#endif
