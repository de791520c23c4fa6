// pbrlab stand-in for Core RP's Runtime/Utilities/Blit.hlsl, the include of full-screen passes
// drawn by Unity's Blitter and URP's Full Screen Pass Renderer Feature: the source texture
// _BlitTexture, its scale and bias _BlitScaleBias and mip _BlitMipLevel, the vertex functions
// Vert (the procedural full-screen triangle), VertQuad and VertQuadPadding (the Blitter's quad)
// and the copy fragments (written for pbrlab from Unity's documentation of the Blitter and of
// full-screen shaders, and observed behaviour; Core RP's own file is under the Unity Companion
// License and is not copied).
//
// pbrlab draws a pass whose vertex input is SV_VertexID alone (these functions') as the Blitter
// does: no mesh, after the scene's other objects, with _BlitTexture a copy of the camera's
// colour as drawn so far, _BlitScaleBias = _BlitScaleBiasRt = (1, 1, 0, 0) (the whole source, to
// the whole target), _BlitMipLevel 0 (importers/unity/fullscreen_pass.py; docs/unity.md). Vert's
// texcoord is then the pixel's viewport position in [0, 1], (0, 0) bottom-left
// (PbrlabFullScreenTriangle.hlsl). _BlitCubeTexture, which the application binds, is unbound,
// and BLIT_DECODE_HDR's decode is not provided.
#ifndef PBRLAB_CORE_RP_BLIT_HLSL
#define PBRLAB_CORE_RP_BLIT_HLSL

#include "Packages/com.unity.render-pipelines.core/ShaderLibrary/Common.hlsl"
#include "Packages/com.unity.render-pipelines.core/ShaderLibrary/Color.hlsl"
#include "Packages/com.unity.render-pipelines.core/ShaderLibrary/GlobalSamplers.hlsl"

// Not in a program written for URP 12's post-processing layout, whose Common.hlsl brings
// Utils/Fullscreen.hlsl's Attributes and Varyings instead (and whose Unity has the two never
// together: each defines Attributes and Varyings), nor in one written for URP 10's, whose
// Common.hlsl declared a mesh's (importers/unity/user_definitions.py).
#if !defined(PBRLAB_USER_READS_FullscreenVert) && !defined(PBRLAB_USER_READS_Attributes_positionOS)

TEXTURE2D_X(_BlitTexture);
TEXTURECUBE(_BlitCubeTexture);
float4 _BlitScaleBias;
float4 _BlitScaleBiasRt;
// _BlitTexture's texel size (1 / w, 1 / h, w, h), which Unity sets for every texture it binds;
// Core RP's Blit.hlsl declares it since Unity 6, where earlier shaders declare it themselves:
// where the shader's own text does, the stand-in leaves it to the shader's declaration
// (importers/unity/user_definitions.py).
#ifndef PBRLAB_USER_DEFINES_BlitTexture_TexelSize
float4 _BlitTexture_TexelSize;
#endif
float _BlitMipLevel;
float2 _BlitTextureSize;
uint _BlitPaddingSize;
int _BlitTexArraySlice;
float4 _BlitDecodeInstructions;

struct Attributes {
    uint vertexID : SV_VertexID;
    UNITY_VERTEX_INPUT_INSTANCE_ID
};

struct Varyings {
    float4 positionCS : SV_POSITION;
    float2 texcoord : TEXCOORD0;
    UNITY_VERTEX_OUTPUT_STEREO
};

// A vertex's clip position, and its texture coordinate scaled and offset by _BlitScaleBias (xy
// scale, zw bias).
Varyings PbrlabBlitVaryings(float4 positionCS, float2 uv) {
    Varyings output;
    output.positionCS = positionCS;
    output.texcoord = uv * _BlitScaleBias.xy + _BlitScaleBias.zw;
    return output;
}

// The full-screen triangle.
Varyings Vert(Attributes input) {
    return PbrlabBlitVaryings(GetFullScreenTriangleVertexPosition(input.vertexID), GetFullScreenTriangleTexCoord(input.vertexID));
}

// The quad's corner placed in the target by _BlitScaleBiasRt (xy scale, zw offset, in [0, 1],
// y down), to clip space (2 x - 1, 1 - 2 y).
float4 PbrlabBlitQuadPosition(uint vertexID) {
    float4 p = GetQuadVertexPosition(vertexID);
    p.xy = p.xy * _BlitScaleBiasRt.xy + _BlitScaleBiasRt.zw;
    return float4(p.x * 2.0 - 1.0, 1.0 - p.y * 2.0, p.z, p.w);
}

Varyings VertQuad(Attributes input) {
    return PbrlabBlitVaryings(PbrlabBlitQuadPosition(input.vertexID), GetQuadTexCoord(input.vertexID));
}

