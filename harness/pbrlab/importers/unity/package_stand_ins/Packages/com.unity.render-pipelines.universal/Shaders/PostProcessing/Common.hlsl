// pbrlab stand-in for URP's Shaders/PostProcessing/Common.hlsl: the utility functions of URP's
// post-processing shaders (written for pbrlab from Unity's documentation of URP's
// post-processing effects and the sRGB standard; URP's own file is under the Unity Companion
// License and is not copied). As URP's, it includes Core RP's Color.hlsl and Blit.hlsl (URP 13
// on: Vert, Varyings.texcoord); a shader written for URP 12, whose Common.hlsl included
// Utils/Fullscreen.hlsl (FullscreenVert, Varyings.uv) instead, is told by its use of
// FullscreenVert (importers/unity/user_definitions.py) and gets URP 12's; one written for URP 10,
// whose Common.hlsl declared a mesh's Attributes { positionOS, uv } and Vert, by its reading
// Attributes.positionOS, and gets URP 10's.
// Provided: GetLuminance, GetSRGBToLinear / GetLinearToSRGB, ApplyVignette, ApplyTonemap
// without a tonemapping keyword. Not provided: the colour-grading LUT, grain, dithering and
// FXAA functions, and ApplyTonemap's ACES and Neutral branches (refused with #error).
#ifndef PBRLAB_URP_POST_PROCESSING_COMMON_HLSL
#define PBRLAB_URP_POST_PROCESSING_COMMON_HLSL

#include "Packages/com.unity.render-pipelines.core/ShaderLibrary/Color.hlsl"
#include "Packages/com.unity.render-pipelines.core/ShaderLibrary/GlobalSamplers.hlsl"
#ifdef PBRLAB_USER_READS_FullscreenVert
#include "Packages/com.unity.render-pipelines.universal/Shaders/Utils/Fullscreen.hlsl"
#elif !defined(PBRLAB_USER_READS_Attributes_positionOS)
#include "Packages/com.unity.render-pipelines.core/Runtime/Utilities/Blit.hlsl"
#endif

// URP 10's layout, which a shader reading Attributes.positionOS (importers/unity/
// user_definitions.py) was written for: a mesh (URP 10 drew its post-processing over a
// full-screen mesh; pbrlab draws the object's), the vertex's object position through the
// object's transform and its first uv set passed on as Varyings.uv.
#if defined(PBRLAB_USER_READS_Attributes_positionOS) && !defined(PBRLAB_USER_READS_FullscreenVert)
#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
struct Attributes {
    float4 positionOS : POSITION;
    float2 uv : TEXCOORD0;
    UNITY_VERTEX_INPUT_INSTANCE_ID
};
struct Varyings {
    float4 positionCS : SV_POSITION;
    float2 uv : TEXCOORD0;
    UNITY_VERTEX_OUTPUT_STEREO
};
Varyings Vert(Attributes input) {
    Varyings output;
    output.positionCS = TransformObjectToHClip(input.positionOS.xyz);
    output.uv = input.uv;
    return output;
}
#endif

// Rec. 709 luminance of a linear colour (Core RP Color.hlsl's Luminance weights, BT.709 / sRGB primaries)
float GetLuminance(float3 colorLinear) { return dot(colorLinear, float3(0.2126729, 0.7151522, 0.0721750)); }

// The exact sRGB curves (Color.hlsl), or their fast approximations under
// _USE_FAST_SRGB_LINEAR_CONVERSION, as URP's
#if defined(_USE_FAST_SRGB_LINEAR_CONVERSION) && _USE_FAST_SRGB_LINEAR_CONVERSION != 0
float3 GetSRGBToLinear(float3 c) { return FastSRGBToLinear(c); }
float4 GetSRGBToLinear(float4 c) { return FastSRGBToLinear(c); }
float3 GetLinearToSRGB(float3 c) { return FastLinearToSRGB(c); }
float4 GetLinearToSRGB(float4 c) { return FastLinearToSRGB(c); }
#else
float3 GetSRGBToLinear(float3 c) { return SRGBToLinear(c); }
float4 GetSRGBToLinear(float4 c) { return SRGBToLinear(c); }
float3 GetLinearToSRGB(float3 c) { return LinearToSRGB(c); }
float4 GetLinearToSRGB(float4 c) { return LinearToSRGB(c); }
#endif

// URP's Vignette: d = |uv - center| * intensity, d.x *= roundness, the factor
// saturate(1 - d.d)^smoothness blends from the vignette colour (0) to no change (1).
float3 ApplyVignette(float3 input, float2 uv, float2 center, float intensity, float roundness, float smoothness,
                     float3 color) {
    float2 dist = abs(uv - center) * intensity;
    dist.x *= roundness;
    float vfactor = pow(saturate(1.0 - dot(dist, dist)), smoothness);
    return input * lerp(color, float3(1.0, 1.0, 1.0), vfactor);
}

// URP's tonemapping with no mode selected: the colour clamped to [0, 1]
float3 ApplyTonemap(float3 input) {
#if (defined(_TONEMAP_ACES) && _TONEMAP_ACES != 0) || (defined(_TONEMAP_NEUTRAL) && _TONEMAP_NEUTRAL != 0)
#error "URP's ACES and Neutral tonemapping (ApplyTonemap under _TONEMAP_ACES / _TONEMAP_NEUTRAL) is not provided by pbrlab's stand-in"
#endif
    return saturate(input);
}

#endif
