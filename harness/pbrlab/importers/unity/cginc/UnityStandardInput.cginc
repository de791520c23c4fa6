// pbrlab stand-in for Unity's UnityStandardInput.cginc: the Standard shader's material
// inputs, read from its properties.
//
// Provides: the uniforms of Standard.shader / StandardSpecular.shader / AutodeskInteractive
//   (_Color, _Cutoff, _MainTex, _DetailAlbedoMap, _BumpMap, _BumpScale, _DetailMask,
//   _DetailNormalMap, _DetailNormalMapScale, _SpecGlossMap, _MetallicGlossMap, _Metallic,
//   _Glossiness, _GlossMapScale, _OcclusionMap, _OcclusionStrength, _ParallaxMap, _Parallax,
//   _UVSec, _EmissionColor, _EmissionMap, with _MainTex_ST and _DetailAlbedoMap_ST);
//   struct VertexInput (POSITION, NORMAL, TEXCOORD0, TEXCOORD1, TANGENT);
//   float4 TexCoords(VertexInput) (xy: the main UV, zw: the detail UV of set _UVSec);
//   DetailMask, Albedo, Alpha, Occlusion, SpecularGloss, MetallicGloss, MetallicRough,
//   Emission, NormalInTangentSpace (with _NORMALMAP), Parallax.
// Unity's file: the same names and keywords (_DETAIL_MULX2/_MUL/_ADD/_LERP, _NORMALMAP,
//   _SPECGLOSSMAP, _METALLICGLOSSMAP, _SMOOTHNESS_TEXTURE_ALBEDO_CHANNEL_A, _EMISSION,
//   _PARALLAXMAP), read for their behaviour (UnityStandardInput.cginc, Unity 2019.4 built-in
//   shaders) and written here anew.
// Differences: none in what these return; pbrlab's colour space is linear, so
//   unity_ColorSpaceDouble is Unity's linear-space value (the detail map's "x2").
// Cg text in the plain subset harness/pbrlab/importers/unity/port.py ports to GLSL.
#ifndef PBRLAB_UNITY_STANDARD_INPUT_CGINC
#define PBRLAB_UNITY_STANDARD_INPUT_CGINC

#include "UnityStandardConfig.cginc"
#include "UnityStandardUtils.cginc"

// Any of the four detail blend keywords turns the detail layer on (Unity: _DETAIL).
#if defined(_DETAIL_MULX2) || defined(_DETAIL_MUL) || defined(_DETAIL_ADD) || defined(_DETAIL_LERP)
#define _DETAIL 1
#endif

half4 _Color;
half _Cutoff;
sampler2D _MainTex;
float4 _MainTex_ST;
sampler2D _DetailAlbedoMap;
float4 _DetailAlbedoMap_ST;
sampler2D _BumpMap;
half _BumpScale;
sampler2D _DetailMask;
sampler2D _DetailNormalMap;
half _DetailNormalMapScale;
sampler2D _SpecGlossMap;
sampler2D _MetallicGlossMap;
half _Metallic;
float _Glossiness;
float _GlossMapScale;
sampler2D _OcclusionMap;
half _OcclusionStrength;
sampler2D _ParallaxMap;
half _Parallax;
half _UVSec;
half4 _EmissionColor;
sampler2D _EmissionMap;

struct VertexInput
{
    float4 vertex : POSITION;
    half3 normal : NORMAL;
    float2 uv0 : TEXCOORD0;
    float2 uv1 : TEXCOORD1;
    half4 tangent : TANGENT;
};

// The main UV with _MainTex's tiling and offset; the detail UV from the set _UVSec names
// (0: the first, 1: the second), with the detail map's.
float4 TexCoords(VertexInput v)
{
    float2 detailSource = _UVSec == 0.0 ? v.uv0 : v.uv1;
    return float4(TRANSFORM_TEX(v.uv0, _MainTex), TRANSFORM_TEX(detailSource, _DetailAlbedoMap));
}

// Where the detail layer applies: the mask's alpha.
half DetailMask(float2 uv)
{
    return tex2D(_DetailMask, uv).a;
}

// Tint times albedo texture, then the detail layer by its blend keyword, weighted by the mask.
half3 Albedo(float4 texcoords)
{
    half3 albedo = _Color.rgb * tex2D(_MainTex, texcoords.xy).rgb;
#if defined(_DETAIL)
    half mask = DetailMask(texcoords.xy);
    half3 detail = tex2D(_DetailAlbedoMap, texcoords.zw).rgb;
#if defined(_DETAIL_MULX2)
    albedo *= LerpWhiteTo(detail * unity_ColorSpaceDouble.rgb, mask);
#elif defined(_DETAIL_MUL)
    albedo *= LerpWhiteTo(detail, mask);
#elif defined(_DETAIL_ADD)
    albedo += detail * mask;
#else
    albedo = lerp(albedo, detail, mask);
#endif
#endif
    return albedo;
}

