// pbrlab stand-in for URP's ShaderLibrary/GlobalIllumination.hlsl: the ambient probe
// (SampleSH), lightmaps, the reflection probe, GlossyEnvironmentReflection, GlobalIllumination and
// MixRealtimeAndBakedGI. As URP's, it brings BRDF.hlsl and RealtimeLights.hlsl,
// written for pbrlab from Unity's documentation of the names and URP 12's and 14's files read for
// their names (Unity's own files are under the Unity Companion License and are not copied).
#ifndef PBRLAB_URP_GLOBALILLUMINATION_HLSL
#define PBRLAB_URP_GLOBALILLUMINATION_HLSL
#define UNIVERSAL_GLOBAL_ILLUMINATION_INCLUDED

#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/BRDF.hlsl"
#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/RealtimeLights.hlsl"

// URP's mip count for the reflection probe's roughness levels (UNITY_SPECCUBE_LOD_STEPS).
#define PBRLAB_URP_SPECCUBE_LOD_STEPS 6.0

// Ambient light: the environment's SH9 as Unity's ambient probe (irradiance / pi).
float3 SampleSH(float3 normalWS) {
#ifdef PBRLAB_ENV
    return PBR_UNITY_SH_IRRADIANCE(normalWS);
#else
    return float3(0.0, 0.0, 0.0);
#endif
}
float3 SampleSHVertex(float3 normalWS) { return SampleSH(normalWS); }
float3 SampleSHPixel(float3 L2Term, float3 normalWS) { return SampleSH(normalWS); }
// Core RP's EntityLighting.hlsl: the order-2 SH polynomial of Unity's packed coefficients (the
// layout of unity_SHAr..unity_SHC: per channel dot(SHA, (n, 1)) + dot(SHB, n.xyzz * n.yzzx) +
// SHC (n.x^2 - n.y^2)), from coefficients a shader gathers itself (SampleSH9(c[7], n)).
float3 SHEvalLinearL0L1(float3 N, float4 shAr, float4 shAg, float4 shAb) {
    float4 vA = float4(N, 1.0);
    return float3(dot(shAr, vA), dot(shAg, vA), dot(shAb, vA));
}
float3 SHEvalLinearL2(float3 N, float4 shBr, float4 shBg, float4 shBb, float4 shC) {
    float4 vB = N.xyzz * N.yzzx;
    return float3(dot(shBr, vB), dot(shBg, vB), dot(shBb, vB)) + shC.rgb * (N.x * N.x - N.y * N.y);
}
float3 SampleSH9(float4 SHCoefficients[7], float3 N) {
    return SHEvalLinearL0L1(N, SHCoefficients[0], SHCoefficients[1], SHCoefficients[2])
         + SHEvalLinearL2(N, SHCoefficients[3], SHCoefficients[4], SHCoefficients[5], SHCoefficients[6]);
}
// URP's SampleLightmap: the static lightmap's light where LIGHTMAP_ON is set (a lightmapped
// object: its material supplies a `lightmap`, importers/unity/lightmaps.py binds unity_Lightmap,
// unity_Lightmap_HDR and unity_LightmapST and defines the encoding's macro), black otherwise,
// as URP gives then; no realtime GI lightmap here (DYNAMICLIGHTMAP_ON adds nothing). The decode
// is Core's DecodeLightmap (EntityLighting.hlsl) in linear colour space, as URP's
// SampleSingleLightmap calls it for an encoded lightmap with the decode instructions
// (LIGHTMAP_HDR_MULTIPLIER, LIGHTMAP_HDR_EXPONENT): RGBM rgb * (x * a^y), dLDR rgb * x, full HDR
// the texel's rgb. Here x, y are unity_Lightmap_HDR's (lightmaps.ENCODINGS: 34.49 and 2.2 for
// RGBM, 1 and 1 for full HDR as Core's; 2^2.2 = 4.59482 for dLDR, where Core rounds to 4.59).
#if defined(LIGHTMAP_ON)
TEXTURE2D(unity_Lightmap);
SAMPLER(samplerunity_Lightmap);
float4 unity_Lightmap_HDR;
#define LIGHTMAP_HDR_MULTIPLIER unity_Lightmap_HDR.x
#define LIGHTMAP_HDR_EXPONENT unity_Lightmap_HDR.y
float3 DecodeLightmap(float4 encodedIlluminance, float4 decodeInstructions) {
#if defined(UNITY_LIGHTMAP_RGBM_ENCODING)
    return encodedIlluminance.rgb * (decodeInstructions.x * pow(max(encodedIlluminance.a, 0.0), decodeInstructions.y));
#elif defined(UNITY_LIGHTMAP_DLDR_ENCODING)
    return encodedIlluminance.rgb * decodeInstructions.x;
#else
    return encodedIlluminance.rgb;
#endif
}
float3 SampleLightmap(float2 staticLightmapUV, float3 normalWS) {
    return DecodeLightmap(SAMPLE_TEXTURE2D(unity_Lightmap, samplerunity_Lightmap, staticLightmapUV),
                          float4(LIGHTMAP_HDR_MULTIPLIER, LIGHTMAP_HDR_EXPONENT, 0.0, 0.0));
}
float3 SampleLightmap(float2 staticLightmapUV, float2 dynamicLightmapUV, float3 normalWS) {
    return SampleLightmap(staticLightmapUV, normalWS);
}
// The varyings member holds the lightmap UV (the mesh's TEXCOORD1 scaled and offset by
// unity_LightmapST in the vertex stage); SAMPLE_GI reads the lightmap instead of the SH.
#define DECLARE_LIGHTMAP_OR_SH(lmName, shName, index) float2 lmName : TEXCOORD##index
#define OUTPUT_LIGHTMAP_UV(lightmapUV, lightmapScaleOffset, OUT) OUT.xy = lightmapUV.xy * lightmapScaleOffset.xy + lightmapScaleOffset.zw
#define OUTPUT_SH(normalWS, OUT)
#define OUTPUT_SH4(absolutePositionWS, normalWS, viewDir, OUT, OUT_OCCLUSION)
#define OUTPUT_SH4_FOUR_ARGUMENTS(absolutePositionWS, normalWS, viewDir, OUT)
#define SAMPLE_GI(lmName, shName, normalWSName) SampleLightmap(lmName, normalWSName)
#else
float3 SampleLightmap(float2 staticLightmapUV, float3 normalWS) { return float3(0.0, 0.0, 0.0); }
float3 SampleLightmap(float2 staticLightmapUV, float2 dynamicLightmapUV, float3 normalWS) { return float3(0.0, 0.0, 0.0); }
// A varyings member for per-vertex SH: declared without its semantic, since SAMPLE_GI evaluates
// the SH per pixel here (URP's default) and never reads it.
#define DECLARE_LIGHTMAP_OR_SH(lmName, shName, index) float3 shName
#define OUTPUT_LIGHTMAP_UV(lightmapUV, lightmapScaleOffset, OUT)
#define OUTPUT_SH(normalWS, OUT) OUT.xyz = SampleSHVertex(normalWS)
// Unity 6.1's form, with the position and view direction adaptive probe volumes read and the
// probe occlusion they write: pbrlab has no probe volumes, so the ambient probe's SH at the
// normal, as OUTPUT_SH, and the occlusion argument unread (URP writes it only under
// USE_APV_PROBE_OCCLUSION). Unity 6.0's four-argument form, the same SH without the occlusion,
// cannot share the name (no variadic macros in glslang's preprocessor): a four-argument call is
// spelled OUTPUT_SH4_FOUR_ARGUMENTS (cg_spellings).
#define OUTPUT_SH4(absolutePositionWS, normalWS, viewDir, OUT, OUT_OCCLUSION) OUT.xyz = SampleSHVertex(normalWS)
#define OUTPUT_SH4_FOUR_ARGUMENTS(absolutePositionWS, normalWS, viewDir, OUT) OUT.xyz = SampleSHVertex(normalWS)
#define SAMPLE_GI(lmName, shName, normalWSName) SampleSHPixel(shName, normalWSName)
#endif

