// pbrlab stand-in for URP's ShaderLibrary/DeclareDepthTexture.hlsl: the camera's depth texture
// _CameraDepthTexture and SampleSceneDepth / LoadSceneDepth, which read its raw depth (written
// for pbrlab from Unity's documentation of URP's depth texture and of these functions; URP's own
// file is under the Unity Companion License and is not copied).
//
// The harness renders the texture in a real depth pre-pass of the scene's opaque objects before
// the frame (harness/pbrlab/render/camera_textures.py; a program including this file makes the
// pass run: importers/unity/material.py camera_textures). Its raw depth is the window depth in
// GL's convention, [0, 1] with near 0 and far 1 (not reversed-Z, as URP's on OpenGL), and the
// _ZBufferParams pbrlab sets are a GL depth buffer's, so Core.hlsl's LinearEyeDepth(depth,
// _ZBufferParams) of it is the eye depth and Linear01Depth(depth, _ZBufferParams) eye depth / far.
#ifndef PBRLAB_URP_DECLARE_DEPTH_TEXTURE_HLSL
#define PBRLAB_URP_DECLARE_DEPTH_TEXTURE_HLSL

#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"

TEXTURE2D_X_FLOAT(_CameraDepthTexture);
SAMPLER(sampler_CameraDepthTexture);

// The raw depth at a [0, 1] screen position (the texture is sampled nearest: the texel the
// position lies in).
float SampleSceneDepth(float2 uv) {
    return SAMPLE_TEXTURE2D_X(_CameraDepthTexture, sampler_CameraDepthTexture, uv).r;
}

// The raw depth of the texel at integer pixel coordinates (x right, y up from the bottom-left,
// as gl_FragCoord.xy - 0.5): its centre sampled nearest, which reads that texel exactly.
float LoadSceneDepth(uint2 uv) {
    return SampleSceneDepth((float2(uv) + 0.5) / _ScreenParams.xy);
}

#endif