// The quad with a border of _BlitPaddingSize texels around a _BlitTextureSize source: its
// coordinate moved in by half the border and stretched by (size + border) / size, so the
// source's edge texels reach into the border.
Varyings VertQuadPadding(Attributes input) {
    float2 padding = float2(float(_BlitPaddingSize), float(_BlitPaddingSize));
    float2 stretch = (_BlitTextureSize + padding) / _BlitTextureSize;
    float2 inset = 0.5 * padding / (_BlitTextureSize + padding);
    return PbrlabBlitVaryings(PbrlabBlitQuadPosition(input.vertexID), (GetQuadTexCoord(input.vertexID) - inset) * stretch);
}

// The source at the coordinate, at mip _BlitMipLevel (its texture's filtering: GlobalSamplers.hlsl).
float4 PbrlabBlitSource(float2 uv) {
    return SAMPLE_TEXTURE2D_X_LOD(_BlitTexture, sampler_LinearClamp, uv, _BlitMipLevel);
}

float4 FragNearest(Varyings input) : SV_Target { return PbrlabBlitSource(input.texcoord); }
float4 FragBilinear(Varyings input) : SV_Target { return PbrlabBlitSource(input.texcoord); }
float4 FragNearestRepeat(Varyings input) : SV_Target { return PbrlabBlitSource(frac(input.texcoord)); }
float4 FragBilinearRepeat(Varyings input) : SV_Target { return PbrlabBlitSource(frac(input.texcoord)); }
// Rec. 709 luminance of the linear colour (Luminance: pbrlab's Unity prelude) in every channel,
// and one channel copied to all four.
float4 FragBilinearLuminance(Varyings input) : SV_Target {
    float y = Luminance(PbrlabBlitSource(frac(input.texcoord)).rgb);
    return float4(y, y, y, y);
}
float4 FragBilinearRedToRGBA(Varyings input) : SV_Target { return PbrlabBlitSource(frac(input.texcoord)).rrrr; }
float4 FragBilinearAlphaToRGBA(Varyings input) : SV_Target { return PbrlabBlitSource(frac(input.texcoord)).aaaa; }

// An octahedral map's coordinate outside [0, 1]^2 folded back in (the map is a sphere unfolded
// onto a square: across an edge the neighbouring texel is the one mirrored through the edge's
// midpoint; across a corner, the opposite corner's).
float2 PbrlabRepeatOctahedralUV(float2 uv) {
    bool uOut = uv.x < 0.0 || uv.x >= 1.0;
    bool vOut = uv.y < 0.0 || uv.y >= 1.0;
    if (uOut && vOut) return frac(uv);
    if (uOut) return float2(uv.x < 0.0 ? -uv.x : 2.0 - uv.x, 1.0 - uv.y);
    if (vOut) return float2(1.0 - uv.x, uv.y < 0.0 ? -uv.y : 2.0 - uv.y);
    return uv;
}

float4 PbrlabBlitCube(float2 uv) {
    return SAMPLE_TEXTURECUBE_LOD(_BlitCubeTexture, sampler_LinearRepeat, UnpackNormalOctQuadEncode(2.0 * uv - 1.0), _BlitMipLevel);
}

float4 FragOctahedralBilinearRepeat(Varyings input) : SV_Target {
    return PbrlabBlitSource(PbrlabRepeatOctahedralUV(input.texcoord));
}
float4 FragOctahedralProject(Varyings input) : SV_Target { return float4(PbrlabBlitCube(saturate(input.texcoord)).rgb, 1.0); }
float4 FragOctahedralProjectNearestRepeat(Varyings input) : SV_Target {
    return float4(PbrlabBlitCube(PbrlabRepeatOctahedralUV(input.texcoord)).rgb, 1.0);
}
float4 FragOctahedralProjectBilinearRepeat(Varyings input) : SV_Target {
    return float4(PbrlabBlitCube(PbrlabRepeatOctahedralUV(input.texcoord)).rgb, 1.0);
}
float4 FragOctahedralProjectLuminance(Varyings input) : SV_Target {
    float y = Luminance(PbrlabBlitCube(saturate(input.texcoord)).rgb);
    return float4(y, y, y, y);
}
float4 FragOctahedralProjectRedToRGBA(Varyings input) : SV_Target { return PbrlabBlitCube(saturate(input.texcoord)).rrrr; }
float4 FragOctahedralProjectAlphaToRGBA(Varyings input) : SV_Target { return PbrlabBlitCube(saturate(input.texcoord)).aaaa; }

#endif  // PBRLAB_USER_READS_FullscreenVert, PBRLAB_USER_READS_Attributes_positionOS

#endif
