// pbr/tonemap/exposure.glsl: photographic exposure in stops.
//
// Provides: vec3 pbr_apply_exposure(vec3 color, float exposureEV)
// Include:  "pbr/tonemap/exposure.glsl" (path relative to glsl/)
// Config macros read: none.
//
// color · 2^EV: each EV (stop) doubles the light reaching the tonemapper. Exact in float32
// for integer EV (exp2 of an integer is a power of two). Apply before the tonemapper, to
// linear HDR colour.
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_TONEMAP_EXPOSURE_GLSL
#define PBR_TONEMAP_EXPOSURE_GLSL

vec3 pbr_apply_exposure(vec3 color, float exposureEV) { return color * exp2(exposureEV); }

#endif // PBR_TONEMAP_EXPOSURE_GLSL
