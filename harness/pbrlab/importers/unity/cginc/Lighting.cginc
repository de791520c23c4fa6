// pbrlab stand-in for Unity's Lighting.cginc: the names a surface shader reads from it are
// already included by the generated program (harness/pbrlab/importers/unity/generate.py; README,
// "Unity shaders", lists them). Unity's file includes UnityGlobalIllumination.cginc, which brings
// UnityImageBasedLighting.cginc, UnityStandardUtils.cginc (BoxProjectedCubemapDirection, ...) and
// UnityStandardConfig.cginc (UNITY_SPECCUBE_LOD_STEPS), so a shader that includes Lighting.cginc
// alone reads them; the stand-in includes the same.
#include "UnityGlobalIllumination.cginc"
#include "UnityStandardConfig.cginc"
