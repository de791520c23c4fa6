// pbrlab stand-in for Unity's UnityCG.cginc: the names a surface shader reads from it are
// already included by the generated program (harness/pbrlab/importers/unity/generate.py; README,
// "Unity shaders", lists them), so this file is empty.

#include "UnityCGPacking.cginc"
#include "UnityCGFog.cginc"
#include "UnityLightmapDecoding.cginc"
#include "UnityRealtimeLightmap.cginc"

// Whether a pass samples the ambient probe's SH (UnityCG.cginc, Unity 2019.4 to 2022: the
// engine's LIGHTPROBE_SH keyword, which it sets in a ForwardBase variant of an object that has no
// lightmap, in a pass that is none of ForwardAdd, PrepassBase, ShadowCaster and Meta; pbrlab
// defines LIGHTPROBE_SH as the engine does, light_probes.py). Evaluated where a program tests it,
// as Unity's expression is.
#define UNITY_SHOULD_SAMPLE_SH (defined(LIGHTPROBE_SH) && !defined(UNITY_PASS_FORWARDADD) && !defined(UNITY_PASS_PREPASSBASE) && !defined(UNITY_PASS_SHADOWCASTER) && !defined(UNITY_PASS_META))
