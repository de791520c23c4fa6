// pbrlab stand-in for the Universal Render Pipeline's ShaderLibrary/Lighting.hlsl (and the
// BRDF.hlsl, GlobalIllumination.hlsl, RealtimeLights.hlsl and Input.hlsl it brings): URP's
// lights, its physically based model (UniversalFragmentPBR) and its ambient and reflection
// light, written for pbrlab from Unity's documentation of the names and the model's formulas
// (URP's own files are under the Unity Companion License and are not copied). The float64
// transcription of the same model is pbrlab.maths.reference.urp_brdf; tests/importers/urp/
// checks a render against it.
//
// Lights: the scene's. The main light is its first directional light (none: black); the
// additional lights are its other directional lights, then its point lights, then its spot
// lights, each with the scene's distance window and cone (URP's smooth range factor and
// angle attenuation are the same functions as glTF's, pbr_distance_attenuation and
// pbr_spot_attenuation). No shadow maps: shadowAttenuation is 1. Ambient light: the
// scene environment's SH9 (SampleSH); reflections: its prefiltered radiance at URP's mip for
// the perceptual roughness (black without an environment).
#ifndef PBRLAB_URP_LIGHTING_HLSL
#define PBRLAB_URP_LIGHTING_HLSL

// URP 14's Shadows.hlsl (which its Lighting.hlsl brings) asks every lit pass for the world
// position varying: a pass copied from URP's Lit reads input.positionWS under this name.
#ifndef REQUIRES_WORLD_SPACE_POS_INTERPOLATOR
#define REQUIRES_WORLD_SPACE_POS_INTERPOLATOR 1
#endif

#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/RenderingLayers.hlsl"
#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/SurfaceData.hlsl"
#include "Packages/com.unity.render-pipelines.core/ShaderLibrary/CommonMaterial.hlsl"
// URP 12+'s Lighting.hlsl includes Debug/Debugging3D.hlsl, which includes DebuggingCommon.hlsl
#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Debug/DebuggingCommon.hlsl"

#define UNIVERSAL_LIGHTING_INCLUDED
// URP's dielectric F0 and 1 - F0 (kDielectricSpec: 0.04 in linear space).
#define kDielectricSpec float4(0.04, 0.04, 0.04, 1.0 - 0.04)
// The name URP 7 to 10 spelled it with (kDieletricSpec), which shaders of that time use.
#define kDieletricSpec kDielectricSpec
// URP's mip count for the reflection probe's roughness levels (UNITY_SPECCUBE_LOD_STEPS).
#define PBRLAB_URP_SPECCUBE_LOD_STEPS 6.0

struct Light {
    float3 direction;            // unit, from the shaded point to the light
    float3 color;
    float distanceAttenuation;   // the distance window (and a spot's cone), 1 for directional
    float shadowAttenuation;     // 1: no shadow maps here
    uint layerMask;
};

Light pbrlab_urp_no_light() {
    Light light;
    light.direction = float3(0.0, 0.0, 1.0);
    light.color = float3(0.0, 0.0, 0.0);
    light.distanceAttenuation = 0.0;
    light.shadowAttenuation = 1.0;
    light.layerMask = 0xFFFFFFFFu;
    return light;
}

Light GetMainLight() {
    Light light = pbrlab_urp_no_light();
#if PBRLAB_DIRECTIONAL_COUNT > 0
    light.direction = -u_directional_direction[0];
    light.color = u_directional_radiance[0];
    light.distanceAttenuation = 1.0;
#endif
    return light;
}
Light GetMainLight(float4 shadowCoord) { return GetMainLight(); }
Light GetMainLight(float4 shadowCoord, float3 positionWS, float4 shadowMask) { return GetMainLight(); }
// A scalar shadow mask (GetMainLight(coord, positionWS, 1)): FXC splats a scalar to the half4
// parameter (HLSL's scalar-to-vector promotion); GLSL converts no scalar to a vector, so this
// overload takes it (the mask is unread here, as above).
Light GetMainLight(float4 shadowCoord, float3 positionWS, float shadowMask) { return GetMainLight(); }

