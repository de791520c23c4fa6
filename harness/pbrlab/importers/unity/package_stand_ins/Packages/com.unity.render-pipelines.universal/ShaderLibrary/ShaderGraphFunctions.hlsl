// pbrlab stand-in for URP's ShaderLibrary/ShaderGraphFunctions.hlsl: the SHADERGRAPH_* hooks
// Shader Graph's generated code calls, written for pbrlab from Unity's documentation of the
// Shader Graph nodes behind them (URP's own file is under the Unity Companion License and is
// not copied). Here: no fog (colour 0, density 0: Unity's Fog node outside fog), the ambient
// colours are the environment's SH9 along the sky, equator and ground directions, and the
// scene's colour and depth nodes are not provided (pbrlab draws no opaque pass first).
#ifndef PBRLAB_URP_SHADER_GRAPH_FUNCTIONS_HLSL
#define PBRLAB_URP_SHADER_GRAPH_FUNCTIONS_HLSL

#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Lighting.hlsl"

// IsGammaSpace() (false: pbrlab renders linear, Unity's Linear colour space) is the Unity
// layer's, which every program of a Unity shader holds (unity_compat/shader_variables).

#define SHADERGRAPH_FOG(position, color, density) color = float4(0.0, 0.0, 0.0, 0.0); density = 0.0
#define SHADERGRAPH_AMBIENT_SKY float4(SampleSH(float3(0.0, 1.0, 0.0)), 1.0)
#define SHADERGRAPH_AMBIENT_EQUATOR float4(SampleSH(float3(1.0, 0.0, 0.0)), 1.0)
#define SHADERGRAPH_AMBIENT_GROUND float4(SampleSH(float3(0.0, -1.0, 0.0)), 1.0)
#define SHADERGRAPH_OBJECT_POSITION UNITY_MATRIX_M._m03_m13_m23
#define SHADERGRAPH_BAKED_GI(positionWS, normalWS, uvStaticLightmap, uvDynamicLightmap, applyScaling) SampleSH(normalWS)
#define SHADERGRAPH_REFLECTION_PROBE(viewDir, normalOS, lod) float3(0.0, 0.0, 0.0)

#endif
