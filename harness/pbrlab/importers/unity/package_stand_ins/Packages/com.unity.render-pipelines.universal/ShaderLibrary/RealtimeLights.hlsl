// pbrlab stand-in for URP's ShaderLibrary/RealtimeLights.hlsl: the Light struct, GetMainLight and GetAdditionalLight(s), which pbrlab's
// stand-in Lighting.hlsl defines (written for pbrlab from Unity's documentation of the names;
// Unity's own file is under the Unity Companion License and is not copied).
#ifndef PBRLAB_URP_REALTIMELIGHTS_HLSL
#define PBRLAB_URP_REALTIMELIGHTS_HLSL

#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Lighting.hlsl"

#endif
