// pbr/tonemap/exposure.hlsl: photographic exposure in stops.
//
// Provides: vec3 pbr_apply_exposure(vec3 color, float exposureEV)
// Include:  "pbr/tonemap/exposure.hlsl" (path relative to hlsl_ports/)
// Config macros read: none.
//
// color · 2^EV: each EV (stop) doubles the light reaching the tonemapper. Exact in float32
// for integer EV (exp2 of an integer is a power of two). Apply before the tonemapper, to
// linear HDR colour.
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_TONEMAP_EXPOSURE_HLSL
#define PBR_TONEMAP_EXPOSURE_HLSL
#include "pbr/common/shim.hlsl"  // generated from glsl/pbr/tonemap/exposure.glsl by harness/pbrlab/gpu/port_hlsl.py: edit the GLSL, then regenerate

float3 pbr_apply_exposure(float3 color, float exposureEV) { return color * exp2(exposureEV); }

#endif // PBR_TONEMAP_EXPOSURE_HLSL
