// pbrlab stand-in for Core RP's ShaderLibrary/ACES.hlsl: the Academy Color Encoding System's
// colour-space conversions and the Reference Rendering Transform's helpers that URP's
// tonemapping and post-processing shaders call (written for pbrlab from the ACES documents and
// the Academy's published CTL, which Core RP's file follows; Core RP's own file is under the
// Unity Companion License and is not copied). The float64 reference, with the sources of each
// value, is harness/pbrlab/maths/reference/aces_colorspaces.py:
// - the matrices are computed there from the primaries and white points (SMPTE ST 2065-1's
//   AP0, S-2014-004's AP1, BT.709 with D65; RP 177's RGB -> XYZ; Bradford adaptation between
//   the ACES white and D65) and written here to 9 decimals; Unity's names, applied as mul(M, c);
// - ACEScc's encoding: S-2014-003 section 4.4;
// - the RRT helpers and constants: aces-dev's ACESlib.RRT_Common / ODT_Common / Utilities_Color.
// Not provided: the segmented-spline RRT and ODTs (RRT, ODT_*), which a shader calling them is
// refused for at compile time, naming the function.
#ifndef PBRLAB_CORE_RP_ACES_HLSL
#define PBRLAB_CORE_RP_ACES_HLSL

#include "Packages/com.unity.render-pipelines.core/ShaderLibrary/Common.hlsl"

// ACEScc's log code values of the largest half float and of 0.18 (S-2014-003's formula)
#define ACEScc_MAX 1.4679964
#define ACEScc_MIDGRAY 0.4135884

static const float3x3 sRGB_2_AP0 = float3x3(
    0.439632982, 0.382988698, 0.177378320,
    0.089776443, 0.813439429, 0.096784128,
    0.017541170, 0.111546553, 0.870912276);
static const float3x3 sRGB_2_AP1 = float3x3(
    0.613097402, 0.339523146, 0.047379451,
    0.070193722, 0.916353879, 0.013452398,
    0.020615593, 0.109569773, 0.869814634);
static const float3x3 AP0_2_sRGB = float3x3(
    2.521686187, -1.134130988, -0.387555199,
    -0.276479914, 1.372719088, -0.096239173,
    -0.015378065, -0.152975336, 1.168353401);
static const float3x3 AP1_2_sRGB = float3x3(
    1.705050993, -0.621792121, -0.083258872,
    -0.130256418, 1.140804737, -0.010548319,
    -0.024003357, -0.128968976, 1.152972333);
static const float3x3 AP0_2_AP1_MAT = float3x3(
    1.451439316, -0.236510747, -0.214928569,
    -0.076553773, 1.176229700, -0.099675926,
    0.008316148, -0.006032450, 0.997716301);
static const float3x3 AP1_2_AP0_MAT = float3x3(
    0.695452241, 0.140678696, 0.163869062,
    0.044794563, 0.859671118, 0.095534318,
    -0.005525883, 0.004025210, 1.001500672);
static const float3x3 AP1_2_XYZ_MAT = float3x3(
    0.662454181, 0.134004206, 0.156187687,
    0.272228717, 0.674081766, 0.053689517,
    -0.005574649, 0.004060734, 1.010339100);
static const float3x3 XYZ_2_AP1_MAT = float3x3(
    1.641023380, -0.324803294, -0.236424695,
    -0.663662859, 1.615331592, 0.016756348,
    0.011721894, -0.008284442, 0.988394859);
static const float3x3 XYZ_2_REC709_MAT = float3x3(
    3.240969942, -1.537383178, -0.498610760,
    -0.969243636, 1.875967502, 0.041555057,
    0.055630080, -0.203976959, 1.056971514);
static const float3x3 D60_2_D65_CAT = float3x3(
    0.987224009, -0.006113229, 0.015953288,
    -0.007598372, 1.001861485, 0.005330036,
    0.003072577, -0.005095962, 1.081680603);

// AP1's luminance weights: AP1_2_XYZ_MAT's Y row
static const float3 AP1_RGB2Y = float3(0.272228717, 0.674081766, 0.053689517);

// Unity's linear colours have BT.709 (sRGB) primaries
float3 unity_to_ACES(float3 x) { return mul(sRGB_2_AP0, x); }
float3 ACES_to_unity(float3 x) { return mul(AP0_2_sRGB, x); }
float3 unity_to_ACEScg(float3 x) { return mul(sRGB_2_AP1, x); }
float3 ACEScg_to_unity(float3 x) { return mul(AP1_2_sRGB, x); }
float3 ACES_to_ACEScg(float3 x) { return mul(AP0_2_AP1_MAT, x); }
float3 ACEScg_to_ACES(float3 x) { return mul(AP1_2_AP0_MAT, x); }

