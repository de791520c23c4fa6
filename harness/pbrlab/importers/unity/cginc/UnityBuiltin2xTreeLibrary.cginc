// pbrlab stand-in for Unity's UnityBuiltin2xTreeLibrary.cginc (the Unity 2.x "soft
// occlusion" tree shaders: Nature/SoftOcclusion/*).
//
// Provides: _Occlusion, _AO, _BaseLight, _Color, _HalfOverCutoff; struct v2f (pos, uv,
//   color); the vertex functions leaves(appdata_tree) and bark(appdata_tree); and everything
//   TerrainEngine.cginc's stand-in provides (appdata_tree, the rest-pose tree helpers).
// Unity's file: the same names (UnityBuiltin2xTreeLibrary.cginc, Unity 2019.4 built-in
//   shaders), read for their behaviour and written here anew.
// Differences, and why: Unity sums four vertex lights (unity_LightPosition[4],
//   unity_LightColor[4], unity_LightAtten[4] of the legacy vertex-lit path, or, with
//   USE_CUSTOM_LIGHT_DIR (the Rendertex passes), the terrain imposter's
//   _TerrainTreeLightDirections/Colors) over the ambient. With USE_CUSTOM_LIGHT_DIR this file
//   does the same: the imposter's four lights are filled from the scene's directional lights
//   (engine_inputs.FILLED: object-space directions towards each, colour x intensity; empty
//   slots 0) over UNITY_LIGHTMODEL_AMBIENT. Without it, leaves and bark are lit by the main
//   light (_WorldSpaceLightPos0, _LightColor0) over the ambient (ShadeSH9 along the normal
//   instead of UNITY_LIGHTMODEL_AMBIENT). The
//   occlusion terms are Unity's: leaves by the baked directional occlusion in tangent
//   (dot(tangent, (L _Occlusion, _AO))), bark by N.L times _AO tangent.w + _BaseLight. Rest pose
//   (TerrainEngine.cginc's stand-in) and _TreeInstanceColor taken as white. No fog.
// Cg text in the plain subset harness/pbrlab/importers/unity/port.py ports to GLSL.
#ifndef PBRLAB_UNITY_BUILTIN_2X_TREE_LIBRARY_CGINC
#define PBRLAB_UNITY_BUILTIN_2X_TREE_LIBRARY_CGINC

#include "TerrainEngine.cginc"

float _Occlusion;
float _AO;
float _BaseLight;
fixed4 _Color;
float _HalfOverCutoff;

struct v2f
{
    float4 pos : SV_POSITION;
    float4 uv : TEXCOORD0;
    half4 color : TEXCOORD1;
};

#if defined(USE_CUSTOM_LIGHT_DIR)
// The terrain imposter's lights, this stage's own globals its entry point fills from the scene
// (harness/pbrlab/importers/unity/engine_inputs.py, FILLED).
static float3 _TerrainTreeLightDirections[4];
static float4 _TerrainTreeLightColors[4];

// Leaves (Unity's custom-light path): ambient plus, per imposter light, its colour times
// max(0, tangent . (L _Occlusion, _AO)) + _BaseLight.
float4 PbrlabTreeImposterLeaves(float4 tangent)
{
    float4 light = UNITY_LIGHTMODEL_AMBIENT;
    for (int i = 0; i < 4; i++)
    {
        float occlusion = max(0.0, dot(tangent, float4(_TerrainTreeLightDirections[i] * _Occlusion, _AO)));
        light += _TerrainTreeLightColors[i] * (occlusion + _BaseLight);
    }
    return light;
}

// Bark (Unity's custom-light path): ambient plus, per imposter light, its colour times
// max(0, N.L) (_AO tangent.w + _BaseLight).
float4 PbrlabTreeImposterBark(float3 normal, float4 tangent)
{
    float4 light = UNITY_LIGHTMODEL_AMBIENT;
    for (int i = 0; i < 4; i++)
    {
        float diffuse = max(0.0, dot(normal, _TerrainTreeLightDirections[i]));
        light += _TerrainTreeLightColors[i] * (diffuse * (_AO * tangent.w + _BaseLight));
    }
    return light;
}
#endif

// The main light's direction in object space (w = 0 directional, else towards its position).
float3 PbrlabTreeObjectLightDir(float4 vertex)
{
    float3 worldPos = mul(unity_ObjectToWorld, vertex).xyz;
    float3 worldDir = normalize(UnityWorldSpaceLightDir(worldPos));
    return normalize(mul(unity_WorldToObject, float4(worldDir, 0.0)).xyz);
}

// Leaves: ambient plus the light times max(0, tangent . (L _Occlusion, _AO)) + _BaseLight,
// alpha 0.5 _HalfOverCutoff (UnityBuiltin2xTreeLibrary.cginc, leaves).
v2f leaves(appdata_tree v)
{
    v2f o;
    TerrainAnimateTree(v.vertex, v.color.w);
    o.pos = UnityObjectToClipPos(v.vertex);
    o.uv = v.texcoord;
#if defined(USE_CUSTOM_LIGHT_DIR)
    o.color = PbrlabTreeImposterLeaves(v.tangent) * _Color;
#else
    float4 occlusionDir = float4(PbrlabTreeObjectLightDir(v.vertex) * _Occlusion, _AO);
    float occlusion = max(0.0, dot(v.tangent, occlusionDir)) + _BaseLight;
    float3 world = UnityObjectToWorldNormal(v.normal);
    float3 light = ShadeSH9(float4(world, 1.0)) + _LightColor0.rgb * occlusion;
    o.color = float4(light, 1.0) * _Color;
#endif
    o.color.a = 0.5 * _HalfOverCutoff;
    return o;
}

// Bark: ambient plus the light times max(0, N.L) (_AO tangent.w + _BaseLight), alpha 1
// (UnityBuiltin2xTreeLibrary.cginc, bark).
v2f bark(appdata_tree v)
{
    v2f o;
    TerrainAnimateTree(v.vertex, v.color.w);
    o.pos = UnityObjectToClipPos(v.vertex);
    o.uv = v.texcoord;
#if defined(USE_CUSTOM_LIGHT_DIR)
    o.color = float4(PbrlabTreeImposterBark(v.normal, v.tangent).rgb, 1.0) * _Color;
#else
    float diffuse = max(0.0, dot(v.normal, PbrlabTreeObjectLightDir(v.vertex)));
    diffuse = diffuse * (_AO * v.tangent.w + _BaseLight);
    float3 world = UnityObjectToWorldNormal(v.normal);
    float3 light = ShadeSH9(float4(world, 1.0)) + _LightColor0.rgb * diffuse;
    o.color = float4(light, 1.0) * _Color;
#endif
#if defined(WRITE_ALPHA_1)
    o.color.a = 1.0;
#endif
    return o;
}

#endif
