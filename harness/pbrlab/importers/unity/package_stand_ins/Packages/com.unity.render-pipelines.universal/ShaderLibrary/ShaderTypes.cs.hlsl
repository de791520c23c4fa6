// pbrlab stand-in for URP's ShaderLibrary/ShaderTypes.cs.hlsl: nothing a forward pass here reads, which pbrlab's
// stand-in Core.hlsl defines (written for pbrlab from Unity's documentation of the names;
// Unity's own file is under the Unity Companion License and is not copied).
#ifndef PBRLAB_URP_SHADERTYPES_CS_HLSL
#define PBRLAB_URP_SHADERTYPES_CS_HLSL

#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"

#endif
