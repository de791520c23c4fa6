// pbrlab stand-in for Unity's UnityStandardUtils.cginc.
//
// Provides: ParallaxOffset1Step(h, height, viewDir), the one-step parallax shift the
//   Standard shader's Parallax() takes (the same formula as UnityCG's ParallaxOffset,
//   pbr/unity/unity_cg.glsl, which documents it). The file's other names
//   (DiffuseAndSpecularFromMetallic, EnergyConservationBetweenDiffuseAndSpecular,
//   PreMultiplyAlpha, UnpackScaleNormal, BlendNormals, ...) are already included by the
//   generated program (harness/pbrlab/importers/unity/generate.py; README, "Unity shaders", lists them).
// Unity's file: the same names (UnityStandardUtils.cginc, Unity 2019.4 built-in shaders),
//   read for their behaviour and written here anew.
// Cg text in the plain subset harness/pbrlab/importers/unity/port.py ports to GLSL.
#ifndef PBRLAB_UNITY_STANDARD_UTILS_CGINC
#define PBRLAB_UNITY_STANDARD_UTILS_CGINC

float2 ParallaxOffset1Step(half h, half height, half3 viewDir)
{
    return ParallaxOffset(h, height, viewDir);
}

#endif
