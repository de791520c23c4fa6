// pbrlab stand-in for Core RP's ShaderLibrary/Filtering.hlsl (written for pbrlab; Core RP's own
// file is under the Unity Companion License and is not copied). Amplify Shader Editor's URP
// templates include it in every pass without calling it. Its B-spline weights and bicubic /
// biquadratic texture filters (BSpline*, BiquadraticFilter, BicubicFilter,
// SampleTexture2DBicubic, SampleTexture2DBiquadratic, SampleTexture2DArrayBicubic(LOD)) are not
// defined here: a program that calls one is refused naming it (importers/unity/unprovided.py).
#ifndef PBRLAB_CORE_RP_FILTERING_HLSL
#define PBRLAB_CORE_RP_FILTERING_HLSL
#endif
