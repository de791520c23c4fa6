// pbrlab stand-in for Unity's UnityStandardBRDF.cginc. The BRDFs a surface shader reads from it
// are already included by the generated program (harness/pbrlab/importers/unity/generate.py;
// README, "Unity shaders", lists them); declared here: the helpers a vertex/fragment program
// calls itself.
//
// Provides: DotClamped(a, b) (the dot product clamped below at 0), and through
//   UnityStandardConfig.cginc UNITY_SPECCUBE_LOD_STEPS, as Unity's file includes it.
// Unity's file: the same names (UnityStandardBRDF.cginc, Unity 2019.4 built-in shaders), read
//   for their behaviour and written here anew. Differences: none; Unity's shader-model-2 path
//   (saturate of the dot product) differs from this one (max(0, dot)) only above 1, which
//   a dot of unit vectors does not reach.
// Text that is HLSL and GLSL alike (preprocessor lines only).
#ifndef PBRLAB_UNITY_STANDARD_BRDF_CGINC
#define PBRLAB_UNITY_STANDARD_BRDF_CGINC

#include "UnityStandardConfig.cginc"

// max(0, a . b): a cosine that light behind the surface does not make negative. A macro, not
// Unity's inline function: its text is both HLSL and GLSL, so this file (which the
// UnityPBSLighting.cginc stand-in includes) also reads as GLSL where a `pbrlab port-unity`
// output includes it unported.
#define DotClamped(a, b) max(0.0, dot(a, b))

#endif
