// pbrlab stand-in for URP 12's Shaders/Terrain/TerrainLitInput.hlsl: the Terrain Lit material's
// inputs as a custom terrain shader reads them (written for pbrlab from the names of URP 12's
// file; Unity's own file is under the Unity Companion License and is not copied). The control map
// _Control (a texel's rgba: the weights of layers 0..3), the layers' maps _Splat0.._Splat3 (one
// sampler, sampler_Splat0), _Normal0..3 (under _NORMALMAP) and _Mask0..3 (under _MASKMAP), their
// per-layer scalars and _ST, the base map _MainTex / _MetallicTex, and the functions
// SampleMetallicSpecGloss, InitializeStandardLitSurfaceData, TerrainInstancing and (with
// _ALPHATEST_ON) ClipHoles. pbrlab draws a terrain shader on its scene's mesh as a material:
// each of these takes the material's value (its Properties' defaults where the material gives
// none), as Unity's Terrain component sets them from its layers. Instanced terrain
// (UNITY_INSTANCING_ENABLED: the heightmap patches _TerrainHeightmapTexture,
// _TerrainNormalmapTexture, _TerrainPatchInstanceData) is not drawn: TerrainInstancing leaves the
// vertex as it is, as URP's does without instancing. The passes (TerrainLitPasses.hlsl) are refused.
#ifndef PBRLAB_URP_TERRAIN_LIT_INPUT_HLSL
#define PBRLAB_URP_TERRAIN_LIT_INPUT_HLSL
#define UNIVERSAL_TERRAIN_LIT_INPUT_INCLUDED

#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
#include "Packages/com.unity.render-pipelines.core/ShaderLibrary/CommonMaterial.hlsl"
#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/SurfaceInput.hlsl"

float4 _MainTex_ST;
float4 _BaseColor;
float _Cutoff;

#define _Surface 0.0  // a terrain is opaque (URP 12)

float _NormalScale0, _NormalScale1, _NormalScale2, _NormalScale3;
float _Metallic0, _Metallic1, _Metallic2, _Metallic3;
float _Smoothness0, _Smoothness1, _Smoothness2, _Smoothness3;
float4 _DiffuseRemapScale0, _DiffuseRemapScale1, _DiffuseRemapScale2, _DiffuseRemapScale3;
float4 _MaskMapRemapOffset0, _MaskMapRemapOffset1, _MaskMapRemapOffset2, _MaskMapRemapOffset3;
float4 _MaskMapRemapScale0, _MaskMapRemapScale1, _MaskMapRemapScale2, _MaskMapRemapScale3;
float4 _Control_ST;
float4 _Control_TexelSize;
float _DiffuseHasAlpha0, _DiffuseHasAlpha1, _DiffuseHasAlpha2, _DiffuseHasAlpha3;
float _LayerHasMask0, _LayerHasMask1, _LayerHasMask2, _LayerHasMask3;
float4 _Splat0_ST, _Splat1_ST, _Splat2_ST, _Splat3_ST;
float _HeightTransition;
float _NumLayersCount;

TEXTURE2D(_Control);
SAMPLER(sampler_Control);
TEXTURE2D(_Splat0);
SAMPLER(sampler_Splat0);
TEXTURE2D(_Splat1);
TEXTURE2D(_Splat2);
TEXTURE2D(_Splat3);
#ifdef _NORMALMAP
TEXTURE2D(_Normal0);
SAMPLER(sampler_Normal0);
TEXTURE2D(_Normal1);
TEXTURE2D(_Normal2);
TEXTURE2D(_Normal3);
#endif
#ifdef _MASKMAP
TEXTURE2D(_Mask0);
SAMPLER(sampler_Mask0);
TEXTURE2D(_Mask1);
TEXTURE2D(_Mask2);
TEXTURE2D(_Mask3);
#endif
TEXTURE2D(_MainTex);
SAMPLER(sampler_MainTex);
TEXTURE2D(_SpecGlossMap);
SAMPLER(sampler_SpecGlossMap);
TEXTURE2D(_MetallicTex);
SAMPLER(sampler_MetallicTex);

#ifdef UNITY_INSTANCING_ENABLED
#error "URP's instanced terrain (UNITY_INSTANCING_ENABLED: the heightmap patches _TerrainHeightmapTexture, _TerrainNormalmapTexture and _TerrainPatchInstanceData, which Unity's Terrain component sets) is not provided by pbrlab's stand-in"
#endif

#ifdef _ALPHATEST_ON
// The terrain's holes: a texel of 0 in _TerrainHolesTexture cuts the pixel away.
TEXTURE2D(_TerrainHolesTexture);
SAMPLER(sampler_TerrainHolesTexture);
void ClipHoles(float2 uv) {
    float hole = SAMPLE_TEXTURE2D(_TerrainHolesTexture, sampler_TerrainHolesTexture, uv).r;
    clip(hole == 0.0 ? -1.0 : 1.0);
}
#endif

// The base map's metallic texel with the albedo's alpha as smoothness.
float4 SampleMetallicSpecGloss(float2 uv, float albedoAlpha) {
    float4 specGloss = SAMPLE_TEXTURE2D(_MetallicTex, sampler_MetallicTex, uv);
    specGloss.a = albedoAlpha;
    return specGloss;
}

// The base map's surface (the terrain seen far away): albedo _MainTex.rgb, smoothness its alpha,
// metallic _MetallicTex.r, the normal map's normal (SurfaceInput.hlsl's SampleNormal), opaque.
void InitializeStandardLitSurfaceData(float2 uv, out SurfaceData outSurfaceData) {
    outSurfaceData = (SurfaceData)0;
    float4 albedoSmoothness = SAMPLE_TEXTURE2D(_MainTex, sampler_MainTex, uv);
    float4 specGloss = SampleMetallicSpecGloss(uv, albedoSmoothness.a);
    outSurfaceData.alpha = 1.0;
    outSurfaceData.albedo = albedoSmoothness.rgb;
    outSurfaceData.metallic = specGloss.r;
    outSurfaceData.specular = float3(0.0, 0.0, 0.0);
    outSurfaceData.smoothness = specGloss.a;
    outSurfaceData.normalTS = SampleNormal(uv, TEXTURE2D_ARGS(_BumpMap, sampler_BumpMap));
    outSurfaceData.occlusion = 1.0;
    outSurfaceData.emission = float3(0.0, 0.0, 0.0);
}

// Without instancing URP's leaves the vertex as it is (its body is under UNITY_INSTANCING_ENABLED).
void TerrainInstancing(inout float4 positionOS, inout float3 normal, inout float2 uv) {}
void TerrainInstancing(inout float4 positionOS, inout float3 normal) {}

#endif
