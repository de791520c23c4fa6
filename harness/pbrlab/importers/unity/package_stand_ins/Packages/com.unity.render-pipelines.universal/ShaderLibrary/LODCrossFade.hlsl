// pbrlab stand-in for URP's ShaderLibrary/LODCrossFade.hlsl: LODFadeCrossFade(positionCS), the
// dithered cross-fade between two levels of a LOD Group (written for pbrlab from Unity's
// documentation of LOD Group's "Cross Fade" mode and of unity_LODFade, and observed behaviour;
// URP's own file is under the Unity Companion License and is not copied).
//
// Unity: while a renderer fades, unity_LODFade.x is its fade f in [-1, 1] (the level fading in
// positive, the one fading out negative) and a pixel is discarded where f - sign(f) n < 0, n the
// pixel's value of a screen-space dither pattern in [0, 1] (URP 14: a blue-noise texture). A
// renderer that is not fading has the keyword LOD_FADE_CROSSFADE off and does not call this.
// pbrlab's scenes have no LOD Group: every object is its only level, fully shown, f = 1, where
// no pixel is discarded whatever the pattern; the pattern here is the 4 x 4 ordered-dither
// (Bayer) matrix's thresholds (k + 0.5) / 16, in place of Unity's blue-noise texture.
#ifndef PBRLAB_URP_LOD_CROSS_FADE_HLSL
#define PBRLAB_URP_LOD_CROSS_FADE_HLSL

#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"

// unity_LODFade: Core.hlsl's (1, 1, 0, 0), no LOD Group here.

// |x| with the sign of s (s = 0 counts as positive)
float CopySign(float x, float s) { return s >= 0.0 ? abs(x) : -abs(x); }

// The 4 x 4 Bayer matrix's threshold of a pixel: (index + 0.5) / 16
float pbrlab_lod_dither(float2 pixel) {
    static const float bayer[16] = { 0.0, 8.0, 2.0, 10.0, 12.0, 4.0, 14.0, 6.0,
                                     3.0, 11.0, 1.0, 9.0, 15.0, 7.0, 13.0, 5.0 };
    int2 p = int2(fmod(floor(pixel), 4.0));
    return (bayer[p.y * 4 + p.x] + 0.5) / 16.0;
}

void LODFadeCrossFade(float4 positionCS) {
    float d = unity_LODFade.x - CopySign(pbrlab_lod_dither(positionCS.xy), unity_LODFade.x);
    clip(d);
}

#endif
