// pbrlab stand-in for Core RP's ShaderLibrary/Color.hlsl: the colour-space conversions URP
// shaders call, written for pbrlab from the sRGB standard (IEC 61966-2-1) and Unity's
// documentation of the names (Core RP's own file is under the Unity Companion License).
#ifndef PBRLAB_CORE_RP_COLOR_HLSL
#define PBRLAB_CORE_RP_COLOR_HLSL

// The exact sRGB curves, per channel (IEC 61966-2-1: 12.92 below 0.04045 / 0.0031308).
float SRGBToLinear(float c) { return c <= 0.04045 ? c / 12.92 : pow((c + 0.055) / 1.055, 2.4); }
float3 SRGBToLinear(float3 c) { return float3(SRGBToLinear(c.r), SRGBToLinear(c.g), SRGBToLinear(c.b)); }
float4 SRGBToLinear(float4 c) { return float4(SRGBToLinear(c.rgb), c.a); }
float LinearToSRGB(float c) { return c <= 0.0031308 ? c * 12.92 : 1.055 * pow(c, 1.0 / 2.4) - 0.055; }
float3 LinearToSRGB(float3 c) { return float3(LinearToSRGB(c.r), LinearToSRGB(c.g), LinearToSRGB(c.b)); }
float4 LinearToSRGB(float4 c) { return float4(LinearToSRGB(c.rgb), c.a); }
float3 Gamma22ToLinear(float3 c) { return pow(max(c, float3(0.0, 0.0, 0.0)), float3(2.2, 2.2, 2.2)); }
float3 LinearToGamma22(float3 c) { return pow(max(c, float3(0.0, 0.0, 0.0)), float3(1.0 / 2.2, 1.0 / 2.2, 1.0 / 2.2)); }

// The fast approximations Unity offers beside them (Core RP's FastSRGBToLinear /
// FastLinearToSRGB; Ian Taylor's polynomial and power fits, chilliant.blogspot.com 2012/08):
// c (c (0.305306011 c + 0.682171111) + 0.012522878), and saturate(1.055 c^(1/2.4) - 0.055).
float3 FastSRGBToLinear(float3 c) { return c * (c * (c * 0.305306011 + 0.682171111) + 0.012522878); }
float4 FastSRGBToLinear(float4 c) { return float4(FastSRGBToLinear(c.rgb), c.a); }
float3 FastLinearToSRGB(float3 c) { return saturate(1.055 * pow(abs(c), float3(0.416666667, 0.416666667, 0.416666667)) - 0.055); }
float4 FastLinearToSRGB(float4 c) { return float4(FastLinearToSRGB(c.rgb), c.a); }

// HSV (hue, saturation, value, each in [0, 1]; Smith 1978's hexcone) from RGB and back, as Core
// RP's RgbToHsv / HsvToRgb: value the largest channel, saturation (max - min) / max, hue the
// sextant position; Unity's adds 1e-4 to the two divisors (a grey's hue and a black's
// saturation are 0, not NaN), which is kept here.
float3 RgbToHsv(float3 c) {
    float ma = max(max(c.r, c.g), c.b);
    float chroma = ma - min(min(c.r, c.g), c.b);
    float h = ma == c.r ? (c.g - c.b) / (6.0 * chroma + 1e-4)
            : ma == c.g ? 1.0 / 3.0 + (c.b - c.r) / (6.0 * chroma + 1e-4)
                        : 2.0 / 3.0 + (c.r - c.g) / (6.0 * chroma + 1e-4);
    return float3(abs(h < 0.0 ? h + 1.0 : h), chroma / (ma + 1e-4), ma);
}
float3 HsvToRgb(float3 c) {
    float3 p = abs(frac(c.xxx + float3(1.0, 2.0 / 3.0, 1.0 / 3.0)) * 6.0 - 3.0);
    return c.z * lerp(float3(1.0, 1.0, 1.0), saturate(p - 1.0), c.y);
}

#endif
