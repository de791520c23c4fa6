// pbr/tonemap/hable.hlsl: Hable's filmic curve from Uncharted 2.
//
// Provides: vec3 pbr_tonemap_hable(vec3 color), float pbr_hable_curve(float x)
// Include:  "pbr/tonemap/hable.hlsl" (path relative to hlsl_ports/)
// Config macros read: none.
//
// Hable 2010, "Uncharted 2: HDR Lighting" (GDC) and "Filmic Tonemapping Operators"
// (filmicgames.com/archives/75): the curve
//   f(x) = ((x (A x + C B) + D E) / (x (A x + B) + D F)) - E / F
// with A shoulder strength 0.15, B linear strength 0.50, C linear angle 0.10, D toe
// strength 0.20, E toe numerator 0.02, F toe denominator 0.30, and the linear white point
// W = 11.2; output = f(x) / f(W), so x = W maps to exactly 1 (tested). Hable's blog code
// also multiplies the input by ExposureBias = 2.0 and applies pow(1/2.2): here exposure
// is the caller's (pbr_apply_exposure(c, 1.0) reproduces the bias) and the output stays
// linear (encode with pbr/color/). Applied per channel; input non-negative linear HDR.
// Guard (every tonemapper of this folder): the input passes through
// pbr_sanitize(color, PBR_HALF_MAX) (pbr/common/guards.hlsl): decided NaN -> 0, negative
// -> 0, +Inf and anything above 65504 (the largest RGBA16F value) -> 65504, where every
// curve is already at its white; the output is in [0, 1]. Bit-identical on [0, 65504].
// The curve passes 1 above W (Hable's code leaves that to the 8-bit target's clamp); the
// input is capped at W, which is exactly saturate(f(x) / f(W)) because f increases, and
// keeps x² from overflowing in half precision (x <= 11.2: x² <= 126). Output saturated
// against rounding at W.
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_TONEMAP_HABLE_HLSL
#define PBR_TONEMAP_HABLE_HLSL
#include "pbr/common/shim.hlsl"  // generated from glsl/pbr/tonemap/hable.glsl by harness/pbrlab/gpu/port_hlsl.py: edit the GLSL, then regenerate

#include "pbr/common/guards.hlsl"

#define PBR_HABLE_A 0.15  // shoulder strength
#define PBR_HABLE_B 0.50  // linear strength
#define PBR_HABLE_C 0.10  // linear angle
#define PBR_HABLE_D 0.20  // toe strength
#define PBR_HABLE_E 0.02  // toe numerator
#define PBR_HABLE_F 0.30  // toe denominator
#define PBR_HABLE_WHITE 11.2  // linear white point W
// The curve's constant products, written out (exact decimal values, rounded once): compilers
// fold C * B etc. at different precisions (glslang in double, Mesa in float32), which put
// the HLSL twin up to 1 ulp per constant away from the GLSL.
#define PBR_HABLE_CB 0.05                    // C * B
#define PBR_HABLE_DE 0.004                   // D * E
#define PBR_HABLE_DF 0.06                    // D * F
#define PBR_HABLE_E_OVER_F 0.066666666666666667  // E / F

float pbr_hable_curve(float x) {
    return ((x * (PBR_HABLE_A * x + PBR_HABLE_CB) + PBR_HABLE_DE)
          / (x * (PBR_HABLE_A * x + PBR_HABLE_B) + PBR_HABLE_DF))
          - PBR_HABLE_E_OVER_F;
}

float3 pbr_tonemap_hable(float3 color) {
    color = pbr_sanitize(color, PBR_HABLE_WHITE);
    float3 curve = float3(pbr_hable_curve(color.r), pbr_hable_curve(color.g), pbr_hable_curve(color.b));
    return pbr_saturate(curve / pbr_hable_curve(PBR_HABLE_WHITE));
}

#endif // PBR_TONEMAP_HABLE_HLSL