int GetAdditionalLightsCount() {
    int count = PBRLAB_POINT_COUNT + PBRLAB_SPOT_COUNT;
#if PBRLAB_DIRECTIONAL_COUNT > 1
    count += PBRLAB_DIRECTIONAL_COUNT - 1;
#endif
    return count;
}

Light pbrlab_urp_positional(float3 position, float3 radiance, float range, float3 positionWS) {
    Light light = pbrlab_urp_no_light();
    float3 toLight = position - positionWS;
    float d2 = dot(toLight, toLight);
    light.direction = toLight * rsqrt(max(d2, PBR_MIN_LIGHT_DISTANCE_SQUARED));
    light.color = radiance;
    light.distanceAttenuation = pbr_distance_attenuation(d2, range);
    return light;
}

Light GetAdditionalLight(uint i, float3 positionWS) {
    int index = int(i);
#if PBRLAB_DIRECTIONAL_COUNT > 1
    if (index < PBRLAB_DIRECTIONAL_COUNT - 1) {
        Light light = pbrlab_urp_no_light();
        light.direction = -u_directional_direction[index + 1];
        light.color = u_directional_radiance[index + 1];
        light.distanceAttenuation = 1.0;
        return light;
    }
    index -= PBRLAB_DIRECTIONAL_COUNT - 1;
#endif
#if PBRLAB_POINT_COUNT > 0
    if (index < PBRLAB_POINT_COUNT)
        return pbrlab_urp_positional(u_point_position[index], u_point_radiance[index], u_point_range[index], positionWS);
    index -= PBRLAB_POINT_COUNT;
#endif
#if PBRLAB_SPOT_COUNT > 0
    if (index < PBRLAB_SPOT_COUNT) {
        Light light = pbrlab_urp_positional(u_spot_position[index], u_spot_radiance[index], u_spot_range[index], positionWS);
        light.distanceAttenuation *= pbr_spot_attenuation(light.direction, u_spot_direction[index],
                                                          u_spot_cone[index].x, u_spot_cone[index].y);
        return light;
    }
#endif
    return pbrlab_urp_no_light();
}
Light GetAdditionalLight(uint i, float3 positionWS, float4 shadowMask) { return GetAdditionalLight(i, positionWS); }
// Shadows (Shadows.hlsl's names): no shadow maps here, so every light is unshadowed (1).
float MainLightRealtimeShadow(float4 shadowCoord) { return 1.0; }
// The main light's shadow map and the parameters URP's SampleShadowmap reads (URP 12's
// ShadowSamplingData: the soft-shadow tap offsets and the map's size; _MainLightShadowParams:
// strength, soft flag, fade scale and bias). No shadow map here: every texel of it would read
// lit (1), so SampleShadowmap's attenuation, lerp(1, map, strength), is 1 for any strength (the
// main light's is 0, as URP's with shadows off).
// The maps are declared as URP's Shadows.hlsl declares them, depth textures with comparison
// samplers (TEXTURE2D_SHADOW, SAMPLER_CMP), so a program's own SAMPLE_TEXTURE2D_SHADOW of them
// compiles; pbrlab binds each to URP's empty shadow map (importers/unity/shadow_maps.py: one
// texel at the far plane's depth, which every comparison passes: 1, lit), what URP binds while
// no light casts shadows.
struct ShadowSamplingData {
    float4 shadowOffset0;
    float4 shadowOffset1;
    float4 shadowOffset2;
    float4 shadowOffset3;
    float4 shadowmapSize;
};
TEXTURE2D_SHADOW(_MainLightShadowmapTexture);
SAMPLER_CMP(sampler_MainLightShadowmapTexture);
TEXTURE2D_SHADOW(_AdditionalLightsShadowmapTexture);
SAMPLER_CMP(sampler_AdditionalLightsShadowmapTexture);
ShadowSamplingData GetMainLightShadowSamplingData() {
    ShadowSamplingData data;
    data.shadowOffset0 = float4(0.0, 0.0, 0.0, 0.0);
    data.shadowOffset1 = float4(0.0, 0.0, 0.0, 0.0);
    data.shadowOffset2 = float4(0.0, 0.0, 0.0, 0.0);
    data.shadowOffset3 = float4(0.0, 0.0, 0.0, 0.0);
    data.shadowmapSize = float4(1.0, 1.0, 1.0, 1.0);
    return data;
}
float4 GetMainLightShadowParams() { return float4(0.0, 0.0, 0.0, 0.0); }
// URP's test for a shadow coordinate outside the shadow map's depth range (beyond the shadow
// distance: lit), z at or before the near end or at or past the far end of [0, 1].
// SampleShadowmap reads the map it is given as URP's does: the coordinate divided by w for a
// perspective (spot) projection, one hardware comparison (URP's soft-shadow taps read the same
// map around it: the empty map passes them all alike), the result moved towards 1 by 1 - strength
// (shadowParams.x), and 1 beyond the map's depth range (BEYOND_SHADOW_FAR). It samples the map so
// that spirv-cross types the texture a caller passes on as a comparison sampler everywhere.
#define BEYOND_SHADOW_FAR(shadowCoord) ((shadowCoord).z <= 0.0 || (shadowCoord).z >= 1.0)
float SampleShadowmap(TEXTURE2D_SHADOW_PARAM(ShadowMap, sampler_ShadowMap), float4 shadowCoord, ShadowSamplingData samplingData,
                      float4 shadowParams, bool isPerspectiveProjection) {
    if (isPerspectiveProjection)
        shadowCoord.xyz /= shadowCoord.w;
    float attenuation = SAMPLE_TEXTURE2D_SHADOW(ShadowMap, sampler_ShadowMap, shadowCoord.xyz);
    attenuation = 1.0 + (attenuation - 1.0) * shadowParams.x;
    return BEYOND_SHADOW_FAR(shadowCoord) ? 1.0 : attenuation;
}
float MainLightShadow(float4 shadowCoord, float3 positionWS, float4 shadowMask, float4 occlusionProbeChannels) { return 1.0; }
// The main light's channel of the baked shadow mask (URP's _MainLightOcclusionProbes, a one-hot
// mask URP sets for a light with baked occlusion): none here, a realtime light's (0, 0, 0, 0).
#define _MainLightOcclusionProbes float4(0.0, 0.0, 0.0, 0.0)
float AdditionalLightRealtimeShadow(int lightIndex, float3 positionWS) { return 1.0; }
float AdditionalLightRealtimeShadow(int lightIndex, float3 positionWS, float3 lightDirection) { return 1.0; }
float AdditionalLightShadow(int lightIndex, float3 positionWS, float3 lightDirection, float4 shadowMask,
                            float4 occlusionProbeChannels) { return 1.0; }
