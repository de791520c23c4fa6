// pbrlab stand-in for Core RP's Runtime/Utilities/Blit.hlsl, the include of full-screen passes
// drawn by Unity's Blitter and URP's Full Screen Pass Renderer Feature: the source texture
// _BlitTexture, its scale and bias _BlitScaleBias and mip _BlitMipLevel, the vertex function
// Vert over a procedural full-screen triangle and the copy fragments FragNearest / FragBilinear
// (written for pbrlab from Unity's documentation of the Blitter and of full-screen shaders, and
// observed behaviour; Core RP's own file is under the Unity Companion License and is not copied).
//
// pbrlab draws a pass whose vertex input is SV_VertexID alone (this Vert's) as the Blitter does:
// 3 vertices, no mesh, after the scene's other objects, with _BlitTexture a copy of the camera's
// colour as drawn so far, _BlitScaleBias (1, 1, 0, 0) (the whole source), _BlitMipLevel 0
// (importers/unity/fullscreen_pass.py; docs/unity.md). Vert's texcoord is then the pixel's
// viewport position in [0, 1], (0, 0) bottom-left (PbrlabFullScreenTriangle.hlsl).
// VertQuad and the octahedral and cube-map fragments are not provided.
#ifndef PBRLAB_CORE_RP_BLIT_HLSL
#define PBRLAB_CORE_RP_BLIT_HLSL

#include "Packages/com.unity.render-pipelines.core/ShaderLibrary/Common.hlsl"
#include "Packages/com.unity.render-pipelines.core/ShaderLibrary/Color.hlsl"
#include "Packages/com.unity.render-pipelines.core/ShaderLibrary/GlobalSamplers.hlsl"

TEXTURE2D_X(_BlitTexture);
float4 _BlitScaleBias;
float4 _BlitScaleBiasRt;
float _BlitMipLevel;
float2 _BlitTextureSize;

struct Attributes {
    uint vertexID : SV_VertexID;
    UNITY_VERTEX_INPUT_INSTANCE_ID
};

struct Varyings {
    float4 positionCS : SV_POSITION;
    float2 texcoord : TEXCOORD0;
    UNITY_VERTEX_OUTPUT_STEREO
};

// The triangle's clip position and its texture coordinate scaled and offset by _BlitScaleBias
// (xy scale, zw bias).
Varyings Vert(Attributes input) {
    Varyings output;
    output.positionCS = GetFullScreenTriangleVertexPosition(input.vertexID);
    output.texcoord = GetFullScreenTriangleTexCoord(input.vertexID) * _BlitScaleBias.xy + _BlitScaleBias.zw;
    return output;
}

// The source at the coordinate, at mip _BlitMipLevel (its texture's filtering: GlobalSamplers.hlsl).
float4 FragNearest(Varyings input) : SV_Target {
    return SAMPLE_TEXTURE2D_X_LOD(_BlitTexture, sampler_PointClamp, input.texcoord, _BlitMipLevel);
}

float4 FragBilinear(Varyings input) : SV_Target {
    return SAMPLE_TEXTURE2D_X_LOD(_BlitTexture, sampler_LinearClamp, input.texcoord, _BlitMipLevel);
}

#endif
