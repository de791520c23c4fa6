// pbrlab stand-in for URP's ShaderLibrary/DeclareOpaqueTexture.hlsl: the camera's opaque texture
// _CameraOpaqueTexture and SampleSceneColor / LoadSceneColor (written for pbrlab from Unity's
// documentation of URP's Opaque Texture and of these functions; URP's own file is under the
// Unity Companion License and is not copied).
//
// URP copies the camera's colour after its opaque objects (and the skybox) are drawn, before
// the transparent ones. The harness does the same job as a built-in GrabPass: a program that
// includes this file gets a grab of the target as drawn so far just before its object's first
// pass (importers/unity/material.py), bilinear-filtered, in the float target's linear colour.
// The harness draws opaque objects before blended ones, so a transparent object reads the
// opaque objects drawn before it; the sky is composited after the frame, so where no object
// was drawn the texture holds the cleared target (0), not the sky URP's copy would hold.
#ifndef PBRLAB_URP_DECLARE_OPAQUE_TEXTURE_HLSL
#define PBRLAB_URP_DECLARE_OPAQUE_TEXTURE_HLSL

#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"

TEXTURE2D_X(_CameraOpaqueTexture);
SAMPLER(sampler_CameraOpaqueTexture);

// The scene's colour at a [0, 1] screen position.
float3 SampleSceneColor(float2 uv) {
    return SAMPLE_TEXTURE2D_X(_CameraOpaqueTexture, sampler_CameraOpaqueTexture, uv).rgb;
}

// The scene's colour of the texel at integer pixel coordinates: its centre, where bilinear
// filtering reads that texel alone.
float3 LoadSceneColor(uint2 uv) {
    return SampleSceneColor((float2(uv) + 0.5) / _ScreenParams.xy);
}

#endif
