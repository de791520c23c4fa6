// pbrlab stand-in for Core RP's ShaderLibrary/Texture.hlsl: Shader Graph's texture objects
// (UnityTexture2D: a texture, its sampler, its texel size and its tiling and offset; built by
// UnityBuildTexture2DStruct from a Texture2D property, or ...NoScale with tiling 1, offset 0;
// UnityTextureCube, UnityTexture2DArray, UnityTexture3D: a texture and its sampler)
// and the SRP texture macros (pbrlab's stand-in Core.hlsl), written for pbrlab from Shader
// Graph's documentation of its Texture 2D Asset and Sample Texture 2D nodes (Core RP's own
// file is under the Unity Companion License and is not copied). In HLSL the struct is
// Unity's; the GLSL port spells each texture object out (importers/unity/port.py:
// UnityTexture2D), since GLSL keeps samplers out of local structs.
#ifndef PBRLAB_CORE_RP_TEXTURE_HLSL
#define PBRLAB_CORE_RP_TEXTURE_HLSL

#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"

#ifndef __VERSION__
struct UnitySamplerState {
    SamplerState samplerstate;
};

struct UnityTexture2D {
    Texture2D tex;
    SamplerState samplerstate;
    float4 texelSize;
    float4 scaleTranslate;
    // The node's UV: tiling (xy) then offset (zw), as _ST applies them.
    float2 GetTransformedUV(float2 uv) { return uv * scaleTranslate.xy + scaleTranslate.zw; }
    float4 Sample(UnitySamplerState s, float2 uv) { return tex.Sample(s.samplerstate, uv); }
    float4 SampleLevel(UnitySamplerState s, float2 uv, float lod) { return tex.SampleLevel(s.samplerstate, uv, lod); }
};

UnityTexture2D UnityBuildTexture2DStructInternal(Texture2D tex, SamplerState samplerstate, float4 texelSize,
                                                 float4 scaleTranslate) {
    UnityTexture2D result;
    result.tex = tex;
    result.samplerstate = samplerstate;
    result.texelSize = texelSize;
    result.scaleTranslate = scaleTranslate;
    return result;
}

#define UnityBuildTexture2DStruct(n) UnityBuildTexture2DStructInternal(n, sampler##n, n##_TexelSize, n##_ST)
#define UnityBuildTexture2DStructNoScale(n) UnityBuildTexture2DStructInternal(n, sampler##n, n##_TexelSize, float4(1.0, 1.0, 0.0, 0.0))
// The cube, 2D-array and 3D texture objects (Shader Graph's Cubemap, Texture 2D Array and
// Texture 3D Asset nodes): the texture and its sampler, no texel size or tiling; each struct and
// its builder made by one macro, as the harness's prelude makes its per-size functions.
#define PBRLAB_TEXTURE_OBJECT(Object, Texture) \
    struct Object { Texture tex; SamplerState samplerstate; }; \
    Object PbrlabBuild##Object(Texture tex, SamplerState samplerstate) { \
        Object result; result.tex = tex; result.samplerstate = samplerstate; return result; }
PBRLAB_TEXTURE_OBJECT(UnityTextureCube, TextureCube)
PBRLAB_TEXTURE_OBJECT(UnityTexture2DArray, Texture2DArray)
PBRLAB_TEXTURE_OBJECT(UnityTexture3D, Texture3D)
#define UnityBuildTextureCubeStruct(n) PbrlabBuildUnityTextureCube(n, sampler##n)
#define UnityBuildTexture2DArrayStruct(n) PbrlabBuildUnityTexture2DArray(n, sampler##n)
#define UnityBuildTexture3DStruct(n) PbrlabBuildUnityTexture3D(n, sampler##n)
#define UnityBuildSamplerStateStruct(n) UnityBuildSamplerStateStructInternal(n)
UnitySamplerState UnityBuildSamplerStateStructInternal(SamplerState samplerstate) {
    UnitySamplerState result;
    result.samplerstate = samplerstate;
    return result;
}
#endif

#endif
