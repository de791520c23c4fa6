// pbrlab's body of the Core RP SpaceTransforms.hlsl stand-in: the space transforms
// (TransformObjectToWorld, TransformWorldToHClip, the directions' and normals' forms with their
// optional doNormalize argument, the tangent frame), written for pbrlab from Unity's
// documentation of the names and their signatures (Core RP's own file is under the Unity
// Companion License and is not copied). Matrices are pbrlab's Unity prelude's
// (unity_compat/shader_variables: unity_ObjectToWorld, UNITY_MATRIX_V, ...).
//
// Included by the stand-in Core.hlsl after its constants and SafeNormalize (a name of pbrlab's,
// not Unity's: the stand-in SpaceTransforms.hlsl includes Core.hlsl, which includes this).
#ifndef PBRLAB_CORE_RP_SPACETRANSFORMS_BODY_HLSL
#define PBRLAB_CORE_RP_SPACETRANSFORMS_BODY_HLSL

float4x4 GetObjectToWorldMatrix() { return unity_ObjectToWorld; }
float4x4 GetWorldToObjectMatrix() { return unity_WorldToObject; }
float4x4 GetWorldToViewMatrix() { return UNITY_MATRIX_V; }
float4x4 GetViewToWorldMatrix() { return UNITY_MATRIX_I_V; }
float4x4 GetWorldToHClipMatrix() { return UNITY_MATRIX_VP; }
float4x4 GetViewToHClipMatrix() { return UNITY_MATRIX_P; }
// -1 where the object's transform mirrors (a negative determinant), else 1.
float GetOddNegativeScale() { return determinant((float3x3)unity_ObjectToWorld) < 0.0 ? -1.0 : 1.0; }

// Positions (w = 1).
float3 TransformObjectToWorld(float3 positionOS) { return mul(unity_ObjectToWorld, float4(positionOS, 1.0)).xyz; }
float3 TransformWorldToObject(float3 positionWS) { return mul(unity_WorldToObject, float4(positionWS, 1.0)).xyz; }
float3 TransformWorldToView(float3 positionWS) { return mul(UNITY_MATRIX_V, float4(positionWS, 1.0)).xyz; }
float3 TransformViewToWorld(float3 positionVS) { return mul(UNITY_MATRIX_I_V, float4(positionVS, 1.0)).xyz; }
float4 TransformWorldToHClip(float3 positionWS) { return mul(UNITY_MATRIX_VP, float4(positionWS, 1.0)); }
float4 TransformObjectToHClip(float3 positionOS) { return TransformWorldToHClip(TransformObjectToWorld(positionOS)); }
float4 TransformWViewToHClip(float3 positionVS) { return mul(UNITY_MATRIX_P, float4(positionVS, 1.0)); }

// Directions (w = 0: the upper 3x3), normalized when doNormalize is true (SafeNormalize: a zero
// vector stays 0). Each default is Core RP's: true from and to the object, false to and from the
// view and to clip space.
float3 pbrlab_normalized_if(float3 v, bool doNormalize) { return doNormalize ? SafeNormalize(v) : v; }
float3 TransformObjectToWorldDir(float3 dirOS, bool doNormalize = true) {
    return pbrlab_normalized_if(mul((float3x3)unity_ObjectToWorld, dirOS), doNormalize);
}
float3 TransformWorldToObjectDir(float3 dirWS, bool doNormalize = true) {
    return pbrlab_normalized_if(mul((float3x3)unity_WorldToObject, dirWS), doNormalize);
}
float3 TransformWorldToViewDir(float3 dirWS, bool doNormalize = false) {
    return pbrlab_normalized_if(mul((float3x3)UNITY_MATRIX_V, dirWS), doNormalize);
}
float3 TransformViewToWorldDir(float3 dirVS, bool doNormalize = false) {
    return pbrlab_normalized_if(mul((float3x3)UNITY_MATRIX_I_V, dirVS), doNormalize);
}
// A world direction to clip space (w dropped: a direction has no position).
float3 TransformWorldToHClipDir(float3 dirWS, bool doNormalize = false) {
    return pbrlab_normalized_if(mul((float3x3)UNITY_MATRIX_VP, dirWS), doNormalize);
}

// Normals by the inverse transpose: n^T M^-1, as Unity writes it (object to world), and n^T M
// back; the view's rotation is orthonormal, so its normals are its directions.
float3 TransformObjectToWorldNormal(float3 normalOS, bool doNormalize = true) {
    return pbrlab_normalized_if(mul(normalOS, (float3x3)unity_WorldToObject), doNormalize);
}
float3 TransformWorldToObjectNormal(float3 normalWS, bool doNormalize = true) {
    return pbrlab_normalized_if(mul(normalWS, (float3x3)unity_ObjectToWorld), doNormalize);
}
float3 TransformWorldToViewNormal(float3 normalWS, bool doNormalize = false) { return TransformWorldToViewDir(normalWS, doNormalize); }
float3 TransformViewToWorldNormal(float3 normalVS, bool doNormalize = false) { return TransformViewToWorldDir(normalVS, doNormalize); }

// The tangent frame as a matrix whose rows are the tangent, the bitangent (the normal crossed
// with the tangent, its sign the tangent's w: flipSign) and the normal (Core RP's
// CreateTangentToWorld); TransformTangentToWorld takes it.
float3x3 CreateTangentToWorld(float3 normal, float3 tangent, float flipSign) {
    float3 bitangent = cross(normal, tangent) * flipSign;
    return float3x3(tangent, bitangent, normal);
}
// A tangent-space normal to world space through the rows (T, B, N).
float3 TransformTangentToWorld(float3 dirTS, float3x3 tangentToWorld, bool doNormalize = false) {
    return pbrlab_normalized_if(mul(dirTS, tangentToWorld), doNormalize);
}
// World to tangent space through the rows (T, B, N): the transpose's product (URP 12's form).
float3 TransformWorldToTangent(float3 dirWS, float3x3 tangentToWorld) { return mul(tangentToWorld, dirWS); }
float3 TransformWorldToTangentDir(float3 dirWS, float3x3 tangentToWorld, bool doNormalize = false) {
    return pbrlab_normalized_if(mul(tangentToWorld, dirWS), doNormalize);
}

#endif
