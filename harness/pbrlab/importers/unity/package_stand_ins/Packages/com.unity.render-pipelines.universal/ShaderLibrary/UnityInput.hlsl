// pbrlab stand-in for URP's ShaderLibrary/UnityInput.hlsl: Unity's built-in variables (unity_ObjectToWorld, _WorldSpaceCameraPos, _Time, ...), which pbrlab's Unity prelude declares, which pbrlab's
// stand-in Core.hlsl defines (written for pbrlab from Unity's documentation of the names;
// Unity's own file is under the Unity Companion License and is not copied).
#ifndef PBRLAB_URP_UNITYINPUT_HLSL
#define PBRLAB_URP_UNITYINPUT_HLSL

#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"

#endif
