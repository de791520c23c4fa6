// s47-glslinc: URP's SurfaceData filled from a colour: albedo (max, min, 0.75) of its channels
// through Core RP's Max3 / Min3.
#ifndef S47_GLSLINC_TONE_INCLUDED
#define S47_GLSLINC_TONE_INCLUDED
#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Lighting.hlsl"

SurfaceData ToneSurface(half3 colour)
{
    SurfaceData surface = (SurfaceData)0;
    surface.albedo = half3(Max3(colour.r, colour.g, colour.b), Min3(colour.r, colour.g, colour.b), 0.75);
    surface.alpha = 1.0;
    return surface;
}
#endif
