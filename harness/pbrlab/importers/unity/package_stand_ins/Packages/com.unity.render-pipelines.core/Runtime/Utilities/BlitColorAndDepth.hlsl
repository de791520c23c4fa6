// pbrlab stand-in for Core RP's Runtime/Utilities/BlitColorAndDepth.hlsl: Blit.hlsl's names (the
// source _BlitTexture, Vert over the full-screen triangle) and FragColorOnly, the source's copy
// (written for pbrlab from Unity's documentation of the Blitter; Core RP's own file is under
// the Unity Companion License and is not copied). FragColorAndDepth, which also writes the
// depth of _InputDepthTexture, a texture the application binds, is not provided.
#ifndef PBRLAB_CORE_RP_BLIT_COLOR_AND_DEPTH_HLSL
#define PBRLAB_CORE_RP_BLIT_COLOR_AND_DEPTH_HLSL

#include "Packages/com.unity.render-pipelines.core/Runtime/Utilities/Blit.hlsl"

float4 FragColorOnly(Varyings input) : SV_Target {
    return SAMPLE_TEXTURE2D_LOD(_BlitTexture, sampler_LinearClamp, input.texcoord, _BlitMipLevel);
}

#endif