// The tint's alpha, times the albedo texture's unless that alpha holds the smoothness.
half Alpha(float2 uv)
{
#if defined(_SMOOTHNESS_TEXTURE_ALBEDO_CHANNEL_A)
    return _Color.a;
#else
    return tex2D(_MainTex, uv).a * _Color.a;
#endif
}

// The occlusion map's green, faded towards 1 by (1 - _OcclusionStrength).
half Occlusion(float2 uv)
{
    return LerpOneTo(tex2D(_OcclusionMap, uv).g, _OcclusionStrength);
}

// The smoothness a map's alpha (or the albedo's alpha) gives, scaled by _GlossMapScale.
half GlossFromMaps(half mapAlpha, float2 uv)
{
#if defined(_SMOOTHNESS_TEXTURE_ALBEDO_CHANNEL_A)
    return tex2D(_MainTex, uv).a * _GlossMapScale;
#else
    return mapAlpha * _GlossMapScale;
#endif
}

// Specular workflow: rgb the specular colour, a the smoothness.
half4 SpecularGloss(float2 uv)
{
#if defined(_SPECGLOSSMAP)
    half4 sg = tex2D(_SpecGlossMap, uv);
    return half4(sg.rgb, GlossFromMaps(sg.a, uv));
#elif defined(_SMOOTHNESS_TEXTURE_ALBEDO_CHANNEL_A)
    return half4(_SpecColor.rgb, tex2D(_MainTex, uv).a * _GlossMapScale);
#else
    return half4(_SpecColor.rgb, _Glossiness);
#endif
}

// Metallic workflow: x the metallic, y the smoothness (the map: metallic in red, smoothness
// in alpha).
half2 MetallicGloss(float2 uv)
{
#if defined(_METALLICGLOSSMAP)
    half4 mg = tex2D(_MetallicGlossMap, uv);
    return half2(mg.r, GlossFromMaps(mg.a, uv));
#elif defined(_SMOOTHNESS_TEXTURE_ALBEDO_CHANNEL_A)
    return half2(_Metallic, tex2D(_MainTex, uv).a * _GlossMapScale);
#else
    return half2(_Metallic, _Glossiness);
#endif
}

// Roughness workflow (AutodeskInteractive): x the metallic, y the smoothness as 1 - roughness
// (the roughness map's red under _SPECGLOSSMAP, else _Glossiness read as a roughness).
half2 MetallicRough(float2 uv)
{
#if defined(_METALLICGLOSSMAP)
    half metallic = tex2D(_MetallicGlossMap, uv).r;
#else
    half metallic = _Metallic;
#endif
#if defined(_SPECGLOSSMAP)
    half roughness = tex2D(_SpecGlossMap, uv).r;
#else
    half roughness = _Glossiness;
#endif
    return half2(metallic, 1.0 - roughness);
}

// Emitted radiance: the emission map times its colour, only with _EMISSION.
half3 Emission(float2 uv)
{
#if defined(_EMISSION)
    return tex2D(_EmissionMap, uv).rgb * _EmissionColor.rgb;
#else
    return half3(0.0, 0.0, 0.0);
#endif
}

#if defined(_NORMALMAP)
// The normal map's tangent-space normal scaled by _BumpScale; the detail normal map blended
// in by the mask (whiteout-style BlendNormals, or a plain lerp with _DETAIL_LERP).
half3 NormalInTangentSpace(float4 texcoords)
{
    half3 normalTangent = UnpackScaleNormal(tex2D(_BumpMap, texcoords.xy), _BumpScale);
#if defined(_DETAIL) && UNITY_ENABLE_DETAIL_NORMALMAP
    half mask = DetailMask(texcoords.xy);
    half3 detailTangent = UnpackScaleNormal(tex2D(_DetailNormalMap, texcoords.zw), _DetailNormalMapScale);
#if defined(_DETAIL_LERP)
    normalTangent = lerp(normalTangent, detailTangent, mask);
#else
    normalTangent = lerp(normalTangent, BlendNormals(normalTangent, detailTangent), mask);
#endif
#endif
    return normalTangent;
}
#endif

// Parallax mapping (_PARALLAXMAP): both UV pairs shifted by one step of the height map's
// green along the tangent-space view direction (ParallaxOffset1Step).
float4 Parallax(float4 texcoords, half3 viewDir)
{
#if defined(_PARALLAXMAP)
    half h = tex2D(_ParallaxMap, texcoords.xy).g;
    float2 offset = ParallaxOffset1Step(h, _Parallax, viewDir);
    return float4(texcoords.xy + offset, texcoords.zw + offset);
#else
    return texcoords;
#endif
}

#endif
