// pbrlab stand-in for Unity's UnityPBSLighting.cginc: the names a surface shader reads from it are
// already included by the generated program (harness/pbrlab/importers/unity/generate.py; README,
// "Unity shaders", lists them), so this file includes only
// UnityGlobalIllumination.cginc, as Unity's does (the probe's names below).
#include "UnityGlobalIllumination.cginc"
