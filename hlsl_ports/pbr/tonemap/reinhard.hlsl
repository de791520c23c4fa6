// pbr/tonemap/reinhard.hlsl: Reinhard's global operator.
//
// Provides: vec3 pbr_tonemap_reinhard(vec3 color)
//           vec3 pbr_tonemap_reinhard_extended(vec3 color, float whitePoint)
// Include:  "pbr/tonemap/reinhard.hlsl" (path relative to hlsl_ports/)
// Config macros read: none.
//
// Reinhard, Stark, Shirley, Ferwerda 2002, "Photographic Tone Reproduction for Digital
// Images", ACM ToG 21(3): eq. 3, L_d = L / (1 + L), and eq. 4 (with the smallest value
// mapped to white, L_white): L_d = L (1 + L / L_white²) / (1 + L). The paper applies them
// to luminance; as is common in games they are applied here per channel to linear RGB
// (simpler, desaturates highlights towards white). Input: non-negative linear HDR colour
// (after exposure); output linear in [0, 1) (eq. 3) or [0, 1] up to whitePoint (eq. 4).
// Guard (every tonemapper of this folder): the input passes through
// pbr_sanitize(color, PBR_HALF_MAX) (pbr/common/guards.hlsl): decided NaN -> 0, negative
// -> 0, +Inf and anything above 65504 (the largest RGBA16F value) -> 65504, where every
// curve is already at its white; the output is in [0, 1]. Bit-identical on [0, 65504].
// Eq. 4 passes 1 above whitePoint (the paper maps only L <= L_white); its input is also
// capped at whitePoint, which is exactly saturate(eq. 4) because the curve increases, and
// keeps color / whitePoint² from overflowing; the output is saturated against rounding at
// the white point (1 + 1 ulp, found by the sweep). whitePoint > 0.
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_TONEMAP_REINHARD_HLSL
#define PBR_TONEMAP_REINHARD_HLSL
#include "pbr/common/shim.hlsl"  // generated from glsl/pbr/tonemap/reinhard.glsl by harness/pbrlab/gpu/port_hlsl.py: edit the GLSL, then regenerate

#include "pbr/common/guards.hlsl"
#include "pbr/common/math.hlsl"

float3 pbr_tonemap_reinhard(float3 color) {
    color = pbr_sanitize(color, PBR_HALF_MAX);
    return color / (((float3)(1.0)) + color);
}

float3 pbr_tonemap_reinhard_extended(float3 color, float whitePoint) {
    color = pbr_sanitize(color, min(whitePoint, PBR_HALF_MAX));
    return pbr_saturate(color * (((float3)(1.0)) + color / (whitePoint * whitePoint)) / (((float3)(1.0)) + color));
}

#endif // PBR_TONEMAP_REINHARD_HLSL