// ACES2065-1 (linear AP0) -> ACEScc (log AP1 code values; the caller converts the primaries).
// S-2014-003 4.4: (log2(x) + 9.72) / 17.52, below 2^-15 log2(2^-16 + x / 2) in its place.
float ACES_to_ACEScc(float x) {
    x = max(x, 0.0);
    return x < 0.000030517578125 ? (log2(0.0000152587890625 + x * 0.5) + 9.72) / 17.52 : (log2(x) + 9.72) / 17.52;
}
float3 ACES_to_ACEScc(float3 x) { return float3(ACES_to_ACEScc(x.r), ACES_to_ACEScc(x.g), ACES_to_ACEScc(x.b)); }

// Its inverse, up to the largest half float (65504), where ACEScc's range ends
float ACEScc_to_ACES(float x) {
    if (x < -0.3013698630)  // (9.72 - 15) / 17.52
        return (exp2(x * 17.52 - 9.72) - 0.0000152587890625) * 2.0;
    if (x < ACEScc_MAX)
        return min(exp2(x * 17.52 - 9.72), 65504.0);
    return 65504.0;
}
float3 ACEScc_to_ACES(float3 x) { return float3(ACEScc_to_ACES(x.r), ACEScc_to_ACES(x.g), ACEScc_to_ACES(x.b)); }

// The RRT's saturation proxy: (max - min) / max, each floored (1e-4, 1e-2 for the divisor)
float rgb_2_saturation(float3 rgb) {
    float mi = min(min(rgb.r, rgb.g), rgb.b);
    float ma = max(max(rgb.r, rgb.g), rgb.b);
    return (max(ma, 1e-4) - max(mi, 1e-4)) / max(ma, 1e-2);
}

// A luminance proxy YC = (r + g + b + 1.75 chroma) / 3, chroma = sqrt(b(b-g) + g(g-r) + r(r-b))
float rgb_2_yc(float3 rgb) {
    float k = rgb.b * (rgb.b - rgb.g) + rgb.g * (rgb.g - rgb.r) + rgb.r * (rgb.r - rgb.b);
    return (rgb.r + rgb.g + rgb.b + 1.75 * sqrt(max(k, 0.0))) / 3.0;
}

// The geometric hue angle in degrees, [0, 360); 0 for a neutral colour
float rgb_2_hue(float3 rgb) {
    float hue = 0.0;
    if (!(rgb.r == rgb.g && rgb.g == rgb.b))
        hue = 57.29577951308232 * atan2(1.7320508075688772 * (rgb.g - rgb.b), 2.0 * rgb.r - rgb.g - rgb.b);
    return hue < 0.0 ? hue + 360.0 : hue;
}

// A hue relative to centerH, in (-180, 180]
float center_hue(float hue, float centerH) {
    float h = hue - centerH;
    if (h < -180.0) h += 360.0;
    else if (h > 180.0) h -= 360.0;
    return h;
}

// 0 to 1 over x in -2 to 2
float sigmoid_shaper(float x) {
    float t = max(1.0 - abs(x / 2.0), 0.0);
    float s = x > 0.0 ? 1.0 : (x < 0.0 ? -1.0 : 0.0);
    return (1.0 + s * (1.0 - t * t)) / 2.0;
}

// The RRT's glow gain at a YC: the full gain below 2/3 mid, none above 2 mid, between them
// gain (mid / yc - 1/2)
float glow_fwd(float ycIn, float glowGainIn, float glowMid) {
    if (ycIn <= 2.0 / 3.0 * glowMid) return glowGainIn;
    if (ycIn >= 2.0 * glowMid) return 0.0;
    return glowGainIn * (glowMid / ycIn - 0.5);
}

static const float RRT_GLOW_GAIN = 0.05;
static const float RRT_GLOW_MID = 0.08;
static const float RRT_RED_SCALE = 0.82;
static const float RRT_RED_PIVOT = 0.03;
static const float RRT_RED_HUE = 0.0;
static const float RRT_RED_WIDTH = 135.0;
static const float RRT_SAT_FACTOR = 0.96;
static const float ODT_SAT_FACTOR = 0.93;
static const float DIM_SURROUND_GAMMA = 0.9811;
static const float CINEMA_WHITE = 48.0;
static const float CINEMA_BLACK = 0.02;  // CINEMA_WHITE / 2400

float3 XYZ_2_xyY(float3 XYZ) {
    float d = max(XYZ.x + XYZ.y + XYZ.z, 1e-10);
    return float3(XYZ.x / d, XYZ.y / d, XYZ.y);
}
float3 xyY_2_XYZ(float3 xyY) {
    float m = xyY.z / max(xyY.y, 1e-10);
    return float3(xyY.x * m, xyY.z, (1.0 - xyY.x - xyY.y) * m);
}

// ODT_Common's dark -> dim surround compensation: luminance Y^0.9811, chromaticity kept (AP1 in
// and out)
float3 darkSurround_to_dimSurround(float3 linearCV) {
    float3 xyY = XYZ_2_xyY(mul(AP1_2_XYZ_MAT, linearCV));
    xyY.z = pow(clamp(xyY.z, 0.0, 65504.0), DIM_SURROUND_GAMMA);
    return mul(XYZ_2_AP1_MAT, xyY_2_XYZ(xyY));
}

#endif
