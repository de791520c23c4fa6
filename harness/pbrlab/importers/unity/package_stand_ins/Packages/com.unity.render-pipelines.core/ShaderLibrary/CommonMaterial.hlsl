// pbrlab stand-in for Core RP's ShaderLibrary/CommonMaterial.hlsl: the roughness vocabulary's
// converters (smoothness = 1 - perceptual roughness, roughness = its square; docs/conventions.md)
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

#endif
