// pbrlab stand-in for Core RP's ShaderLibrary/UnityInstancing.hlsl: the instancing macros, each for one instance (UNITY_VERTEX_INPUT_INSTANCE_ID, UNITY_SETUP_INSTANCE_ID, ...), which pbrlab's
// stand-in Core.hlsl defines (written for pbrlab from Unity's documentation of the names;
// Unity's own file is under the Unity Companion License and is not copied).
#ifndef PBRLAB_CORE_RP_UNITYINSTANCING_HLSL
#define PBRLAB_CORE_RP_UNITYINSTANCING_HLSL

#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"

#endif
