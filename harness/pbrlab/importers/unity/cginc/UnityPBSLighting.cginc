// pbrlab stand-in for Unity's UnityPBSLighting.cginc: the names a surface shader reads from it are
// already included by the generated program (harness/pbrlab/importers/unity/generate.py; README,
// "Unity shaders", lists them). It includes UnityStandardBRDF.cginc and
// UnityGlobalIllumination.cginc, as Unity's file does, so a vertex/fragment program that
// includes this one has their helpers (DotClamped; the probe's names below).
#include "UnityStandardBRDF.cginc"
#include "UnityGlobalIllumination.cginc"
