// pbr/unity/unity_cg.hlsl: the colour and normal helpers of Unity's UnityCG.cginc that
// surface shaders call, by Unity's names.
//
// Provides: UNITY_PI, UNITY_TWO_PI, UNITY_FOUR_PI, UNITY_HALF_PI, UNITY_INV_PI, UNITY_INV_TWO_PI,
//           UNITY_INV_FOUR_PI, UNITY_INV_HALF_PI (macros: UnityCG.cginc's whole family of pi's
//           multiples and reciprocals, to Unity's 12 significant digits);
//           vec3 UnpackNormalmapRGorAG(vec4 packednormal)   DXT5nm (x in a, y in g) or BC5 (x, y)
//           vec3 UnpackNormalWithScale(vec4 packednormal, float scale)
//           vec3 BlendNormals(vec3 n1, vec3 n2)                   (UnityStandardUtils.cginc)
//           float/vec3 LerpOneTo(b, t), vec3 LerpWhiteTo(vec3 b, float t)  (UnityStandardUtils.cginc)
//           float Luminance(vec3 rgb), float LinearRgbToLuminance(vec3 linearRgb)
//           vec3 GammaToLinearSpace(vec3 sRGB), vec3 LinearToGammaSpace(vec3 linRGB)   Unity's fits
//           float GammaToLinearSpaceExact(float value), float LinearToGammaSpaceExact(float value)
//           vec3 DecodeHDR(vec4 data, vec4 decodeInstructions)
//           vec3 UnpackNormalDXT5nm(vec4 packednormal)            DXT5nm only (x in a, y in g)
//           vec2 ParallaxOffset(float h, float height, vec3 viewDir)   tangent-space viewDir
//           vec4 ComputeGrabScreenPos(vec4 clipPos)   GL orientation (UNITY_UV_STARTS_AT_TOP unset)
//           unity_ColorSpaceGrey, unity_ColorSpaceDouble, unity_ColorSpaceLuminance (macros,
//           linear colour space: Unity's values when UNITY_COLORSPACE_GAMMA is undefined);
//           UNITY_PROJ_COORD(a) (= a), UNITY_OPAQUE_ALPHA(outputAlpha) (outputAlpha = 1.0);
//           fog macros as no-ops, Unity's definitions when no FOG_LINEAR / FOG_EXP / FOG_EXP2
//           variant is compiled (the harness has no fog): UNITY_FOG_COORDS(idx) and
//           UNITY_TRANSFER_FOG(o, outpos) expand to nothing (so a v2f struct keeps no fogCoord
//           member), UNITY_APPLY_FOG(coord, col) and UNITY_APPLY_FOG_COLOR(coord, col, fogCol)
//           leave col unchanged and never read coord.
// Include:  "pbr/unity/unity_cg.hlsl" (path relative to hlsl_ports/). Not part of pbr/pbr.hlsl: the
//           names are Unity's. UnpackNormal / UnpackScaleNormal (RGB or DXT5nm maps by
//           PBR_UNITY_NORMAL_MAP_ENCODING) are in pbr/unity/surface_standard.hlsl.
// Config macros read: UNITY_UV_STARTS_AT_TOP (ComputeGrabScreenPos: defined, the grab
//           texture's v runs downwards, Direct3D-like; the pbrlab harness renders with GL
//           conventions and leaves it undefined, as Unity does for its OpenGL targets, so a
//           shader's test of UNITY_UV_STARTS_AT_TOP takes the GL branch in both languages).
//
// Semantics: Unity 2018-2019 UnityCG.cginc (linear colour space, UNITY_NO_DXT5nm undefined
// for UnpackNormalmapRGorAG); the fits are Unity's (from Ian Taylor's "sRGB approximations
// for HLSL", chilliant.blogspot.com 2012), kept beside the exact IEC 61966-2-1 curves so a
// shader that calls them sees Unity's numbers, not pbrlab's. Float64 references:
// harness/pbrlab/maths/reference/unity_cg.py.
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_UNITY_UNITY_CG_HLSL
#define PBR_UNITY_UNITY_CG_HLSL
#include "pbr/common/shim.hlsl"  // generated from glsl/pbr/unity/unity_cg.glsl by harness/pbrlab/gpu/port_hlsl.py: edit the GLSL, then regenerate
#include "pbr/color/srgb.hlsl"

// pi, 2 pi, 4 pi, pi / 2 and their reciprocals (UnityCG.cginc names the same eight; the digits
// are pi's own, to 12 significant figures; tests/importers/unity/test_unity_builtin_names.py).
#define UNITY_PI 3.14159265359
#define UNITY_TWO_PI 6.28318530718
#define UNITY_FOUR_PI 12.5663706144
#define UNITY_HALF_PI 1.57079632679
#define UNITY_INV_PI 0.31830988618
#define UNITY_INV_TWO_PI 0.159154943092
#define UNITY_INV_FOUR_PI 0.0795774715459
#define UNITY_INV_HALF_PI 0.636619772368

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

