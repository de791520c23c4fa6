// pbrlab stand-in for Unity's UnityBuiltin3xTreeLibrary.cginc (the Tree Creator shaders:
// Nature/TreeCreator/*).
//
// Provides: _Color, _TranslucencyColor, _TranslucencyViewDependency, _ShadowStrength;
//   LeafSurfaceOutput and its lighting model LightingTreeLeaf (s, lightDir, viewDir, atten);
//   the per-vertex leaf lighting ShadeTranslucentMainLight and ShadeTranslucentLights;
//   the vertex functions TreeVertBark and TreeVertLeaf; ScreenDitherToAlpha and
//   ComputeAlphaCoverage; and everything TerrainEngine.cginc's stand-in provides.
// Unity's file: the same names (UnityBuiltin3xTreeLibrary.cginc, Unity 2019.4 built-in
//   shaders), read for their behaviour and written here anew.
// Differences, and why: the tree's rest pose (TerrainEngine.cginc's stand-in: no wind, no
//   per-instance scale or squash; _TreeInstanceColor, set per tree by the terrain, taken as
//   white); billboard leaves (tangent.w = 0, baked by the Tree Creator) are not turned to the
//   camera, since pbrlab's meshes carry none and the harness has no view matrix
//   (UNITY_MATRIX_IT_MV); ShadeTranslucentLights has the ambient (ShadeSH9) but not Unity's
//   four per-vertex point lights (VERTEXLIGHT_ON: the harness has no such arrays);
//   LightingTreeLeaf's atten is the harness's (1: the light's falloff is in its colour) and
//   _ShadowStrength has no shadow to soften. ScreenDitherToAlpha computes Unity's 8 x 8 ordered
//   dither matrix from the pixel's bits instead of a table.
// Cg text in the plain subset harness/pbrlab/importers/unity/port.py ports to GLSL (a local's name is
// not reused with another type in this file: the port reads a name's type file-wide).
#ifndef PBRLAB_UNITY_BUILTIN_3X_TREE_LIBRARY_CGINC
#define PBRLAB_UNITY_BUILTIN_3X_TREE_LIBRARY_CGINC

#include "TerrainEngine.cginc"

fixed4 _Color;
fixed3 _TranslucencyColor;
fixed _TranslucencyViewDependency;
half _ShadowStrength;

struct LeafSurfaceOutput
{
    fixed3 Albedo;
    fixed3 Normal;
    fixed3 Emission;
    fixed Translucency;
    half Specular;
    fixed Gloss;
    fixed Alpha;
};

// How much light comes through from behind: Unity lerps from the back-facing -N.L towards
// the view-dependent V.(-L) by _TranslucencyViewDependency (UnityBuiltin3xTreeLibrary.cginc).
half PbrlabTreeBackContribution(half NdotL, float3 viewDir, float3 lightDir)
{
    half viewBack = saturate(dot(viewDir, -lightDir));
    return lerp(saturate(-NdotL), viewBack, _TranslucencyViewDependency);
}

// Wrapped diffuse max(0, 0.6 N.L + 0.4) plus twice the translucency, times the light, plus a
// Blinn-Phong highlight of exponent 128 Specular scaled by Gloss (UnityBuiltin3xTreeLibrary.cginc,
// LightingTreeLeaf; Unity softens the directional shadow by _ShadowStrength, here atten is 1).
half4 LightingTreeLeaf(LeafSurfaceOutput s, half3 lightDir, half3 viewDir, half atten)
{
    half3 h = normalize(lightDir + viewDir);
    half NdotL = dot(s.Normal, lightDir);
    half NdotH = max(0.0, dot(s.Normal, h));
    half highlight = pow(NdotH, s.Specular * 128.0) * s.Gloss;
    fixed3 translucency = PbrlabTreeBackContribution(NdotL, viewDir, lightDir) * s.Translucency * _TranslucencyColor;
    half wrapped = max(0.0, NdotL * 0.6 + 0.4);
    half3 lit = s.Albedo * (translucency * 2.0 + wrapped) * _LightColor0.rgb + highlight;
#if defined(DIRECTIONAL) || defined(DIRECTIONAL_COOKIE)
    lit = lit * lerp(1.0, atten, _ShadowStrength);
#else
    lit = lit * atten;
#endif
    return half4(lit, s.Alpha);
}