// URP 10's form, before the light's direction was a parameter.
float AdditionalLightShadow(int lightIndex, float3 positionWS, float4 shadowMask, float4 occlusionProbeChannels) {
    return 1.0;
}
float4 GetShadowCoord(VertexPositionInputs vertexInput) { return float4(0.0, 0.0, 0.0, 0.0); }
float3 ApplyShadowBias(float3 positionWS, float3 normalWS, float3 lightDirection) { return positionWS; }

// URP's per-object light list: the i-th additional light is the scene's i-th here (every
// light reaches every object), so the index is i and the light is GetAdditionalLight's.
int GetPerObjectLightIndex(uint index) { return int(index); }
Light GetAdditionalPerObjectLight(int perObjectLightIndex, float3 positionWS) {
    return GetAdditionalLight(uint(perObjectLightIndex), positionWS);
}

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
// URP's indirect specular where a shader's glossy reflections are off (Input.hlsl's
// _GlossyEnvironmentColor): URP sets it to the ambient probe's constant (L0) term times the
// reflection intensity (1 here), which is the probe's mean over all directions: the Unity
// prelude's Unity_LightmodelAmbient() (black without an environment).
#define _GlossyEnvironmentColor Unity_LightmodelAmbient()
// The probes' baked occlusion of the shadow mask: none here (every channel 1).
#define unity_ProbesOcclusion float4(1.0, 1.0, 1.0, 1.0)
// The mesh's rendering layers, as RenderingLayers.hlsl's GetMeshRenderingLayer (every layer).
uint GetMeshRenderingLightLayer() { return 0xFFFFFFFFu; }

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

