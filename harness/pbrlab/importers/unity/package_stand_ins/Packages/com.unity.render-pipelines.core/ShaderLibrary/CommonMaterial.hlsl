// pbrlab stand-in for Core RP's ShaderLibrary/CommonMaterial.hlsl (which URP's Lighting.hlsl brings,
// through its BRDF.hlsl): the roughness vocabulary's converters (smoothness = 1 - perceptual
// roughness, roughness = its square; docs/conventions.md) and BlendNormal
// (PerceptualRoughnessToRoughness and RoughnessToPerceptualRoughness are the built-in
// prelude's, the same functions), written for pbrlab from Unity's documentation of the names
// (Core RP's own file is under the Unity Companion License).
#ifndef PBRLAB_CORE_RP_COMMON_MATERIAL_HLSL
#define PBRLAB_CORE_RP_COMMON_MATERIAL_HLSL

float PerceptualSmoothnessToPerceptualRoughness(float perceptualSmoothness) { return 1.0 - perceptualSmoothness; }
float PerceptualRoughnessToPerceptualSmoothness(float perceptualRoughness) { return 1.0 - perceptualRoughness; }
float PerceptualSmoothnessToRoughness(float perceptualSmoothness) {
    return (1.0 - perceptualSmoothness) * (1.0 - perceptualSmoothness);
}

// Two tangent-space normals blended (Core RP's BlendNormal): the "whiteout" blend of
// Barre-Brisebois and Hill, "Blending in Detail" (2012): xy summed, each weighted by the other's
// z, z the product of the z's, normalized.
float3 BlendNormal(float3 n1, float3 n2) {
    return normalize(float3(n1.xy * n2.z + n2.xy * n1.z, n1.z * n2.z));
}

// Reoriented normal mapping (Core RP's BlendNormalRNM; Barre-Brisebois and Hill, "Blending in
// Detail", 2012): n2 rotated by the rotation that takes (0, 0, 1) to n1, both unit:
// t = n1 + (0, 0, 1), u = n2 * (-1, -1, 1), t dot(t, u) / t.z - u, normalized.
float3 BlendNormalRNM(float3 n1, float3 n2) {
    float3 t = n1 + float3(0.0, 0.0, 1.0);
    float3 u = n2 * float3(-1.0, -1.0, 1.0);
    return normalize(t * dot(t, u) / t.z - u);
}

// A detail map's blend toward white (Core RP 14.0.9 CommonMaterial.hlsl, LerpWhiteTo, which URP's
// Shadows.hlsl applies to the shadow strength): lerp(1, b, t) written as (1 - t) + b t. The
// float3 form is the harness library's (pbr/unity/unity_cg, UnityStandardUtils.cginc's, the same
// formula), in every Unity program; Core's scalar form here.
float LerpWhiteTo(float b, float t) { return (1.0 - t) + b * t; }

#endif
