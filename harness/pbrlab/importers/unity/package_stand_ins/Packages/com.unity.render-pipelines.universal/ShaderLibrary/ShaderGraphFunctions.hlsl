// pbrlab stand-in for URP's ShaderLibrary/ShaderGraphFunctions.hlsl: the SHADERGRAPH_* hooks
// Shader Graph's generated code calls, written for pbrlab from Unity's documentation of the
// Shader Graph nodes behind them (URP's own file is under the Unity Companion License and is
// not copied). Here: no fog (colour 0, density 0: Unity's Fog node outside fog), the ambient
// colours are the environment's SH9 along the sky, equator and ground directions. The scene's
// depth, colour and normals (Shader Graph's Scene Depth, Scene Color and URP Sample Buffer
// nodes) are the camera's textures the DeclareDepthTexture / DeclareOpaqueTexture /
// DeclareNormalsTexture stand-ins read, brought in by the program's REQUIRE_DEPTH_TEXTURE /
// REQUIRE_OPAQUE_TEXTURE / REQUIRE_NORMAL_TEXTURE, which Shader Graph's generated code defines
// for a graph that has the node; without it the node reads 0, as URP's does.
#ifndef PBRLAB_URP_SHADER_GRAPH_FUNCTIONS_HLSL
#define PBRLAB_URP_SHADER_GRAPH_FUNCTIONS_HLSL

#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Lighting.hlsl"

// IsGammaSpace() (false: pbrlab renders linear, Unity's Linear colour space) is the Unity
// layer's, which every program of a Unity shader holds (unity_compat/shader_variables).

#if defined(REQUIRE_DEPTH_TEXTURE)
#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/DeclareDepthTexture.hlsl"
#endif
#if defined(REQUIRE_OPAQUE_TEXTURE)
#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/DeclareOpaqueTexture.hlsl"
#endif
#if defined(REQUIRE_NORMAL_TEXTURE)
#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/DeclareNormalsTexture.hlsl"
#endif

// The raw depth (the depth buffer's [0, 1] value), the colour and the world normal at a [0, 1]
// screen position.
float pbrlab_shadergraph_scene_depth(float2 uv) {
#if defined(REQUIRE_DEPTH_TEXTURE)
    return SampleSceneDepth(uv);
#else
    return 0.0;
#endif
}
float3 pbrlab_shadergraph_scene_color(float2 uv) {
#if defined(REQUIRE_OPAQUE_TEXTURE)
    return SampleSceneColor(uv);
#else
    return float3(0.0, 0.0, 0.0);
#endif
}
float3 pbrlab_shadergraph_scene_normal(float2 uv) {
#if defined(REQUIRE_NORMAL_TEXTURE)
    return SampleSceneNormals(uv);
#else
    return float3(0.0, 0.0, 0.0);
#endif
}
// The same given a float4 position (Amplify Shader Editor's graphs pass the normalized grab
// screen position, a float4): Unity's functions take a float2, which FXC reads as the float4's
// xy (implicit truncation, warning X3206); glslang's HLSL does the same, GLSL refuses the call.
float pbrlab_shadergraph_scene_depth(float4 uv) { return pbrlab_shadergraph_scene_depth(uv.xy); }
float3 pbrlab_shadergraph_scene_color(float4 uv) { return pbrlab_shadergraph_scene_color(uv.xy); }
float3 pbrlab_shadergraph_scene_normal(float4 uv) { return pbrlab_shadergraph_scene_normal(uv.xy); }
#define SHADERGRAPH_SAMPLE_SCENE_DEPTH(uv) pbrlab_shadergraph_scene_depth(uv)
#define SHADERGRAPH_SAMPLE_SCENE_COLOR(uv) pbrlab_shadergraph_scene_color(uv)
#define SHADERGRAPH_SAMPLE_SCENE_NORMAL(uv) pbrlab_shadergraph_scene_normal(uv)

#define SHADERGRAPH_FOG(position, color, density) color = float4(0.0, 0.0, 0.0, 0.0); density = 0.0
#define SHADERGRAPH_AMBIENT_SKY float4(SampleSH(float3(0.0, 1.0, 0.0)), 1.0)
#define SHADERGRAPH_AMBIENT_EQUATOR float4(SampleSH(float3(1.0, 0.0, 0.0)), 1.0)
#define SHADERGRAPH_AMBIENT_GROUND float4(SampleSH(float3(0.0, -1.0, 0.0)), 1.0)
#define SHADERGRAPH_OBJECT_POSITION UNITY_MATRIX_M._m03_m13_m23
#define SHADERGRAPH_BAKED_GI(positionWS, normalWS, uvStaticLightmap, uvDynamicLightmap, applyScaling) SampleSH(normalWS)
#define SHADERGRAPH_REFLECTION_PROBE(viewDir, normalOS, lod) float3(0.0, 0.0, 0.0)

#endif
