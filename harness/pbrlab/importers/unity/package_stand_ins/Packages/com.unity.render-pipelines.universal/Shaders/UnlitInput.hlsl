// pbrlab stand-in for URP's Shaders/UnlitInput.hlsl: the Unlit shader's material inputs (its
// UnityPerMaterial properties _BaseMap_ST, _BaseColor, _Cutoff, _Surface, and the base map
// SurfaceInput.hlsl declares), written for pbrlab from Unity's documentation of the Unlit
// shader's properties (URP's own file is under the Unity Companion License and is not copied).
// Projects that copy URP's Unlit.shader include it.
#ifndef PBRLAB_URP_UNLIT_INPUT_HLSL
#define PBRLAB_URP_UNLIT_INPUT_HLSL

#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/SurfaceInput.hlsl"

CBUFFER_START(UnityPerMaterial)
float4 _BaseMap_ST;
float4 _BaseColor;
float _Cutoff;
float _Surface;
CBUFFER_END

#endif