// The main light on a leaf vertex: wrapped diffuse plus translucency, in the light's colour
// (UnityBuiltin3xTreeLibrary.cginc, ShadeTranslucentMainLight).
fixed3 ShadeTranslucentMainLight(float4 vertex, float3 normal)
{
    float3 worldPos = mul(unity_ObjectToWorld, vertex).xyz;
    float3 viewDir = normalize(UnityWorldSpaceViewDir(worldPos));
    float3 lightDir = normalize(UnityWorldSpaceLightDir(worldPos));
    float NdotL = dot(normal, lightDir);
    fixed wrapped = max(0.0, NdotL * 0.6 + 0.4);
    fixed back = PbrlabTreeBackContribution(NdotL, viewDir, lightDir);
    return _LightColor0.rgb * (wrapped + back * _TranslucencyColor);
}

// The ambient on a leaf vertex from both sides, the back side's through the translucency,
// halved since it covers the whole sphere (UnityBuiltin3xTreeLibrary.cginc,
// ShadeTranslucentLights; without Unity's per-vertex point lights, header).
fixed3 ShadeTranslucentLights(float4 vertex, float3 normal)
{
    float3 worldPos = mul(unity_ObjectToWorld, vertex).xyz;
    float3 viewDir = normalize(UnityWorldSpaceViewDir(worldPos));
    float3 mainLightDir = normalize(UnityWorldSpaceLightDir(worldPos));
    float3 frontAmbient = ShadeSH9(float4(normal, 1.0));
    float3 backAmbient = ShadeSH9(float4(-normal, 1.0));
    fixed viewBack = saturate(dot(viewDir, -mainLightDir));
    backAmbient = lerp(backAmbient, backAmbient * viewBack, float3(_TranslucencyViewDependency,
                       _TranslucencyViewDependency, _TranslucencyViewDependency));
    return 0.5 * (frontAmbient + backAmbient * _TranslucencyColor);
}

// The rest pose of a Tree Creator vertex (header), its colour the material's (Unity: times
// the instance colour), normal and tangent renormalised (UnityBuiltin3xTreeLibrary.cginc).
void TreeVertBark(inout appdata_full v)
{
    v.vertex = AnimateVertex(v.vertex, v.normal, float4(v.color.xy, v.texcoord1.xy));
    v.vertex = Squash(v.vertex);
    v.color = float4(_Color.rgb, v.color.a);
    v.normal = normalize(v.normal);
    v.tangent = float4(normalize(v.tangent.xyz), v.tangent.w);
}

void TreeVertLeaf(inout appdata_full v)
{
    TreeVertBark(v);   // Unity also expands billboard leaves first (header)
}

// Unity's 8 x 8 ordered-dither threshold at pixel (x, y): the Bayer index interleaves the
// bits of x ^ y and y, most significant pair first (Bayer 1973; UnityBuiltin3xTreeLibrary.cginc
// tabulates the same 64 values), then fades from limit c0 to 1 as c0 goes 0 -> 1.
float ScreenDitherToAlpha(float x, float y, float c0)
{
    int ix = int(x) & 7;
    int iy = int(y) & 7;
    int d = ix ^ iy;
    int index = ((d & 1) << 5) | ((iy & 1) << 4) | ((d & 2) << 2) | ((iy & 2) << 1) | ((d & 4) >> 1) | ((iy & 4) >> 2);
    float limit = (float(index) + 11.0) / 64.0;
    return lerp(limit * c0, 1.0, c0);
}

float ComputeAlphaCoverage(float4 screenPos, float fadeAmount)
{
    float2 pixel = screenPos.xy / (screenPos.w + 0.00001) * _ScreenParams.xy;
    return ScreenDitherToAlpha(pixel.x, pixel.y, fadeAmount);
}

#endif
