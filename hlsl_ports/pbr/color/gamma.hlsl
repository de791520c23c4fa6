// pbr/color/gamma.hlsl: the lecture's approximate "DIY linear space" helpers.
//
// Provides: pbr_degamma, pbr_regamma (pow 2.2 / pow 1/2.2), pbr_degamma_fast,
//           pbr_regamma_fast (c·c / sqrt c), PBR_DISPLAY_GAMMA.
// Include:  "pbr/color/gamma.hlsl" (path relative to hlsl_ports/)
// Config macros read: none.
//
// Lanterman, "Physically-Based Rendering" lecture, slide "DIY linear space (helpers)",
// after Hable 2010 ("Linear-Space Lighting (i.e. Gamma)", filmicgames.com): DeGamma is
// pow(c, 2.2), ReGamma is pow(c, 1/2.2), with c·c and sqrt(c) as the commented-out cheap
// forms. They approximate the exact sRGB curves (pbr/color/srgb.hlsl). Worst encode error
// against the exact curve, in 8-bit steps over linear [0, 1] (measured by
// tests/library/test_color_space.py::test_gamma_approximations_error_reported): pow 1/2.2
// 9 LSB, sqrt 10 LSB, both in the dark toe where sRGB is a linear segment; the exact DIY
// path is 0 LSB off the hardware path. Guard: inputs pass through pbr_sanitize(c, 1.0)
// (pbr/common/guards.hlsl): NaN and negatives -> 0 (pow() and sqrt() are undefined below 0,
// GLSL 4.60 §8.2), above 1 and +Inf -> 1, so outputs are in [0, 1]; bit-identical on [0, 1].
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_COLOR_GAMMA_HLSL
#define PBR_COLOR_GAMMA_HLSL
#include "pbr/common/shim.hlsl"  // generated from glsl/pbr/color/gamma.glsl by harness/pbrlab/gpu/port_hlsl.py: edit the GLSL, then regenerate

#include "pbr/common/guards.hlsl"

// The CRT-era display gamma the lecture uses. Shared with reference/color.py DISPLAY_GAMMA.
#define PBR_DISPLAY_GAMMA 2.2
// 1 / PBR_DISPLAY_GAMMA written out: compilers fold 1.0 / 2.2 at different precisions
// (glslang in double: 0.45454547; Mesa in float32: 0.45454544), which put the HLSL twin
// 1 ulp of exponent away from the GLSL; the literal is the same float everywhere.
#define PBR_INV_DISPLAY_GAMMA 0.45454545454545453

float3 pbr_degamma(float3 c) { return pow(pbr_sanitize(c, 1.0), ((float3)(PBR_DISPLAY_GAMMA))); }
float3 pbr_regamma(float3 c) { return pow(pbr_sanitize(c, 1.0), ((float3)(PBR_INV_DISPLAY_GAMMA))); }

// Gamma 2.0: the cheapest pair; exact inverses of each other.
float3 pbr_degamma_fast(float3 c) { c = pbr_sanitize(c, 1.0); return c * c; }
float3 pbr_regamma_fast(float3 c) { return sqrt(pbr_sanitize(c, 1.0)); }

#endif // PBR_COLOR_GAMMA_HLSL
