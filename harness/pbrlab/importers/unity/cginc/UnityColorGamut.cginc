// pbrlab stand-in for Unity's UnityColorGamut.cginc (the built-in pipeline's HDR output
// encodings: Internal-BlitCopyHDRTonemappedToSDR and the HDR blits read it).
//
// Provides: the gamut codes kColorGamutSRGB (0), kColorGamutRec709 (1), kColorGamutRec2020 (2),
//   kColorGamutDisplayP3 (3), kColorGamutHDR10 (4), kColorGamutDolbyHDR (5), kColorGamutP3D65G22
//   (6); kReferenceLuminanceWhiteForRec709 (80 nits: Unity's value off Metal, which pbrlab is);
//   LinearToSRGB(c), SRGBToLinear(c); the gamut matrices Rec709ToRec2020, Rec2020ToRec709,
//   Rec709ToP3D65Mat, P3D65MatToRec709; PQ_M1, PQ_M2, PQ_C1, PQ_C2, PQ_C3, LinearToST2084(c),
//   ST2084ToLinear(c); LinearToGamma22(c), Gamma22ToLinear(c);
//   SimpleHDRDisplayToneMapAndOETF(scene, colorGamut, forceGammaToLinear, nitsForPaperWhite,
//   maxDisplayNits) and its inverse InverseSimpleHDRDisplayToneMapAndOETF (same arguments).
// Unity's file: the same names (Unity 2019.4+ built-in shaders), read for their behaviour and
//   written here anew from the standards:
//   - sRGB: IEC 61966-2-1:1999, the piecewise curve (linear below 0.0031308 / 0.04045, else
//     1.055 L^(1/2.4) - 0.055 and its inverse);
//   - PQ: SMPTE ST 2084:2014 (= ITU-R BT.2100-2 Table 4), m1 = 2610/16384, m2 = 2523/4096 x 128,
//     c1 = 3424/4096, c2 = 2413/4096 x 32, c3 = 2392/4096 x 32, on luminance / 10000 nits;
//   - the gamut matrices: RGB -> XYZ from each space's primaries and D65 white (SMPTE RP 177),
//     BT.709 (ITU-R BT.709-6 item 1.3), BT.2020 (ITU-R BT.2020-2 Table 3), P3-D65 (SMPTE EG
//     432-1), one's matrix times the other's inverse, in float64, to 10 digits
//     (pbrlab.maths.reference.color_gamut computes them; tests/importers/unity/
//     test_color_gamut.py checks these against it).
// Differences: none in the maths. Unity's matrices are the same to its 6 digits. The paths
//   kColorGamutRec2020, DisplayP3 and DolbyHDR take Unity's last branch (Rec.709 scaled by
//   nitsForPaperWhite / 80), as Unity's do. HLG (BT.2100) is no part of Unity's file.
// Cg text in the plain subset harness/pbrlab/importers/unity/port.py ports to GLSL.
#ifndef PBRLAB_UNITY_COLOR_GAMUT_CGINC
#define PBRLAB_UNITY_COLOR_GAMUT_CGINC

#define kColorGamutSRGB         0
#define kColorGamutRec709       1
#define kColorGamutRec2020      2
#define kColorGamutDisplayP3    3
#define kColorGamutHDR10        4
#define kColorGamutDolbyHDR     5
#define kColorGamutP3D65G22     6

// The luminance, in nits, of Rec.709's reference white (Unity: 80, 100 on Metal).
#define kReferenceLuminanceWhiteForRec709 80

// IEC 61966-2-1's encoding of one linear channel.
float pbrlab_srgb_encode(float value)
{
    return value < 0.0031308 ? 12.92 * value : 1.055 * pow(abs(value), 1.0 / 2.4) - 0.055;
}

// IEC 61966-2-1's decoding of one encoded channel.
float pbrlab_srgb_decode(float value)
{
    return value < 0.04045 ? value / 12.92 : pow(abs(value + 0.055) / 1.055, 2.4);
}

float3 LinearToSRGB(float3 color)
{
    return float3(pbrlab_srgb_encode(color.r), pbrlab_srgb_encode(color.g), pbrlab_srgb_encode(color.b));
}

float3 SRGBToLinear(float3 color)
{
    return float3(pbrlab_srgb_decode(color.r), pbrlab_srgb_decode(color.g), pbrlab_srgb_decode(color.b));
}

// Linear BT.709 RGB to linear BT.2020 RGB (rows: the output's r, g, b), and back.
static const float3x3 Rec709ToRec2020 = float3x3(
    0.6274038959, 0.3292830384, 0.0433130657,
    0.0690972894, 0.9195403951, 0.0113623156,
    0.0163914389, 0.0880133079, 0.8955952532);

static const float3x3 Rec2020ToRec709 = float3x3(
    1.6604910021, -0.5876411388, -0.0728498633,
    -0.1245504745, 1.1328998971, -0.0083494226,
    -0.0181507634, -0.1005788980, 1.1187296614);