struct InputData {
    float3 positionWS;
    float4 positionCS;
    float3 normalWS;
    float3 viewDirectionWS;
    float4 shadowCoord;
    float fogCoord;
    float3 vertexLighting;
    float3 bakedGI;
    float2 normalizedScreenSpaceUV;
    float4 shadowMask;
    float3x3 tangentToWorld;
};

struct BRDFData {
    float3 albedo;
    float3 diffuse;
    float3 specular;
    float reflectivity;
    float perceptualRoughness;
    float roughness;
    float roughness2;
    float grazingTerm;
    float normalizationTerm;    // roughness * 4 + 2
    float roughness2MinusOne;   // roughness^2 - 1
};

float OneMinusReflectivityMetallic(float metallic) { return kDielectricSpec.a - metallic * kDielectricSpec.a; }
float ReflectivitySpecular(float3 specular) { return max(max(specular.r, specular.g), specular.b); }

// URP's BRDF setup: diffuse and F0 from the workflow; roughness = (1 - smoothness)^2 floored
// at HALF_MIN_SQRT, its square at HALF_MIN; premultiplied alpha scales the diffuse.
void InitializeBRDFDataDirect(float3 albedo, float3 diffuse, float3 specular, float reflectivity,
                              float oneMinusReflectivity, float smoothness, inout float alpha, out BRDFData outBRDFData) {
    outBRDFData.albedo = albedo;
    outBRDFData.diffuse = diffuse;
    outBRDFData.specular = specular;
    outBRDFData.reflectivity = reflectivity;
    outBRDFData.perceptualRoughness = 1.0 - smoothness;
    outBRDFData.roughness = max(outBRDFData.perceptualRoughness * outBRDFData.perceptualRoughness, HALF_MIN_SQRT);
    outBRDFData.roughness2 = max(outBRDFData.roughness * outBRDFData.roughness, HALF_MIN);
    outBRDFData.grazingTerm = saturate(smoothness + reflectivity);
    outBRDFData.normalizationTerm = outBRDFData.roughness * 4.0 + 2.0;
    outBRDFData.roughness2MinusOne = outBRDFData.roughness2 - 1.0;
#ifdef _ALPHAPREMULTIPLY_ON
    outBRDFData.diffuse *= alpha;
    alpha = alpha * oneMinusReflectivity + reflectivity;
#endif
}

void InitializeBRDFData(float3 albedo, float metallic, float3 specular, float smoothness, inout float alpha,
                        out BRDFData outBRDFData) {
#ifdef _SPECULAR_SETUP
    float reflectivity = ReflectivitySpecular(specular);
    float oneMinusReflectivity = 1.0 - reflectivity;
    float3 brdfDiffuse = albedo * (float3(1.0, 1.0, 1.0) - specular);
    float3 brdfSpecular = specular;
#else
    float oneMinusReflectivity = OneMinusReflectivityMetallic(metallic);
    float reflectivity = 1.0 - oneMinusReflectivity;
    float3 brdfDiffuse = albedo * oneMinusReflectivity;
    float3 brdfSpecular = lerp(kDielectricSpec.rgb, albedo, metallic);
#endif
    InitializeBRDFDataDirect(albedo, brdfDiffuse, brdfSpecular, reflectivity, oneMinusReflectivity, smoothness,
                             alpha, outBRDFData);
}

