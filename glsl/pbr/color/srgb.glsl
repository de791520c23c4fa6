// pbr/color/srgb.glsl: the exact sRGB transfer functions of IEC 61966-2-1:1999.
//
// Provides: pbr_srgb_to_linear(float|vec3), pbr_linear_to_srgb(float|vec3) and the
//           PBR_SRGB_* constants of the standard.
// Include:  "pbr/color/srgb.glsl" (path relative to glsl/)
// Config macros read: none.
//
// IEC 61966-2-1:1999 §5.2 (decode, sRGB' -> linear) and §5.3 (encode), per channel:
//   linear = sRGB / 12.92                          if sRGB <= 0.04045
//          = ((sRGB + 0.055) / 1.055)^2.4          otherwise
//   sRGB   = 12.92 · linear                         if linear <= 0.0031308
//          = 1.055 · linear^(1/2.4) - 0.055        otherwise
// The two thresholds are the standard's rounded values (the curves meet within 1e-7, not
// exactly: 0.04045/12.92 = 0.0031308 to 5 digits). Inputs below the threshold, negative
// Guard: both curves are defined on [0, 1] (IEC 61966-2-1) and their input is passed
// through pbr_sanitize(c, 1.0) first (pbr/common/guards.glsl): decided NaN -> 0, negative
// -> 0, above 1 and +Inf -> 1, so the output is always in [0, 1] (a UNORM target clamps the
// same way). Bit-identical on [0, 1]. float64 twin:
// harness/pbrlab/maths/reference/color.py; these are the curves GL_FRAMEBUFFER_SRGB and
// GL_SRGB8_ALPHA8 textures implement in hardware (the "let the GPU handle it" path).
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_COLOR_SRGB_GLSL
#define PBR_COLOR_SRGB_GLSL

#include "pbr/common/guards.glsl"

#define PBR_SRGB_DECODE_THRESHOLD 0.04045    // IEC 61966-2-1 §5.2, sRGB' breakpoint
#define PBR_SRGB_ENCODE_THRESHOLD 0.0031308  // IEC 61966-2-1 §5.3, linear breakpoint
#define PBR_SRGB_LINEAR_SLOPE     12.92      // slope of the linear toe
#define PBR_SRGB_OFFSET           0.055      // a in (x + a) / (1 + a)
#define PBR_SRGB_EXPONENT         2.4        // exponent of the power segment

float pbr_srgb_to_linear(float c) {
    c = pbr_sanitize(c, 1.0);
    return c <= PBR_SRGB_DECODE_THRESHOLD
        ? c / PBR_SRGB_LINEAR_SLOPE
        : pow((c + PBR_SRGB_OFFSET) / (1.0 + PBR_SRGB_OFFSET), PBR_SRGB_EXPONENT);
}

vec3 pbr_srgb_to_linear(vec3 c) {
    return vec3(pbr_srgb_to_linear(c.r), pbr_srgb_to_linear(c.g), pbr_srgb_to_linear(c.b));
}

float pbr_linear_to_srgb(float c) {
    c = pbr_sanitize(c, 1.0);
    return c <= PBR_SRGB_ENCODE_THRESHOLD
        ? c * PBR_SRGB_LINEAR_SLOPE
        : (1.0 + PBR_SRGB_OFFSET) * pow(c, 1.0 / PBR_SRGB_EXPONENT) - PBR_SRGB_OFFSET;
}

vec3 pbr_linear_to_srgb(vec3 c) {
    return vec3(pbr_linear_to_srgb(c.r), pbr_linear_to_srgb(c.g), pbr_linear_to_srgb(c.b));
}

#endif // PBR_COLOR_SRGB_GLSL