// Unity's LerpOneTo / LerpWhiteTo: mix(1, b, t) written as 1 - t + b t, as Unity writes it
// (UnityStandardUtils.cginc; the occlusion and detail masks use them).
float LerpOneTo(float b, float t) {
    return (1.0 - t) + b * t;
}

float3 LerpOneTo(float3 b, float t) {
    return ((float3)(1.0 - t)) + b * t;
}

float3 LerpWhiteTo(float3 b, float t) {
    return ((float3)(1.0 - t)) + b * t;
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
// Unity 2018+'s three-argument form (UnityCG.cginc) names the colour space: colorspaceIsGamma
// != 0 skips the exponent (a gamma-space project's RGBM is multiplier * alpha * rgb).
float3 DecodeHDR(float4 data, float4 decodeInstructions, int colorspaceIsGamma) {
    float alpha = decodeInstructions.w * (data.a - 1.0) + 1.0;
    if (colorspaceIsGamma != 0) {
        return (decodeInstructions.x * alpha) * data.rgb;
    }
    return (decodeInstructions.x * pow(alpha, decodeInstructions.y)) * data.rgb;
}

float3 DecodeHDR(float4 data, float4 decodeInstructions) {
    return DecodeHDR(data, decodeInstructions, 0);
}

// Unity's DXT5nm-only unpack (UnityCG.cginc UnpackNormalDXT5nm): x from alpha, y from green;
// unlike UnpackNormalmapRGorAG it ignores red, so a BC5 or RGB map does not decode through it.
float3 UnpackNormalDXT5nm(float4 packednormal) {
    float2 xy = packednormal.wy * 2.0 - 1.0;
    return float3(xy, sqrt(1.0 - clamp(dot(xy, xy), 0.0, 1.0)));
}

// Unity's ParallaxOffset (UnityCG.cginc): parallax mapping (Kaneko et al. 2001, "Detailed
// shape representation with parallax mapping", ICAT): the height sample h in [0, 1] is
// centred on the surface, (h - 1/2) * height, and shifts the UV along the tangent-space view
// direction by that much per unit of depth, xy / z. Unity adds PBR_UNITY_PARALLAX_Z_BIAS to
// z, between Kaneko's xy / z and Welsh's offset limiting (2004, xy alone), so the shift stays
// finite where the view grazes the surface: at most 1/0.42 = 2.4 times the centred height
// for any view above it (z >= 0).
#define PBR_UNITY_PARALLAX_Z_BIAS 0.42
float2 ParallaxOffset(float h, float height, float3 viewDir) {
    float centred = (h - 0.5) * height;
    float3 v = normalize(viewDir);
    return centred * v.xy / (v.z + PBR_UNITY_PARALLAX_Z_BIAS);
}

// Unity's ComputeGrabScreenPos (UnityCG.cginc): as ComputeScreenPos, clip xy mapped to
// [0, w] (x/w, y/w in [0, 1] after the divide, zw kept), for sampling a GrabPass texture;
// where a target's texture rows start at the top (UNITY_UV_STARTS_AT_TOP) y is flipped.
#ifdef UNITY_UV_STARTS_AT_TOP
#define PBR_UNITY_GRAB_Y_SIGN -1.0
#else
#define PBR_UNITY_GRAB_Y_SIGN 1.0
#endif
float4 ComputeGrabScreenPos(float4 pos) {
    float2 xy = 0.5 * (float2(pos.x, PBR_UNITY_GRAB_Y_SIGN * pos.y) + pos.w);
    return float4(xy, pos.zw);
}

// Unity's colour-space constants in linear colour space (UnityCG.cginc, the branch without
// UNITY_COLORSPACE_GAMMA): grey is the exact sRGB decode of 0.5 (IEC 61966-2-1:
// ((0.5 + 0.055) / 1.055)^2.4), double is 2^2.2, the linear value of a gamma-space 2 (both
// with alpha kept in gamma space); the luminance weights as Luminance() uses them, w = 1
// marking linear mode (tests/surface/test_unity_cg.py checks grey and double).
#define unity_ColorSpaceGrey float4(0.214041144, 0.214041144, 0.214041144, 0.5)
#define unity_ColorSpaceDouble float4(4.59479380, 4.59479380, 4.59479380, 2.0)
#define unity_ColorSpaceLuminance float4(PBR_UNITY_LUMINANCE_WEIGHTS, 1.0)

// HLSLSupport.cginc: the coordinate of a projective texture read as written (a few old
// platforms needed a swizzle there; none here).
#define UNITY_PROJ_COORD(a) a
// UnityCG.cginc: an opaque pass writes alpha 1 (Unity calls it where no alpha blending is on).
#define UNITY_OPAQUE_ALPHA(outputAlpha) outputAlpha = 1.0

// UnityCG.cginc's fog helpers with no fog variant compiled (no fog in the harness).
#define UNITY_FOG_COORDS(idx)
#define UNITY_TRANSFER_FOG(o, outpos)
#define UNITY_APPLY_FOG_COLOR(coord, col, fogCol)
#define UNITY_APPLY_FOG(coord, col)
#endif