// URP's mip for a perceptual roughness: pr (1.7 - 0.7 pr) of its 6 levels, in pbrlab's chain.
// The same mip as a number: perceptual roughness pr to pr (1.7 - 0.7 pr) times the steps.
float PerceptualRoughnessToMipmapLevel(float perceptualRoughness) {
    return perceptualRoughness * (1.7 - 0.7 * perceptualRoughness) * PBRLAB_URP_SPECCUBE_LOD_STEPS;
}
// The reflection probe as URP shaders read it themselves: unity_SpecCube0 (and its sampler
// samplerunity_SpecCube0) is the scene environment's prefiltered chain, its mip given in
// Unity's steps (0 mirror .. PBRLAB_URP_SPECCUBE_LOD_STEPS rough), each the same fraction of
// pbrlab's chain (u_env_lod_count levels: level i holds perceptual roughness i / (count - 1));
// black without an environment. unity_SpecCube0_HDR's decode is the identity here (the
// environment is float radiance: multiplier 1, exponent 1). HLSL reads the probe through a
// struct's SampleLevel (the harness's own where it stands), GLSL through the port's spelling of
// SAMPLE_TEXTURECUBE_LOD as the same read, templates/unity_surface.inc's
// pbrlab_unity_reflection_probe (importers/unity/port.py); unity_SpecCube1 (probe blending) is
// not provided.
float4 pbrlab_urp_reflection_probe(float3 direction, float mip) {
#ifdef PBRLAB_ENV
    float lod = mip / PBRLAB_URP_SPECCUBE_LOD_STEPS * (u_env_lod_count - 1.0);
    return float4(PBRLAB_SAMPLE_TEXCUBE_LOD(u_env_prefiltered, direction, lod).rgb, 1.0);
#else
    return float4(0.0, 0.0, 0.0, 1.0);
#endif
}
#if !defined(__VERSION__) && !defined(PBRLAB_UNITY_SPECCUBE0)  // the harness's own (unity_hlsl_support.hlsl) stands
struct PbrlabURPReflectionProbe {
    float unused;
    float4 SampleLevel(SamplerState s, float3 direction, float mip) { return pbrlab_urp_reflection_probe(direction, mip); }
    float4 Sample(SamplerState s, float3 direction) { return pbrlab_urp_reflection_probe(direction, 0.0); }
};
static PbrlabURPReflectionProbe unity_SpecCube0;
SamplerState samplerunity_SpecCube0;
#endif
// A reflection direction corrected for a box-projected probe (URP's GlobalIllumination.hlsl,
// after Lagarde and Zanuttini, "Local Image-based Lighting With Parallax-corrected Cubemap",
// SIGGRAPH 2012): where the probe's position has w > 0, the ray from positionWS along the
// direction meets the box [boxMin, boxMax] at the nearest of its three exit planes' distances,
// and the direction from the probe's centre to that point is returned; where w is 0 (box
// projection off, as for the sky's probe here: unity_compat/shader_variables) the direction as given.
float3 BoxProjectedCubemapDirection(float3 reflectionWS, float3 positionWS, float4 cubemapPositionWS,
                                    float4 boxMin, float4 boxMax) {
    if (cubemapPositionWS.w > 0.0) {
        // the max plane along a positive component, the min plane along a negative one
        float3 exits = (lerp(boxMin.xyz, boxMax.xyz, step(0.0, reflectionWS)) - positionWS) / reflectionWS;
        float distance = min(min(exits.x, exits.y), exits.z);
        return positionWS - cubemapPositionWS.xyz + reflectionWS * distance;
    }
    return reflectionWS;
}
// Unity's HDR decode of a probe texel: instructions.x * alpha^instructions.y * rgb, alpha
// the texel's when instructions.w is 1 (else 1).
float3 DecodeHDREnvironment(float4 encodedIrradiance, float4 decodeInstructions) {
    float alpha = max(decodeInstructions.w * (encodedIrradiance.a - 1.0) + 1.0, 0.0);
    return (decodeInstructions.x * pow(abs(alpha), decodeInstructions.y)) * encodedIrradiance.rgb;
}

