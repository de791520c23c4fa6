// pbrlab stand-in for Unity's Lighting.cginc: the names a surface shader reads from it are
// already included by the generated program (harness/pbrlab/importers/unity/generate.py; README,
// "Unity shaders", lists them). Unity's file reaches UnityStandardConfig.cginc through
// UnityGlobalIllumination.cginc and UnityImageBasedLighting.cginc, so a shader that includes
// Lighting.cginc alone reads UNITY_SPECCUBE_LOD_STEPS; the stand-in includes it likewise.
#include "UnityStandardConfig.cginc"
