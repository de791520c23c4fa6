// pbr/tonemap/khronos_neutral.hlsl: the Khronos PBR Neutral tone mapper.
//
// Provides: vec3 pbr_tonemap_khronos_neutral(vec3 color)
// Include:  "pbr/tonemap/khronos_neutral.hlsl" (path relative to hlsl_ports/)
// Config macros read: none.
//
// Khronos Group 2024, "PBR Neutral" specification (github.com/KhronosGroup/ToneMapping,
// PBR_Neutral/README.md), with F90 = 0.04, K_s = 0.8 - F90, K_d = 0.15:
//   x = min(R, G, B);  f = x - x²/(4 F90) if x <= 2 F90, else F90
//   p = max(c - f);    p_n = 1 - (1 - K_s)² / (p + 1 - 2 K_s);   g = 1 / (K_d (p - p_n) + 1)
//   out = c - f                                   if p <= K_s
//       = (c - f) (p_n / p) g + p_n (1 - g)       otherwise.
// Written like the specification's sample code (mix(c·p_n/p, p_n, 1 - g)). Input:
// non-negative linear Rec. 709; output linear Rec. 709 in [0, 1]. Colours up to K_s pass
// through nearly unchanged (only the offset f), which keeps base colours true.
// Guard (every tonemapper of this folder): the input passes through
// pbr_sanitize(color, PBR_HALF_MAX) (pbr/common/guards.hlsl): decided NaN -> 0, negative
// -> 0, +Inf and anything above 65504 (the largest RGBA16F value) -> 65504, where every
// curve is already at its white; the output is in [0, 1]. Bit-identical on [0, 65504].
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_TONEMAP_KHRONOS_NEUTRAL_HLSL
#define PBR_TONEMAP_KHRONOS_NEUTRAL_HLSL
#include "pbr/common/shim.hlsl"  // generated from glsl/pbr/tonemap/khronos_neutral.glsl by harness/pbrlab/gpu/port_hlsl.py: edit the GLSL, then regenerate

#include "pbr/common/math.hlsl"
#include "pbr/common/guards.hlsl"

#define PBR_KHRONOS_NEUTRAL_F90 0.04                                // spec: F90
// K_s = 0.8 - F90 and 1 - K_s, written out: a compiler folds 1.0 - (0.8 - 0.04) in float32
// (Mesa: 0.24000001) or in double (the HLSL run: 0.24), which moved the compressed
// highlight by 3 ulp between the two languages (tests/gpu/hlsl/test_function_agreement.py).
#define PBR_KHRONOS_NEUTRAL_START_COMPRESSION 0.76                  // spec: K_s = 0.8 - F90
#define PBR_KHRONOS_NEUTRAL_ONE_MINUS_START_COMPRESSION 0.24        // 1 - K_s
#define PBR_KHRONOS_NEUTRAL_DESATURATION 0.15                       // spec: K_d

float3 pbr_tonemap_khronos_neutral(float3 color) {
    color = pbr_sanitize(color, PBR_HALF_MAX);
    float x = pbr_min3(color);
    float offset = x <= 2.0 * PBR_KHRONOS_NEUTRAL_F90
        ? x - x * x / (4.0 * PBR_KHRONOS_NEUTRAL_F90)
        : PBR_KHRONOS_NEUTRAL_F90;
    color -= offset;
    float peak = pbr_max3(color);
    if (peak <= PBR_KHRONOS_NEUTRAL_START_COMPRESSION) return color;
    float d = PBR_KHRONOS_NEUTRAL_ONE_MINUS_START_COMPRESSION;
    float newPeak = 1.0 - d * d / (peak + d - PBR_KHRONOS_NEUTRAL_START_COMPRESSION);
    color *= newPeak / peak;
    float g = 1.0 - 1.0 / (PBR_KHRONOS_NEUTRAL_DESATURATION * (peak - newPeak) + 1.0);
    return lerp(color, ((float3)(newPeak)), g);
}

#endif // PBR_TONEMAP_KHRONOS_NEUTRAL_HLSL
