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

#endif
