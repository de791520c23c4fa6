// pbrlab stand-in for URP's Shaders/Utils/Fullscreen.hlsl, the full-screen vertex function of URP
// 12's post-processing shaders (PostProcessing/Common.hlsl included it until URP 13 moved them to
// Core RP's Blit.hlsl): Attributes, Varyings { positionCS, uv } and FullscreenVert (written for
// pbrlab from Unity's documentation of URP 12's post-processing and observed behaviour; URP's own
// file is under the Unity Companion License and is not copied).
//
// URP 12 draws such a pass either over a full-screen mesh or, with _USE_DRAW_PROCEDURAL, from
// SV_VertexID alone; pbrlab draws every full-screen pass procedurally (importers/unity/
// fullscreen_pass.py), so Attributes is the procedural one and FullscreenVert places Core's
// full-screen triangle (PbrlabFullScreenTriangle.hlsl), which covers the same viewport as URP's
// quad: uv is the pixel's viewport position in [0, 1], (0, 0) bottom-left, URP's _ScaleBias
// being (1, 1, 0, 0) (the whole source).
#ifndef PBRLAB_URP_FULLSCREEN_HLSL
#define PBRLAB_URP_FULLSCREEN_HLSL

#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"

// Only in a program written for URP 12's layout (one that names FullscreenVert:
// importers/unity/user_definitions.py), and Blit.hlsl's body only in one that is not: the parser
// reads every file a program includes, whatever branch includes it, and takes each struct's
// last definition it meets (importers/unity/parse_pass.py).
#ifdef PBRLAB_USER_READS_FullscreenVert

struct Attributes {
    uint vertexID : SV_VertexID;
    UNITY_VERTEX_INPUT_INSTANCE_ID
};

struct Varyings {
    float4 positionCS : SV_POSITION;
    float2 uv : TEXCOORD0;
    UNITY_VERTEX_OUTPUT_STEREO
};

Varyings FullscreenVert(Attributes input) {
    Varyings output;
    output.positionCS = GetFullScreenTriangleVertexPosition(input.vertexID);
    output.uv = GetFullScreenTriangleTexCoord(input.vertexID);
    return output;
}

#endif  // PBRLAB_USER_READS_FullscreenVert

#endif