float3 GlossyEnvironmentReflection(float3 reflectVector, float perceptualRoughness, float occlusion) {
#ifdef PBRLAB_ENV
    return PBR_UNITY_GLOSSY_ENVIRONMENT(reflectVector, perceptualRoughness) * occlusion;
#else
    return float3(0.0, 0.0, 0.0);
#endif
}
float3 GlossyEnvironmentReflection(float3 reflectVector, float3 positionWS, float perceptualRoughness, float occlusion) {
    return GlossyEnvironmentReflection(reflectVector, perceptualRoughness, occlusion);
}

float3 GlobalIllumination(BRDFData brdfData, float3 bakedGI, float occlusion, float3 positionWS, float3 normalWS,
                          float3 viewDirectionWS) {
    float3 reflectVector = reflect(-viewDirectionWS, normalWS);
    float NoV = saturate(dot(normalWS, viewDirectionWS));
    float fresnelTerm = Pow4(1.0 - NoV);
    float3 indirectDiffuse = bakedGI;
    float3 indirectSpecular = GlossyEnvironmentReflection(reflectVector, positionWS, brdfData.perceptualRoughness, 1.0);
    return EnvironmentBRDF(brdfData, indirectDiffuse, indirectSpecular, fresnelTerm) * occlusion;
}
float3 GlobalIllumination(BRDFData brdfData, float3 bakedGI, float occlusion, float3 normalWS, float3 viewDirectionWS) {
    return GlobalIllumination(brdfData, bakedGI, occlusion, float3(0.0, 0.0, 0.0), normalWS, viewDirectionWS);
}

// Baked lighting mixed with the realtime main light: only with lightmaps (none here).
void MixRealtimeAndBakedGI(inout Light light, float3 normalWS, inout float3 bakedGI) {}
void MixRealtimeAndBakedGI(inout Light light, float3 normalWS, inout float3 bakedGI, float4 shadowMask) {}

// URP 14's GlobalIllumination.hlsl overload: the baked light darkened by the indirect factor
// (then mixed with the realtime main light, which needs lightmaps: nothing more here).
void MixRealtimeAndBakedGI(inout Light light, float3 normalWS, inout float3 bakedGI, AmbientOcclusionFactor aoFactor) {
    bakedGI *= aoFactor.indirectAmbientOcclusion;
    MixRealtimeAndBakedGI(light, normalWS, bakedGI);
}

#endif
