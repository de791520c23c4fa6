// pbrlab stand-in for Core RP's ShaderLibrary/ImageBasedLighting.hlsl: the reflection probe's
// mip for a perceptual roughness and back, written for pbrlab from Unity's documentation of the
// names (Core RP's own file is under the Unity Companion License and is not copied).
//
// Provides: PerceptualRoughnessToMipmapLevel(perceptualRoughness) (the stand-in Lighting.hlsl's:
//           pr (1.7 - 0.7 pr) times UNITY_SPECCUBE_LOD_STEPS, 6) and (perceptualRoughness,
//           mipMapCount) (the same fraction of mipMapCount levels);
//           MipmapLevelToPerceptualRoughness(mip) (its inverse on [0, 6]: the root in [0, 1] of
//           0.7 pr^2 - 1.7 pr + mip / 6 = 0, pr = (1.7 - sqrt(1.7^2 - 2.8 mip / 6)) / 1.4);
//           UNITY_SPECCUBE_LOD_STEPS; and, through Lighting.hlsl, unity_SpecCube0 (the scene
//           environment's prefiltered radiance) and DecodeHDREnvironment.
#ifndef PBRLAB_CORE_RP_IMAGE_BASED_LIGHTING_HLSL
#define PBRLAB_CORE_RP_IMAGE_BASED_LIGHTING_HLSL

#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Lighting.hlsl"

// Core RP's literal (an integer, which a program may test in #if): the last of the 7 mips
#ifndef UNITY_SPECCUBE_LOD_STEPS
#define UNITY_SPECCUBE_LOD_STEPS 6
#endif

float PerceptualRoughnessToMipmapLevel(float perceptualRoughness, uint mipMapCount) {
    return perceptualRoughness * (1.7 - 0.7 * perceptualRoughness) * float(mipMapCount);
}
float MipmapLevelToPerceptualRoughness(float mipmapLevel) {
    float fraction = saturate(mipmapLevel / PBRLAB_URP_SPECCUBE_LOD_STEPS);
    return saturate((1.7 - sqrt(1.7 * 1.7 - 2.8 * fraction)) / 1.4);
}

#endif
