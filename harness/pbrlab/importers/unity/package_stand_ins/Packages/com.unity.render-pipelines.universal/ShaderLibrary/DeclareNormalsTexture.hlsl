// pbrlab stand-in for URP's ShaderLibrary/DeclareNormalsTexture.hlsl: the camera's normals
// texture _CameraNormalsTexture and SampleSceneNormals / LoadSceneNormals, which return the
// world-space normal of the nearest opaque surface (written for pbrlab from Unity's
// documentation of URP's DepthNormals prepass and of these functions; URP's own file is under
// the Unity Companion License and is not copied).
//
// The harness renders the texture in its pre-pass of the scene's opaque objects before the
// frame (harness/pbrlab/render/camera_textures.py; a program including this file makes the pass
// run: importers/unity/material.py camera_textures). It holds what URP 10 and later store
// without the deferred renderer's octahedral option (_GBUFFER_NORMALS_OCT, not set here): the
// unit world normal itself in rgb, signed, 0 where no opaque object was drawn. Sampled nearest.
#ifndef PBRLAB_URP_DECLARE_NORMALS_TEXTURE_HLSL
#define PBRLAB_URP_DECLARE_NORMALS_TEXTURE_HLSL

#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"

TEXTURE2D_X_FLOAT(_CameraNormalsTexture);
SAMPLER(sampler_CameraNormalsTexture);

// The world normal at a [0, 1] screen position (the texel the position lies in).
float3 SampleSceneNormals(float2 uv) {
    return SAMPLE_TEXTURE2D_X(_CameraNormalsTexture, sampler_CameraNormalsTexture, uv).xyz;
}

// The world normal of the texel at integer pixel coordinates (x right, y up from the
// bottom-left, as gl_FragCoord.xy - 0.5): its centre sampled nearest, which reads that texel.
float3 LoadSceneNormals(uint2 uv) {
    return SampleSceneNormals((float2(uv) + 0.5) / _ScreenParams.xy);
}

#endif
