// pbr/common/math.hlsl: small scalar helpers shared by every layer.
//
// Provides: pbr_saturate, pbr_sq, pbr_pow5, pbr_max3, pbr_min3.
// Include:  "pbr/common/math.hlsl" (path relative to hlsl_ports/)
// Config macros read: none.
//
// pbr_pow5 multiplies (x² · x² · x) instead of calling pow(x, 5.0): pow is exp2(5·log2 x)
// on most GPUs, which is slower, loses ~1e-6 relative accuracy, and is undefined for x < 0
// and ambiguous at x == 0 (GLSL 4.6 §8.2: "results are undefined if x < 0, or if x = 0
// and y <= 0"). Schlick's Fresnel and Burley's diffuse both need (1 - cos)^5.
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_COMMON_MATH_HLSL
#define PBR_COMMON_MATH_HLSL
#include "pbr/common/shim.hlsl"  // generated from glsl/pbr/common/math.glsl by harness/pbrlab/gpu/port_hlsl.py: edit the GLSL, then regenerate

float pbr_saturate(float x) { return clamp(x, 0.0, 1.0); }
float3  pbr_saturate(float3 x)  { return clamp(x, 0.0, 1.0); }

float pbr_sq(float x) { return x * x; }

// x^5 by three multiplications (see header). Exact for x = 0 and x = 1.
float pbr_pow5(float x) {
    float x2 = x * x;
    return x2 * x2 * x;
}

float pbr_max3(float3 v) { return max(v.x, max(v.y, v.z)); }
float pbr_min3(float3 v) { return min(v.x, min(v.y, v.z)); }

#endif // PBR_COMMON_MATH_HLSL
