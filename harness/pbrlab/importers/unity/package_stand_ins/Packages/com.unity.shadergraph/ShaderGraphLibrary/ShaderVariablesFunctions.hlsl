// pbrlab stand-in for Shader Graph's ShaderGraphLibrary/ShaderVariablesFunctions.hlsl: the
// camera and transform helpers (GetCameraPositionWS, GetWorldSpaceViewDir, ...), which
// pbrlab's URP stand-in Core.hlsl defines (written for pbrlab from Unity's documentation of
// the names; Unity's own file is under the Unity Companion License and is not copied).
#ifndef PBRLAB_SHADERGRAPH_SHADER_VARIABLES_FUNCTIONS_HLSL
#define PBRLAB_SHADERGRAPH_SHADER_VARIABLES_FUNCTIONS_HLSL

#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"

#endif