void InitializeBRDFData(inout SurfaceData surfaceData, out BRDFData brdfData) {
    InitializeBRDFData(surfaceData.albedo, surfaceData.metallic, surfaceData.specular, surfaceData.smoothness,
                       surfaceData.alpha, brdfData);
}

// URP's direct specular: D * V * F folded into r^2 / ((d^2) max(0.1, LdotH^2) (4r + 2)), with
// d = NdotH^2 (r^2 - 1) + 1.00001 (Unity, "Optimizing PBR for mobile", Siggraph 2015).
float DirectBRDFSpecular(BRDFData brdfData, float3 normalWS, float3 lightDirectionWS, float3 viewDirectionWS) {
    float3 halfDir = SafeNormalize(lightDirectionWS + viewDirectionWS);
    float NoH = saturate(dot(normalWS, halfDir));
    float LoH = saturate(dot(lightDirectionWS, halfDir));
    float d = NoH * NoH * brdfData.roughness2MinusOne + 1.00001;
    float LoH2 = LoH * LoH;
    return brdfData.roughness2 / ((d * d) * max(0.1, LoH2) * brdfData.normalizationTerm);
}

float3 LightingPhysicallyBased(BRDFData brdfData, float3 lightColor, float3 lightDirectionWS, float lightAttenuation,
                               float3 normalWS, float3 viewDirectionWS) {
    float NdotL = saturate(dot(normalWS, lightDirectionWS));
    float3 radiance = lightColor * (lightAttenuation * NdotL);
    float3 brdf = brdfData.diffuse;
    brdf += brdfData.specular * DirectBRDFSpecular(brdfData, normalWS, lightDirectionWS, viewDirectionWS);
    return brdf * radiance;
}

float3 LightingPhysicallyBased(BRDFData brdfData, Light light, float3 normalWS, float3 viewDirectionWS) {
    return LightingPhysicallyBased(brdfData, light.color, light.direction,
                                   light.distanceAttenuation * light.shadowAttenuation, normalWS, viewDirectionWS);
}

// URP's environment BRDF: (1 / (roughness^2 + 1)) lerp(F0, grazing, (1 - NdotV)^4).
float3 EnvironmentBRDFSpecular(BRDFData brdfData, float fresnelTerm) {
    float surfaceReduction = 1.0 / (brdfData.roughness2 + 1.0);
    return surfaceReduction * lerp(brdfData.specular, float3(brdfData.grazingTerm, brdfData.grazingTerm, brdfData.grazingTerm), fresnelTerm);
}

