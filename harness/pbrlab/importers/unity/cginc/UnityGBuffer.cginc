// pbrlab stand-in for Unity's UnityGBuffer.cginc: the built-in deferred path's G-buffer layout.
//
// Provides: struct UnityStandardData (diffuseColor, occlusion, specularColor, smoothness,
//   normalWorld), UnityStandardDataToGbuffer(data, out g0, out g1, out g2),
//   UnityStandardDataFromGbuffer(g0, g1, g2).
// Include: #include "UnityGBuffer.cginc".
// Config macros read: none.
// Unity's file (UnityGBuffer.cginc, Unity 2019.4 built-in shaders; the layout in Unity's manual,
//   "Deferred shading rendering path"), read for its behaviour and written here anew:
//   RT0 diffuse colour rgb, occlusion a; RT1 specular colour rgb, smoothness a; RT2 the world
//   normal * 0.5 + 0.5 rgb (a unused, 1). The harness's G-buffer pre-pass writes the same
//   layout (harness/pbrlab/render/camera_textures.py).
// Cg text in the plain subset harness/pbrlab/importers/unity/port.py ports to GLSL.
#ifndef PBRLAB_UNITY_GBUFFER_CGINC
#define PBRLAB_UNITY_GBUFFER_CGINC

struct UnityStandardData
{
    half3 diffuseColor;
    half occlusion;
    half3 specularColor;
    half smoothness;
    float3 normalWorld;
};

void UnityStandardDataToGbuffer(UnityStandardData data, out half4 outGBuffer0, out half4 outGBuffer1,
                                out half4 outGBuffer2)
{
    outGBuffer0 = half4(data.diffuseColor, data.occlusion);
    outGBuffer1 = half4(data.specularColor, data.smoothness);
    outGBuffer2 = half4(data.normalWorld * 0.5 + 0.5, 1.0);
}

UnityStandardData UnityStandardDataFromGbuffer(half4 inGBuffer0, half4 inGBuffer1, half4 inGBuffer2)
{
    UnityStandardData data;
    data.diffuseColor = inGBuffer0.rgb;
    data.occlusion = inGBuffer0.a;
    data.specularColor = inGBuffer1.rgb;
    data.smoothness = inGBuffer1.a;
    data.normalWorld = normalize(inGBuffer2.rgb * 2.0 - 1.0);
    return data;
}

#endif
