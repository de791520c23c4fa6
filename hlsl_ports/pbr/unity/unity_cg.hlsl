// pbr/unity/unity_cg.hlsl: the colour and normal helpers of Unity's UnityCG.cginc that
// surface shaders call, by Unity's names.
//
// Provides: UNITY_PI, UNITY_TWO_PI, UNITY_INV_PI (macros);
//           vec3 UnpackNormalmapRGorAG(vec4 packednormal)   DXT5nm (x in a, y in g) or BC5 (x, y)
//           vec3 UnpackNormalWithScale(vec4 packednormal, float scale)
//           vec3 BlendNormals(vec3 n1, vec3 n2)                   (UnityStandardUtils.cginc)
//           float Luminance(vec3 rgb), float LinearRgbToLuminance(vec3 linearRgb)
//           vec3 GammaToLinearSpace(vec3 sRGB), vec3 LinearToGammaSpace(vec3 linRGB)   Unity's fits
//           float GammaToLinearSpaceExact(float value), float LinearToGammaSpaceExact(float value)
//           vec3 DecodeHDR(vec4 data, vec4 decodeInstructions)
// Include:  "pbr/unity/unity_cg.hlsl" (path relative to hlsl_ports/). Not part of pbr/pbr.hlsl: the
//           names are Unity's. UnpackNormal / UnpackScaleNormal (RGB maps, Unity's
//           UNITY_NO_DXT5nm branch) are in pbr/unity/surface_standard.hlsl.
// Config macros read: none.
//
// Semantics: Unity 2018-2019 UnityCG.cginc (linear colour space, UNITY_NO_DXT5nm undefined
// for UnpackNormalmapRGorAG); the fits are Unity's (from Ian Taylor's "sRGB approximations
// for HLSL", chilliant.blogspot.com 2012), kept beside the exact IEC 61966-2-1 curves so a
// shader that calls them sees Unity's numbers, not pbrlab's. Float64 references:
// harness/pbrlab/reference/unity_cg.py.
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_UNITY_UNITY_CG_HLSL
#define PBR_UNITY_UNITY_CG_HLSL
#include "pbr/common/shim.hlsl"  // generated from glsl/pbr/unity/unity_cg.glsl by harness/pbrlab/port_hlsl.py: edit the GLSL, then regenerate
#include "pbr/color/srgb.hlsl"

#define UNITY_PI 3.14159265359
#define UNITY_TWO_PI 6.28318530718
#define UNITY_INV_PI 0.31830988618

// Unity's unity_ColorSpaceLuminance in linear colour space (UnityCG.cginc, "Linear values";
// Unity marks it legacy: the gamma-space weights (0.22, 0.707, 0.071) run through its decode).
#define PBR_UNITY_LUMINANCE_WEIGHTS float3(0.0396819152, 0.458021790, 0.00609653955)
// Rec. 709 / sRGB relative luminance of linear RGB (IEC 61966-2-1, D65), Unity's
// LinearRgbToLuminance constants.
#define PBR_UNITY_REC709_LUMINANCE float3(0.2126729, 0.7151522, 0.0721750)

// Unity's GammaToLinearSpace fit: a cubic in the encoded value (Taylor 2012), max abs error
// 1.8e-3 against the exact curve on [0, 1] (tests/surface/test_unity_cg.py measures it).
#define PBR_UNITY_G2L_A 0.305306011
#define PBR_UNITY_G2L_B 0.682171111
#define PBR_UNITY_G2L_C 0.012522878
// Unity's LinearToGammaSpace: 1.055 x^(1/2.4) - 0.055 without the linear toe (Taylor 2012).
#define PBR_UNITY_L2G_EXPONENT 0.416666667

// DXT5nm stores x in alpha and y in green (r = 1); BC5 stores (x, y, 0, 1): x *= a maps
// both to x (Unity's "This do the trick"); z is rebuilt from a unit normal.
float3 UnpackNormalmapRGorAG(float4 packednormal) {
    packednormal.x *= packednormal.w;
    float3 normal;
    normal.xy = packednormal.xy * 2.0 - 1.0;
    normal.z = sqrt(1.0 - clamp(dot(normal.xy, normal.xy), 0.0, 1.0));
    return normal;
}

float3 UnpackNormalWithScale(float4 packednormal, float scale) {
    packednormal.x *= packednormal.w;
    float3 normal;
    normal.xy = (packednormal.xy * 2.0 - 1.0) * scale;
    normal.z = sqrt(1.0 - clamp(dot(normal.xy, normal.xy), 0.0, 1.0));
    return normal;
}

// Unity's BlendNormals: sum of xy, product of z, normalised (UnityStandardUtils.cginc).
float3 BlendNormals(float3 n1, float3 n2) {
    return normalize(float3(n1.xy + n2.xy, n1.z * n2.z));
}

float Luminance(float3 rgb) {
    return dot(rgb, PBR_UNITY_LUMINANCE_WEIGHTS);
}

float LinearRgbToLuminance(float3 linearRgb) {
    return dot(linearRgb, PBR_UNITY_REC709_LUMINANCE);
}

float3 GammaToLinearSpace(float3 sRGB) {
    return sRGB * (sRGB * (sRGB * PBR_UNITY_G2L_A + PBR_UNITY_G2L_B) + PBR_UNITY_G2L_C);
}

float3 LinearToGammaSpace(float3 linRGB) {
    linRGB = max(linRGB, float3(0.0, 0.0, 0.0));
    return max(1.055 * pow(linRGB, float3(PBR_UNITY_L2G_EXPONENT, PBR_UNITY_L2G_EXPONENT,
                                        PBR_UNITY_L2G_EXPONENT)) - 0.055, float3(0.0, 0.0, 0.0));
}

float GammaToLinearSpaceExact(float value) {
    return pbr_srgb_to_linear(value);
}

float LinearToGammaSpaceExact(float value) {
    return pbr_linear_to_srgb(value);
}

// Unity's DecodeHDR (linear colour space, not UNITY_USE_NATIVE_HDR): RGBM-style
// decode, decodeInstructions = (multiplier, exponent, 0, use alpha). The harness's
// environment is float, so unity_SpecCube0_HDR = (1, 1, 0, 0) makes it the identity.
float3 DecodeHDR(float4 data, float4 decodeInstructions) {
    float alpha = decodeInstructions.w * (data.a - 1.0) + 1.0;
    return (decodeInstructions.x * pow(alpha, decodeInstructions.y)) * data.rgb;
}
#endif
