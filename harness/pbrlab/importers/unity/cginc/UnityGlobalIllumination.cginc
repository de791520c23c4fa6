// pbrlab stand-in for Unity's UnityGlobalIllumination.cginc: the names a surface shader reads from it are
// already included by the generated program (harness/pbrlab/importers/unity/generate.py; README,
// "Unity shaders", lists them), so this file includes only
// what Unity's includes for a program's own reflection-probe reads: UnityImageBasedLighting.cginc
// (the three-argument Unity_GlossyEnvironment) and UnityStandardUtils.cginc
// (BoxProjectedCubemapDirection).
#include "UnityImageBasedLighting.cginc"
#include "UnityStandardUtils.cginc"
