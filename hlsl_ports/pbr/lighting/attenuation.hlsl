// pbr/lighting/attenuation.hlsl: how much of a point or spot light reaches a point.
//
// Provides: float pbr_range_window(float distance2, float range)
//           float pbr_distance_attenuation(float distance2, float range)
//           float pbr_spot_attenuation(vec3 l, vec3 spotDirection, float cosOuter, float invCosRange)
// Include:  "pbr/lighting/attenuation.hlsl" (path relative to hlsl_ports/)
// Config macros read: none.
//
// Units follow the lecture's convention (pbr/common/conventions.hlsl §5): a light of
// intensity I at distance d delivers I / d^2 as the lightRadiance of pbr_shade_punctual.
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_LIGHTING_ATTENUATION_HLSL
#define PBR_LIGHTING_ATTENUATION_HLSL
#include "pbr/common/shim.hlsl"  // generated from glsl/pbr/lighting/attenuation.glsl by harness/pbrlab/gpu/port_hlsl.py: edit the GLSL, then regenerate

// Smallest squared distance used in 1/d^2: a light at the shaded point would divide by
// zero. 1e-8 (d = 1e-4 scene units) caps the inverse square at 1e8, far above any
// other term, so only the degenerate case is touched.
#define PBR_MIN_LIGHT_DISTANCE_SQUARED 1e-8

// Smooth window that reaches 0 at `range`: saturate(1 - (d/range)^4)^2.
// Karis 2013, "Real Shading in Unreal Engine 4", eq. 9 (without its +1 in the
// denominator: the inverse square stays physical). range = +inf gives 1.
float pbr_range_window(float distance2, float range) {
    float ratio2 = distance2 / (range * range);
    float w = clamp(1.0 - ratio2 * ratio2, 0.0, 1.0);
    return w * w;
}

// Inverse-square falloff times the range window.
float pbr_distance_attenuation(float distance2, float range) {
    return pbr_range_window(distance2, range) / max(distance2, PBR_MIN_LIGHT_DISTANCE_SQUARED);
}

// Spot cone: the square of a linear ramp in cos(angle) from the outer cone (0) to the
// inner cone (1). Lagarde & de Rousiers 2014, "Moving Frostbite to PBR", listing 4 (the
// square gives a smoother edge); invCosRange = 1 / (cosInner - cosOuter).
// l points from the surface to the light; spotDirection is the way the light travels.
float pbr_spot_attenuation(float3 l, float3 spotDirection, float cosOuter, float invCosRange) {
    float t = clamp((dot(-l, spotDirection) - cosOuter) * invCosRange, 0.0, 1.0);
    return t * t;
}
#endif
