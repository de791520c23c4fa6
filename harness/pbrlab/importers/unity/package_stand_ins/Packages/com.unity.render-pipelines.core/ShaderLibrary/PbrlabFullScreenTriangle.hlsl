// pbrlab's body of Core RP's full-screen triangle and quad functions (Core's Common.hlsl:
// GetFullScreenTriangleVertexPosition, GetFullScreenTriangleTexCoord, GetQuadVertexPosition,
// GetQuadTexCoord) and URP's UnityStereoTransformScreenSpaceTex, written for pbrlab from
// Unity's documentation of its Blitter (a procedural draw of 3 vertices covering the viewport,
// positioned from SV_VertexID) and observed behaviour (Core RP's own file is under the Unity
// Companion License and is not copied). Included by the stand-in Core.hlsl, so a program that
// includes Core.hlsl, Common.hlsl or Blit.hlsl reaches them.
//
// Vertex i of the triangle has the corner c = (2 (i & 1), i & 2) of (0, 0), (2, 0), (0, 2): its
// clip position is (2 c - 1, z, 1), a triangle (-1, -1), (3, -1), (-1, 3) whose inside holds the
// whole viewport, counter-clockwise (front-facing); z defaults to the near plane
// (UNITY_NEAR_CLIP_VALUE, -1 on GL). Its texture coordinate is c: (0, 0) at the viewport's
// bottom-left corner and (1, 1) at its top-right one, since UNITY_UV_STARTS_AT_TOP is undefined on
// GL (a Direct3D build flips v to 1 - v, where textures start at the top); so an interpolated
// coordinate at a pixel centre is the centre's viewport position in [0, 1], the texel of a
// viewport-sized texture under it.
#ifndef PBRLAB_CORE_RP_FULL_SCREEN_TRIANGLE_HLSL
#define PBRLAB_CORE_RP_FULL_SCREEN_TRIANGLE_HLSL

float2 PbrlabFullScreenTriangleCorner(uint vertexID) {
    return float2(float((vertexID << 1u) & 2u), float(vertexID & 2u));
}

float2 GetFullScreenTriangleTexCoord(uint vertexID) {
    return PbrlabFullScreenTriangleCorner(vertexID);
}

float4 GetFullScreenTriangleVertexPosition(uint vertexID, float z = UNITY_NEAR_CLIP_VALUE) {
    return float4(PbrlabFullScreenTriangleCorner(vertexID) * 2.0 - 1.0, z, 1.0);
}

// The Blitter's quad (Blitter.BlitQuad: 4 vertices, triangles (0, 1, 2) and (0, 2, 3)): vertex i's
// corner (i >> 1, 1 for i = 0 and 3, else 0), y down, which its callers map to clip space by
// (2 x - 1, 1 - 2 y) (Blit.hlsl's VertQuad); its texture coordinate (i >> 1, 1 for i = 1 and 2,
// else 0), so each corner reads its own corner of the source, v up on GL (a Direct3D build
// flips v, UNITY_UV_STARTS_AT_TOP).
float4 GetQuadVertexPosition(uint vertexID, float z = UNITY_NEAR_CLIP_VALUE) {
    float y = (vertexID == 0u || vertexID == 3u) ? 1.0 : 0.0;
    return float4(float(vertexID >> 1u), y, z, 1.0);
}

float2 GetQuadTexCoord(uint vertexID) {
    float v = (vertexID == 1u || vertexID == 2u) ? 1.0 : 0.0;
    return float2(float(vertexID >> 1u), v);
}

// One view, no XR: a screen-space texture coordinate is the eye's own (URP's
// ShaderVariablesFunctions.hlsl defines it so without single-pass stereo).
#ifndef UnityStereoTransformScreenSpaceTex
#define UnityStereoTransformScreenSpaceTex(uv) (uv)
#endif

#endif
