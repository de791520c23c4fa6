// pbrlab stand-in for URP's ShaderLibrary/ShaderVariablesFunctions.hlsl: GetVertexPositionInputs, GetVertexNormalInputs, GetCameraPositionWS, the fog functions, which pbrlab's
// stand-in Core.hlsl defines (written for pbrlab from Unity's documentation of the names;
// Unity's own file is under the Unity Companion License and is not copied).
#ifndef PBRLAB_URP_SHADERVARIABLESFUNCTIONS_HLSL
#define PBRLAB_URP_SHADERVARIABLESFUNCTIONS_HLSL

#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"

#endif
