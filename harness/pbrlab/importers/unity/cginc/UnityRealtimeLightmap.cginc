// pbrlab stand-in for the realtime-GI (Enlighten) lightmap part of Unity's UnityShaderVariables.cginc
// and UnityCG.cginc (included by pbrlab's UnityCG.cginc): the object's realtime lightmap, which the
// material supplies (its `dynamic_lightmap` field: harness/pbrlab/importers/unity/dynamic_lightmaps.py
// binds these), and Unity's decode of its texel. Written by pbrlab from Unity's documentation:
//   DecodeRealtimeLightmap(color) = pow((x * color.a) * color.rgb, y), x and y from
//   unity_DynamicLightmap_HDR (the decode of Enlighten's output texture, read in linear space);
//   the lightmap supplied here is Unity's RGB9E5 output (a float texture: "Lightmaps: Technical
//   information", Precomputed Realtime GI), whose decode instructions are (1, 1): the texel's RGB.
// A program that reads these with no realtime lightmap supplied is refused at the line that reads them.
// Cg text in the plain subset harness/pbrlab/importers/unity/port.py ports to GLSL.
#ifndef PBRLAB_UNITY_REALTIME_LIGHTMAP_CGINC
#define PBRLAB_UNITY_REALTIME_LIGHTMAP_CGINC

// Unity declares it with UNITY_DECLARE_TEX2D (a texture and its sampler on Direct3D 11).
UNITY_DECLARE_TEX2D(unity_DynamicLightmap);
#ifndef unity_DynamicLightmapST  // (URP's Core.hlsl stand-in, included first, defines it: an unlightmapped object's)
float4 unity_DynamicLightmapST;
#endif
half4 unity_DynamicLightmap_HDR;

// Enlighten's output in linear colour space: pow((x a) rgb, y) (unity_DynamicLightmap_HDR).
half3 DecodeRealtimeLightmap(fixed4 color)
{
    return pow((unity_DynamicLightmap_HDR.x * color.a) * color.rgb, unity_DynamicLightmap_HDR.y);
}

#endif
