// pbrlab stand-in for Core RP's ShaderLibrary/EntityLighting.hlsl: DecodeHDREnvironment and the
// ambient SH (SampleSH), which pbrlab's stand-in Lighting.hlsl defines (written for pbrlab from
// Unity's documentation of the names; Unity's own file is under the Unity Companion License and
// is not copied).
#ifndef PBRLAB_CORE_RP_ENTITY_LIGHTING_HLSL
#define PBRLAB_CORE_RP_ENTITY_LIGHTING_HLSL

#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Lighting.hlsl"

#endif