float3 EnvironmentBRDF(BRDFData brdfData, float3 indirectDiffuse, float3 indirectSpecular, float fresnelTerm) {
    float3 c = indirectDiffuse * brdfData.diffuse;
    c += indirectSpecular * EnvironmentBRDFSpecular(brdfData, fresnelTerm);
    return c;
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

float3 LightingLambert(float3 lightColor, float3 lightDir, float3 normal) {
    return lightColor * saturate(dot(normal, lightDir));
}

// Per-vertex additional lights (_ADDITIONAL_LIGHTS_VERTEX): their Lambert sum, else black.
float3 VertexLighting(float3 positionWS, float3 normalWS) {
    float3 vertexLightColor = float3(0.0, 0.0, 0.0);
#ifdef _ADDITIONAL_LIGHTS_VERTEX
    int lightCount = GetAdditionalLightsCount();
    for (int lightIndex = 0; lightIndex < lightCount; ++lightIndex) {
        Light light = GetAdditionalLight(uint(lightIndex), positionWS);
        vertexLightColor += LightingLambert(light.color * light.distanceAttenuation, light.direction, normalWS);
    }
#endif
    return vertexLightColor;
}

// Baked lighting mixed with the realtime main light: only with lightmaps (none here).
void MixRealtimeAndBakedGI(inout Light light, float3 normalWS, inout float3 bakedGI) {}
void MixRealtimeAndBakedGI(inout Light light, float3 normalWS, inout float3 bakedGI, float4 shadowMask) {}

// AmbientOcclusion.hlsl's names (URP 14's Lighting.hlsl brings that file): the factor a pixel's
// lights and baked light are darkened by. Screen-space ambient occlusion is off here (no
// _SCREEN_SPACE_OCCLUSION keyword, no SSAO texture), so URP 14's screen-space factor is 1 for
// both the direct and the indirect light, and CreateAmbientOcclusionFactor's indirect factor is
// min(1, the material's occlusion).
struct AmbientOcclusionFactor {
    float indirectAmbientOcclusion;   // multiplies the baked (ambient) light
    float directAmbientOcclusion;     // multiplies the realtime lights (with SSAO on only)
};

// The SSAO texture's value at a screen position: no SSAO pass here, so unoccluded (1).
float SampleAmbientOcclusion(float2 normalizedScreenSpaceUV) { return 1.0; }

// SSAO's factors at a screen position; without _SCREEN_SPACE_OCCLUSION both are 1 in URP 14.
AmbientOcclusionFactor GetScreenSpaceAmbientOcclusion(float2 normalizedScreenSpaceUV) {
    AmbientOcclusionFactor aoFactor;
    aoFactor.indirectAmbientOcclusion = 1.0;
    aoFactor.directAmbientOcclusion = 1.0;
    return aoFactor;
}

// The screen-space factors with the material's occlusion folded into the indirect one (the
// smaller of the two wins, as in URP 14).
AmbientOcclusionFactor CreateAmbientOcclusionFactor(float2 normalizedScreenSpaceUV, float occlusion) {
    AmbientOcclusionFactor aoFactor = GetScreenSpaceAmbientOcclusion(normalizedScreenSpaceUV);
    aoFactor.indirectAmbientOcclusion = min(aoFactor.indirectAmbientOcclusion, occlusion);
    return aoFactor;
}

AmbientOcclusionFactor CreateAmbientOcclusionFactor(InputData inputData, SurfaceData surfaceData) {
    return CreateAmbientOcclusionFactor(inputData.normalizedScreenSpaceUV, surfaceData.occlusion);
}

// URP 14's RealtimeLights.hlsl overloads that take the factor: the light as without it (the
// direct factor darkens a light only with SSAO on).
Light GetMainLight(InputData inputData, float4 shadowMask, AmbientOcclusionFactor aoFactor) {
    return GetMainLight(inputData.shadowCoord, inputData.positionWS, shadowMask);
}
Light GetAdditionalLight(uint i, InputData inputData, float4 shadowMask, AmbientOcclusionFactor aoFactor) {
    return GetAdditionalLight(i, inputData.positionWS, shadowMask);
}

// URP 14's GlobalIllumination.hlsl overload: the baked light darkened by the indirect factor
// (then mixed with the realtime main light, which needs lightmaps: nothing more here).
void MixRealtimeAndBakedGI(inout Light light, float3 normalWS, inout float3 bakedGI, AmbientOcclusionFactor aoFactor) {
    bakedGI *= aoFactor.indirectAmbientOcclusion;
    MixRealtimeAndBakedGI(light, normalWS, bakedGI);
}

// Blinn-Phong's highlight: colour * specular * NdotH^smoothness (smoothness here the exponent).
float3 LightingSpecular(float3 lightColor, float3 lightDir, float3 normal, float3 viewDir, float4 specular, float smoothness) {
    float3 halfVec = SafeNormalize(lightDir + viewDir);
    float NdotH = saturate(dot(normal, halfVec));
    return lightColor * (specular.rgb * pow(NdotH, smoothness));
}

// SimpleLit's light: Lambert's diffuse times the albedo, plus the highlight where the material
// has one (_SPECGLOSSMAP or _SPECULAR_COLOR), its exponent exp2(10 smoothness + 1).
float3 CalculateBlinnPhong(Light light, InputData inputData, SurfaceData surfaceData) {
    float3 attenuatedLightColor = light.color * (light.distanceAttenuation * light.shadowAttenuation);
    float3 lightDiffuseColor = LightingLambert(attenuatedLightColor, light.direction, inputData.normalWS);
    float3 lightSpecularColor = float3(0.0, 0.0, 0.0);
#if defined(_SPECGLOSSMAP) || defined(_SPECULAR_COLOR)
    float exponent = exp2(10.0 * surfaceData.smoothness + 1.0);
    lightSpecularColor += LightingSpecular(attenuatedLightColor, light.direction, inputData.normalWS,
                                           inputData.viewDirectionWS, float4(surfaceData.specular, 1.0), exponent);
#endif
#ifdef _ALPHAPREMULTIPLY_ON
    return lightDiffuseColor * surfaceData.albedo * surfaceData.alpha + lightSpecularColor;
#else
    return lightDiffuseColor * surfaceData.albedo + lightSpecularColor;
#endif
}

// SimpleLit's pixel: the ambient light times the albedo, every light's Blinn-Phong, emission.
float4 UniversalFragmentBlinnPhong(InputData inputData, SurfaceData surfaceData) {
    float3 color = inputData.bakedGI * surfaceData.albedo;
    color += CalculateBlinnPhong(GetMainLight(inputData.shadowCoord, inputData.positionWS, inputData.shadowMask),
                                 inputData, surfaceData);
#ifdef _ADDITIONAL_LIGHTS
    int lightCount = GetAdditionalLightsCount();
    for (int lightIndex = 0; lightIndex < lightCount; ++lightIndex) {
        color += CalculateBlinnPhong(GetAdditionalLight(uint(lightIndex), inputData.positionWS, inputData.shadowMask),
                                     inputData, surfaceData);
    }
#endif
    color += surfaceData.emission;
    return float4(color, surfaceData.alpha);
}

float4 UniversalFragmentBlinnPhong(InputData inputData, float3 diffuse, float4 specularGloss, float smoothness,
                                   float3 emission, float alpha, float3 normalTS) {
    SurfaceData s;
    s.albedo = diffuse;
    s.specular = specularGloss.rgb;
    s.metallic = 0.0;
    s.smoothness = smoothness;
    s.normalTS = normalTS;
    s.emission = emission;
    s.occlusion = 1.0;
    s.alpha = alpha;
    s.clearCoatMask = 0.0;
    s.clearCoatSmoothness = 1.0;
    return UniversalFragmentBlinnPhong(inputData, s);
}

float4 UniversalFragmentBlinnPhong(InputData inputData, float3 diffuse, float4 specularGloss, float smoothness,
                                   float3 emission, float alpha) {
    return UniversalFragmentBlinnPhong(inputData, diffuse, specularGloss, smoothness, emission, alpha,
                                       float3(0.0, 0.0, 1.0));
}

// Clustered (Forward+) light lists: none here; the additional lights are one loop over
// GetAdditionalLightsCount(), lightIndex its counter (LIGHT_LOOP_BEGIN / LIGHT_LOOP_END).
#define USE_FORWARD_PLUS 0
#define USE_CLUSTERED_LIGHTING 0
#define LIGHT_LOOP_BEGIN(lightCount) for (uint lightIndex = 0u; lightIndex < uint(lightCount); lightIndex++) {
#define LIGHT_LOOP_END }

// The shadow mask a pixel's baked shadows come from: none here (no lightmaps), every channel 1.
float4 CalculateShadowMask(InputData inputData) { return float4(1.0, 1.0, 1.0, 1.0); }

// URP 12's LightingData and the functions that take it; left out where the shader declares a
// struct LightingData of its own (written for an earlier URP: importers/unity/user_definitions.py).
#ifndef PBRLAB_USER_DEFINES_LightingData
// A pixel's light by kind, summed by CalculateLightingColor: the global illumination, the main
// light, the additional lights and the vertex lights, times the albedo, plus the emission.
struct LightingData {
    float3 giColor;
    float3 mainLightColor;
    float3 additionalLightsColor;
    float3 vertexLightingColor;
    float3 emissionColor;
};

LightingData CreateLightingData(InputData inputData, SurfaceData surfaceData) {
    LightingData lightingData;
    lightingData.giColor = inputData.bakedGI;
    lightingData.mainLightColor = float3(0.0, 0.0, 0.0);
    lightingData.additionalLightsColor = float3(0.0, 0.0, 0.0);
    lightingData.vertexLightingColor = float3(0.0, 0.0, 0.0);
    lightingData.emissionColor = surfaceData.emission;
    return lightingData;
}

float3 CalculateLightingColor(LightingData lightingData, float3 albedo) {
    float3 light = lightingData.giColor + lightingData.mainLightColor + lightingData.additionalLightsColor
                 + lightingData.vertexLightingColor;
    return light * albedo + lightingData.emissionColor;
}

float4 CalculateFinalColor(LightingData lightingData, float alpha) {
    return float4(CalculateLightingColor(lightingData, float3(1.0, 1.0, 1.0)), alpha);
}

float4 CalculateFinalColor(LightingData lightingData, float3 albedo, float alpha, float fogCoord) {
    return float4(CalculateLightingColor(lightingData, albedo), alpha);  // no fog here
}
#endif

// The lit pixel: ambient and reflections, the main light, every additional light, emission.
float4 UniversalFragmentPBR(InputData inputData, SurfaceData surfaceData) {
    BRDFData brdfData;
    InitializeBRDFData(surfaceData.albedo, surfaceData.metallic, surfaceData.specular, surfaceData.smoothness,
                       surfaceData.alpha, brdfData);
    float3 color = GlobalIllumination(brdfData, inputData.bakedGI, surfaceData.occlusion, inputData.positionWS,
                                      inputData.normalWS, inputData.viewDirectionWS);
    Light mainLight = GetMainLight(inputData.shadowCoord, inputData.positionWS, inputData.shadowMask);
    color += LightingPhysicallyBased(brdfData, mainLight, inputData.normalWS, inputData.viewDirectionWS);
#ifdef _ADDITIONAL_LIGHTS
    int lightCount = GetAdditionalLightsCount();
    for (int lightIndex = 0; lightIndex < lightCount; ++lightIndex) {
        Light light = GetAdditionalLight(uint(lightIndex), inputData.positionWS, inputData.shadowMask);
        color += LightingPhysicallyBased(brdfData, light, inputData.normalWS, inputData.viewDirectionWS);
    }
#endif
    color += surfaceData.emission;
    return float4(color, surfaceData.alpha);
}

float4 UniversalFragmentPBR(InputData inputData, float3 albedo, float metallic, float3 specular, float smoothness,
                            float occlusion, float3 emission, float alpha) {
    SurfaceData s;
    s.albedo = albedo;
    s.specular = specular;
    s.metallic = metallic;
    s.smoothness = smoothness;
    s.normalTS = float3(0.0, 0.0, 1.0);
    s.emission = emission;
    s.occlusion = occlusion;
    s.alpha = alpha;
    s.clearCoatMask = 0.0;
    s.clearCoatSmoothness = 1.0;
    return UniversalFragmentPBR(inputData, s);
}

// The Lightweight Render Pipeline's name (URP before 7.0) for UniversalFragmentPBR.
float4 LightweightFragmentPBR(InputData inputData, float3 albedo, float metallic, float3 specular, float smoothness,
                              float occlusion, float3 emission, float alpha) {
    return UniversalFragmentPBR(inputData, albedo, metallic, specular, smoothness, occlusion, emission, alpha);
}

// URP's Lighting.hlsl includes GlobalIllumination.hlsl, which includes Core RP's
// ImageBasedLighting.hlsl (URP 14.0.9): UNITY_SPECCUBE_LOD_STEPS and the mip <-> roughness
// converters reach a program that includes Lighting.hlsl (its include of this file is skipped).
#include "Packages/com.unity.render-pipelines.core/ShaderLibrary/ImageBasedLighting.hlsl"

#endif
