// pbr/ibl/importance_sampling.hlsl: low-discrepancy points and GGX importance sampling,
// for prefiltering environments and integrating the environment BRDF.
//
// Provides: vec2 pbr_hammersley(uint i, uint count)            (not in GLSL ES 1.00: no uint)
//           vec2 pbr_hammersley_float(float i, float count)    (every GLSL and HLSL version)
//           vec3 pbr_importance_sample_GGX(vec2 xi, float alpha)
//           float pbr_pdf_GGX_half_vector(float NdotH, float alpha)
//           vec3 pbr_tangent_to_world(vec3 v, vec3 n)
// Include:  "pbr/ibl/importance_sampling.hlsl" (path relative to hlsl_ports/)
// Config macros read: none.
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_IBL_IMPORTANCE_SAMPLING_HLSL
#define PBR_IBL_IMPORTANCE_SAMPLING_HLSL
#include "pbr/common/shim.hlsl"  // generated from glsl/pbr/ibl/importance_sampling.glsl by harness/pbrlab/gpu/port_hlsl.py: edit the GLSL, then regenerate
#include "pbr/common/constants.hlsl"
#include "pbr/brdf/d_ggx.hlsl"

// 2^-32: maps a 32-bit radical inverse to [0, 1).
#define PBR_INV_2_POW_32 2.3283064365386963e-10

// Hammersley point i of count in [0,1)^2: (i/count, base-2 radical inverse of i).
// Hammersley & Handscomb 1964; the bit reversal as in Dammertz 2012, "Hammersley
// Points on the Hemisphere" (GLSL 3.30 has no bitfieldReverse).
// GLSL ES 1.00 / WebGL 1 has no uint (nor bit operations), so there only
// pbr_hammersley_float below exists; desktop GLSL, ES 3.00+ and HLSL (no GL_ES) keep this one.
// ES 1.00 is the one GLSL ES version below 3.00, so `> 100` tests it: Babylon.js's own
// preprocessor reads __VERSION__ as 200 under WebGL2 (glsl/README.md, one-level preprocessors).
#if !defined(GL_ES) || __VERSION__ > 100
float2 pbr_hammersley(uint i, uint count) {
    uint bits = (i << 16u) | (i >> 16u);
    bits = ((bits & 0x55555555u) << 1u) | ((bits & 0xAAAAAAAAu) >> 1u);
    bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xCCCCCCCCu) >> 2u);
    bits = ((bits & 0x0F0F0F0Fu) << 4u) | ((bits & 0xF0F0F0F0u) >> 4u);
    bits = ((bits & 0x00FF00FFu) << 8u) | ((bits & 0xFF00FF00u) >> 8u);
    return float2(float(i) / float(count), float(bits) * PBR_INV_2_POW_32);
}
#endif

// Bits of i the float form reverses: float32 holds every integer below 2^24 exactly.
#define PBR_HAMMERSLEY_FLOAT_BITS 24

// pbr_hammersley for whole numbers i in [0, 2^24) held in floats: the same radical inverse,
// bit by bit in arithmetic (a loop with a constant bound, as GLSL ES 1.00 requires). Exact:
// each step halves a whole number below 2^24 and adds a power of two, and the reversed bits
// span 2^-1..2^-24, within one float32 mantissa; so it equals pbr_hammersley bit for bit
// for i < 2^24 (tested). Larger i lose their bits above 2^24.
float2 pbr_hammersley_float(float i, float count) {
    float rest = i;
    float radical = 0.0;
    float weight = 0.5;
    for (int k = 0; k < PBR_HAMMERSLEY_FLOAT_BITS; ++k) {
        float half_rest = floor(rest * 0.5);
        radical += (rest - 2.0 * half_rest) * weight;
        rest = half_rest;
        weight *= 0.5;
    }
    return float2(i / count, radical);
}

// A half vector distributed as D_GGX(h) * NdotH, in tangent space (z = normal).
// Walter et al. 2007, "Microfacet Models for Refraction through Rough Surfaces",
// eqs. 35-36: phi = 2 pi xi.x, cos^2 theta = (1 - xi.y) / (1 + (alpha^2 - 1) xi.y).
float3 pbr_importance_sample_GGX(float2 xi, float alpha) {
    float phi = 2.0 * PBR_PI * xi.x;
    float cosTheta2 = (1.0 - xi.y) / (1.0 + (alpha * alpha - 1.0) * xi.y);
    float cosTheta = sqrt(cosTheta2);
    float sinTheta = sqrt(max(1.0 - cosTheta2, 0.0));
    return float3(sinTheta * cos(phi), sinTheta * sin(phi), cosTheta);
}

// Density of pbr_importance_sample_GGX over half-vector solid angle: D(h) * NdotH.
// (For the reflected direction l divide by 4 VdotH: Walter et al. 2007, eq. 14.)
float pbr_pdf_GGX_half_vector(float NdotH, float alpha) {
    return pbr_D_GGX(NdotH, alpha) * NdotH;
}

// A tangent-space vector (z = n) in world space, with any orthonormal frame around n.
float3 pbr_tangent_to_world(float3 v, float3 n) {
    float3 up = abs(n.z) < 0.999 ? float3(0.0, 0.0, 1.0) : float3(1.0, 0.0, 0.0);
    float3 t = normalize(cross(up, n));
    float3 b = cross(n, t);
    return t * v.x + b * v.y + n * v.z;
}
#endif
