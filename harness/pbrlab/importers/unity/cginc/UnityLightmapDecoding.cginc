// pbrlab stand-in for the baked-lightmap part of Unity's UnityShaderVariables.cginc and UnityCG.cginc
// (included by pbrlab's UnityCG.cginc): the object's lightmap, which the material supplies
// (its `lightmap` field: harness/pbrlab/importers/unity/lightmaps.py binds these), and Unity's
// decoding of a lightmap texel. Written by pbrlab from Unity's manual ("Lightmaps: Technical
// information"), in linear colour space (the harness's):
//   RGBM: the texel's RGB (sampled from an sRGB texture: linear) times the multiplier
//         M = a^2.2 scaled to the linear range 5^2.2 = 34.49, so decoded = 34.49 a^2.2 rgb;
//   dLDR: the RGB (sRGB-sampled) times 2^2.2 = 4.59482;
//   full HDR (Unity's "High Quality" lightmap encoding): the texel's RGB as it is (a float texture).
// unity_Lightmap_HDR holds the decode instructions (x: the range, y: the exponent of M), as Unity
// sets it; the encoding's macro (UNITY_LIGHTMAP_RGBM_ENCODING, UNITY_LIGHTMAP_DLDR_ENCODING or
// UNITY_LIGHTMAP_FULL_HDR) is defined by the harness for the supplied lightmap's encoding.
// A program that reads these with no lightmap supplied is refused at the line that reads them.
// Cg text in the plain subset harness/pbrlab/importers/unity/port.py ports to GLSL.
#ifndef PBRLAB_UNITY_LIGHTMAP_DECODING_CGINC
#define PBRLAB_UNITY_LIGHTMAP_DECODING_CGINC

// Unity declares it with UNITY_DECLARE_TEX2D (a texture and its sampler on Direct3D 11), which its
// shaders read with UNITY_SAMPLE_TEX2D.
UNITY_DECLARE_TEX2D(unity_Lightmap);
#ifndef unity_LightmapST  // (URP's Core.hlsl stand-in, included first, defines it: an unlightmapped object's)
float4 unity_LightmapST;
#endif
half4 unity_Lightmap_HDR;

// RGBM in linear colour space: (x * a^y) * rgb, x = 5^2.2, y = 2.2 (unity_Lightmap_HDR).
half3 DecodeLightmapRGBM(half4 data, half4 decodeInstructions)
{
    return (decodeInstructions.x * pow(data.a, decodeInstructions.y)) * data.rgb;
}

// dLDR in linear colour space: x * rgb, x = 2^2.2.
half3 DecodeLightmapDoubleLDR(fixed4 color, half4 decodeInstructions)
{
    return decodeInstructions.x * color.rgb;
}

// The decode of the lightmap's encoding (full HDR: the texel as it is).
half3 DecodeLightmap(fixed4 color, half4 decodeInstructions)
{
#if defined(UNITY_LIGHTMAP_DLDR_ENCODING)
    return DecodeLightmapDoubleLDR(color, decodeInstructions);
#elif defined(UNITY_LIGHTMAP_RGBM_ENCODING)
    return DecodeLightmapRGBM(color, decodeInstructions);
#else
    return color.rgb;
#endif
}

half3 DecodeLightmap(fixed4 color)
{
    return DecodeLightmap(color, unity_Lightmap_HDR);
}

// A directional lightmap's second texture (UnityShaderVariables.cginc's unity_LightmapInd; Unity
// manual, "Directional Mode"): per texel the dominant direction of the baked light, xyz in [0, 1]
// (a world-space direction times 0.5 plus 0.5), and in w the rebalancing factor. The material's
// lightmap `direction` image where it has one; otherwise a grey texel (0.5, 0.5, 0.5, 0.5), the
// direction texture of a lightmap with no dominant direction, under which
// DecodeDirectionalLightmap returns the lightmap as it is (lightmaps.py binds either).
UNITY_DECLARE_TEX2D_NOSAMPLER(unity_LightmapInd);

// The directional decode (Unity's UnityCG.cginc, "Directional Mode": a half-Lambert term of the
// normal against the dominant direction, divided by the rebalancing factor so that the average
// over directions is the lightmap's colour): color (dot(n, d.xyz - 0.5) + 0.5) / max(d.w, 1e-4).
half3 DecodeDirectionalLightmap(half3 color, fixed4 dirTex, half3 normalWorld)
{
    half halfLambert = dot(normalWorld, dirTex.xyz - 0.5) + 0.5;
    return color * halfLambert / max(1e-4, dirTex.w);
}

// The baked shadow mask (UnityShaderVariables.cginc's unity_ShadowMask, read at the lightmap UV;
// Unity manual, "Shadowmask"): per texel the baked occlusion of up to four mixed lights, one per
// channel, which unity_OcclusionMaskSelector picks for the light being drawn. pbrlab bakes no
// shadows and a supplied lightmap brings no mask: the mask is white (lightmaps.py leaves it to the
// default of an unset texture, white, as Unity binds for a lightmap without a shadow mask) and the
// selector picks its first channel, so a shader's baked occlusion is 1: the light unshadowed.
UNITY_DECLARE_TEX2D(unity_ShadowMask);
static const fixed4 unity_OcclusionMaskSelector = fixed4(1.0, 0.0, 0.0, 0.0);
#define UNITY_SAMPLE_SHADOWMASK(uv) UNITY_SAMPLE_TEX2D(unity_ShadowMask, uv)

#endif
