// pbr/tonemap/aces.hlsl: two fits of the ACES filmic transform (RRT + sRGB ODT).
//
// Provides: vec3 pbr_tonemap_aces_fitted(vec3 color)     (Hill 2016, with the colour matrices)
//           vec3 pbr_tonemap_aces_narkowicz(vec3 color)  (Narkowicz 2015, luminance-only curve)
// Include:  "pbr/tonemap/aces.hlsl" (path relative to hlsl_ports/)
// Config macros read: none.
//
// pbr_tonemap_aces_fitted is Stephen Hill's fit (2016, "ACES.hlsl" in MJP's BakingLab,
// MIT licence): linear sRGB -> (sRGB => XYZ => D65_2_D60 => AP1 => RRT_SAT) input matrix,
// the rational fit of RRT + ODT
//   RRTAndODTFit(v) = (v (v + 0.0245786) - 0.000090537) / (v (0.983729 v + 0.4329510) + 0.238081),
// the (ODT_SAT => XYZ => D60_2_D65 => sRGB) output matrix, then saturate. Output is linear
// sRGB in [0, 1]. Matrix rows are written out as dot products so no row/column-major
// convention is involved.
// pbr_tonemap_aces_narkowicz is Narkowicz 2015, "ACES Filmic Tone Mapping Curve"
// (knarkowicz.wordpress.com, 2016-01-06): saturate(x (2.51 x + 0.03) / (x (2.43 x + 0.59) + 0.14))
// per channel. The post pre-scales the input by 0.6 to match the ACES reference white;
// that belongs to exposure (pbr_apply_exposure(c, log2(0.6))) and is not applied here.
// Guard (every tonemapper of this folder): the input passes through
// pbr_sanitize(color, PBR_HALF_MAX) (pbr/common/guards.hlsl): decided NaN -> 0, negative
// -> 0, +Inf and anything above 65504 (the largest RGBA16F value) -> 65504, where every
// curve is already at its white; the output is in [0, 1]. Bit-identical on [0, 65504].
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_TONEMAP_ACES_HLSL
#define PBR_TONEMAP_ACES_HLSL
#include "pbr/common/shim.hlsl"  // generated from glsl/pbr/tonemap/aces.glsl by harness/pbrlab/gpu/port_hlsl.py: edit the GLSL, then regenerate

#include "pbr/common/math.hlsl"
#include "pbr/common/guards.hlsl"

// Hill 2016 input matrix rows (sRGB => XYZ => D65_2_D60 => AP1 => RRT_SAT)
#define PBR_ACES_INPUT_ROW0 float3(0.59719, 0.35458, 0.04823)
#define PBR_ACES_INPUT_ROW1 float3(0.07600, 0.90834, 0.01566)
#define PBR_ACES_INPUT_ROW2 float3(0.02840, 0.13383, 0.83777)
// Hill 2016 output matrix rows (ODT_SAT => XYZ => D60_2_D65 => sRGB)
#define PBR_ACES_OUTPUT_ROW0 float3( 1.60475, -0.53108, -0.07367)
#define PBR_ACES_OUTPUT_ROW1 float3(-0.10208,  1.10813, -0.00605)
#define PBR_ACES_OUTPUT_ROW2 float3(-0.00327, -0.07276,  1.07602)

float3 pbr_aces_rrt_odt_fit(float3 v) {
    float3 a = v * (v + 0.0245786) - 0.000090537;
    float3 b = v * (0.983729 * v + 0.4329510) + 0.238081;
    return a / b;
}

float3 pbr_tonemap_aces_fitted(float3 color) {
    color = pbr_sanitize(color, PBR_HALF_MAX);
    float3 aces = float3(dot(PBR_ACES_INPUT_ROW0, color),
                     dot(PBR_ACES_INPUT_ROW1, color),
                     dot(PBR_ACES_INPUT_ROW2, color));
    float3 fitted = pbr_aces_rrt_odt_fit(aces);
    float3 rgb = float3(dot(PBR_ACES_OUTPUT_ROW0, fitted),
                    dot(PBR_ACES_OUTPUT_ROW1, fitted),
                    dot(PBR_ACES_OUTPUT_ROW2, fitted));
    return pbr_saturate(rgb);
}

#define PBR_ACES_NARKOWICZ_A 2.51
#define PBR_ACES_NARKOWICZ_B 0.03
#define PBR_ACES_NARKOWICZ_C 2.43
#define PBR_ACES_NARKOWICZ_D 0.59
#define PBR_ACES_NARKOWICZ_E 0.14
// Input cap of the Narkowicz curve: f(x) reaches 1 at x = 7.24 (root of
// 0.08 x² - 0.56 x - 0.14) and increases everywhere (f' ∝ 1.408 x² + 0.703 x + 0.004 > 0)
// towards 2.51/2.43, so saturate(f(min(x, 16))) == saturate(f(x)) for every x >= 0: no
// accuracy cost; it keeps x (2.51 x + 0.03) <= 643 so the curve is finite in half precision
// (uncapped it overflows for x > ~160: measured, glsl/README.md).
#define PBR_ACES_NARKOWICZ_MAX_INPUT 16.0

float3 pbr_tonemap_aces_narkowicz(float3 x) {
    x = pbr_sanitize(x, PBR_ACES_NARKOWICZ_MAX_INPUT);
    return pbr_saturate((x * (PBR_ACES_NARKOWICZ_A * x + PBR_ACES_NARKOWICZ_B))
                      / (x * (PBR_ACES_NARKOWICZ_C * x + PBR_ACES_NARKOWICZ_D) + PBR_ACES_NARKOWICZ_E));
}

#endif // PBR_TONEMAP_ACES_HLSL
