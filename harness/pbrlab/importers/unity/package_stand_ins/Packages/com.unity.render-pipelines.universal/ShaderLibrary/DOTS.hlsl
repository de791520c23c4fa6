// pbrlab stand-in for URP's ShaderLibrary/DOTS.hlsl: DOTS instancing, which has one instance here (UNITY_DOTS_INSTANCING_START and friends declare plain uniforms), which pbrlab's
// stand-in Core.hlsl defines (written for pbrlab from Unity's documentation of the names;
// Unity's own file is under the Unity Companion License and is not copied).
#ifndef PBRLAB_URP_DOTS_HLSL
#define PBRLAB_URP_DOTS_HLSL

#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"

#endif