// Linear BT.709 RGB to linear P3-D65 RGB, and back.
static const float3x3 Rec709ToP3D65Mat = float3x3(
    0.8224619687, 0.1775380313, 0.0,
    0.0331941989, 0.9668058011, 0.0,
    0.0170826307, 0.0723974407, 0.9105199286);

static const float3x3 P3D65MatToRec709 = float3x3(
    1.2249401763, -0.2249401763, 0.0,
    -0.0420569547, 1.0420569547, 0.0,
    -0.0196375546, -0.0786360456, 1.0982736001);

// SMPTE ST 2084's constants.
#define PQ_M1 (2610.0 / 4096.0 / 4.0)
#define PQ_M2 (2523.0 / 4096.0 * 128.0)
#define PQ_C1 (3424.0 / 4096.0)
#define PQ_C2 (2413.0 / 4096.0 * 32.0)
#define PQ_C3 (2392.0 / 4096.0 * 32.0)

// ST 2084's inverse EOTF: linear luminance / 10000 nits to the PQ signal.
float3 LinearToST2084(float3 color)
{
    float3 powered = pow(abs(color), float3(PQ_M1, PQ_M1, PQ_M1));
    return pow((PQ_C1 + PQ_C2 * powered) / (1.0 + PQ_C3 * powered), float3(PQ_M2, PQ_M2, PQ_M2));
}

// ST 2084's EOTF: the PQ signal to linear luminance / 10000 nits.
float3 ST2084ToLinear(float3 color)
{
    float3 root = pow(abs(color), float3(1.0 / PQ_M2, 1.0 / PQ_M2, 1.0 / PQ_M2));
    return pow(max(root - PQ_C1, float3(0.0, 0.0, 0.0)) / (PQ_C2 - PQ_C3 * root),
               float3(1.0 / PQ_M1, 1.0 / PQ_M1, 1.0 / PQ_M1));
}

// A pure 2.2 power (a P3-D65 display's transfer), and its inverse.
float3 LinearToGamma22(float3 color)
{
    return pow(abs(color), float3(1.0 / 2.2, 1.0 / 2.2, 1.0 / 2.2));
}

float3 Gamma22ToLinear(float3 color)
{
    return pow(abs(color), float3(2.2, 2.2, 2.2));
}

// Each channel's sRGB decode (UnityCG's exact curve), where the scene is gamma-encoded.
float3 pbrlab_gamma_to_linear3(float3 color)
{
    return float3(GammaToLinearSpaceExact(color.r), GammaToLinearSpaceExact(color.g), GammaToLinearSpaceExact(color.b));
}

float3 pbrlab_linear_to_gamma3(float3 color)
{
    return float3(LinearToGammaSpaceExact(color.r), LinearToGammaSpaceExact(color.g), LinearToGammaSpaceExact(color.b));
}

// A linear BT.709 scene (paper white 1) to a display's signal: sRGB encoded; HDR10 (BT.2020
// primaries, PQ of the luminance in nits / 10000, paper white at nitsForPaperWhite); P3-D65 with
// a 2.2 power, paper white at nitsForPaperWhite / maxDisplayNits; else Rec.709 scaled so that
// paper white is nitsForPaperWhite / 80. A gamma-space scene is decoded first.
float3 SimpleHDRDisplayToneMapAndOETF(float3 scene, int colorGamut, bool forceGammaToLinear,
                                      float nitsForPaperWhite, float maxDisplayNits)
{
    float3 result = (IsGammaSpace() || forceGammaToLinear) ? pbrlab_gamma_to_linear3(scene) : scene;
    if (colorGamut == kColorGamutSRGB) {
        if (!IsGammaSpace())
            result = LinearToSRGB(result);
    } else if (colorGamut == kColorGamutHDR10) {
        result = LinearToST2084(mul(Rec709ToRec2020, result) * (nitsForPaperWhite / 10000.0));
    } else if (colorGamut == kColorGamutP3D65G22) {
        result = LinearToGamma22(mul(Rec709ToP3D65Mat, result) * (nitsForPaperWhite / maxDisplayNits));
    } else {
        result *= nitsForPaperWhite / kReferenceLuminanceWhiteForRec709;
    }
    return result;
}

// The display's signal back to the linear BT.709 scene (each step above undone in reverse
// order), gamma-encoded again where the scene is.
float3 InverseSimpleHDRDisplayToneMapAndOETF(float3 result, int colorGamut, bool forceGammaToLinear,
                                             float nitsForPaperWhite, float maxDisplayNits)
{
    if (colorGamut == kColorGamutSRGB) {
        if (!IsGammaSpace())
            result = SRGBToLinear(result);
    } else if (colorGamut == kColorGamutHDR10) {
        result = mul(Rec2020ToRec709, ST2084ToLinear(result) / (nitsForPaperWhite / 10000.0));
    } else if (colorGamut == kColorGamutP3D65G22) {
        result = mul(P3D65MatToRec709, Gamma22ToLinear(result) / (nitsForPaperWhite / maxDisplayNits));
    } else {
        result /= nitsForPaperWhite / kReferenceLuminanceWhiteForRec709;
    }
    return (IsGammaSpace() || forceGammaToLinear) ? pbrlab_linear_to_gamma3(result) : result;
}

#endif
