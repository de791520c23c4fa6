// pbrlab stand-in for Unity's UnityGlobalIllumination.cginc: the names a surface shader reads from it are
// already included by the generated program (harness/pbrlab/importers/unity/generate.py; README,
// "Unity shaders", lists them), so this file includes only
// what Unity's includes for a program's own reflection-probe reads: UnityImageBasedLighting.cginc
// (the three-argument Unity_GlossyEnvironment) and UnityStandardUtils.cginc
// (BoxProjectedCubemapDirection).
#include "UnityImageBasedLighting.cginc"
#include "UnityStandardUtils.cginc"

#ifndef PBRLAB_UNITY_RESET_GI
#define PBRLAB_UNITY_RESET_GI
// Unity's resets of a light and of a GI result before a program fills them
// (UnityGlobalIllumination.cginc's ResetUnityLight / ResetUnityGI, read for their behaviour and
// written here anew): every member zero, the light's deprecated ndotl among them.
void ResetUnityLight(out UnityLight outLight)
{
    outLight.color = half3(0, 0, 0);
    outLight.dir = half3(0, 0, 0);
    outLight.ndotl = 0;
}

void ResetUnityGI(out UnityGI outGI)
{
    ResetUnityLight(outGI.light);
    outGI.indirect.diffuse = half3(0, 0, 0);
    outGI.indirect.specular = half3(0, 0, 0);
}
#endif
