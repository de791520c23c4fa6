// pbrlab stand-in for Core RP's ShaderLibrary/API/GLCore.hlsl: the texture and sampler macros, which pbrlab's
// stand-in Core.hlsl defines (written for pbrlab from Unity's documentation of the names;
// Unity's own file is under the Unity Companion License and is not copied).
#ifndef PBRLAB_CORE_RP_API_GLCORE_HLSL
#define PBRLAB_CORE_RP_API_GLCORE_HLSL

#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"

#endif
