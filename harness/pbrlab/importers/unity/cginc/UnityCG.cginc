// pbrlab stand-in for Unity's UnityCG.cginc: the names a surface shader reads from it are
// already included by the generated program (harness/pbrlab/importers/unity/generate.py; README,
// "Unity shaders", lists them), so this file is empty.

#include "UnityCGPacking.cginc"
#include "UnityCGFog.cginc"
#include "UnityLightmapDecoding.cginc"
#include "UnityRealtimeLightmap.cginc"
