// pbrlab stand-in for Core RP's Runtime/Utilities/BlitColorAndDepth.hlsl: Blit.hlsl's names (the
// source _BlitTexture, Vert over the full-screen triangle), FragColorOnly (the source's copy) and
// FragColorAndDepth (the copy, and the depth of _InputDepthTexture as the fragment's depth)
// (written for pbrlab from Unity's documentation of the Blitter; Core RP's own file is under the
// Unity Companion License and is not copied). _InputDepthTexture is a texture the application
// binds, unbound here; pbrlab's pass entry writes the colour target alone (SV_Depth is not written).
#ifndef PBRLAB_CORE_RP_BLIT_COLOR_AND_DEPTH_HLSL
#define PBRLAB_CORE_RP_BLIT_COLOR_AND_DEPTH_HLSL

#include "Packages/com.unity.render-pipelines.core/Runtime/Utilities/Blit.hlsl"

TEXTURE2D(_InputDepthTexture);

float4 FragColorOnly(Varyings input) : SV_Target {
    return SAMPLE_TEXTURE2D_LOD(_BlitTexture, sampler_LinearClamp, input.texcoord, _BlitMipLevel);
}

struct PixelData {
    float4 color : SV_Target;
    float depth : SV_Depth;
};

PixelData FragColorAndDepth(Varyings input) {
    PixelData pd;
    pd.color = SAMPLE_TEXTURE2D_LOD(_BlitTexture, sampler_LinearClamp, input.texcoord, _BlitMipLevel);
    pd.depth = SAMPLE_TEXTURE2D_LOD(_InputDepthTexture, sampler_PointClamp, input.texcoord, _BlitMipLevel).x;
    return pd;
}

#endif
