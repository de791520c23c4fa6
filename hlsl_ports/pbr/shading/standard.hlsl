// pbr/shading/standard.hlsl: the standard shading model, diffuse + Cook-Torrance specular.
//
// Provides: vec3  pbr_brdf_standard(vec3 n, vec3 v, vec3 l, vec3 diffuseColor, vec3 f0,
//                                   float perceptualRoughness)
//           void  pbr_brdf_standard_terms(vec3 n, vec3 v, vec3 l, float perceptualRoughness,
//                                         out float Fd, out float DV, out float LdotH)
//           vec3  pbr_brdf_standard_f90(vec3 n, vec3 v, vec3 l, vec3 diffuseColor, vec3 f0,
//                                       float f90, float perceptualRoughness)
//                 (an explicit F90, pbr_specular_F_f90: KHR_materials_specular's specularFactor;
//                 pbr_brdf_standard takes F90 = pbr_f90_from_f0(f0))
//           float pbr_clamp_perceptual_roughness(float perceptualRoughness)
//           PBR_LIT_SCALE (2^126, the diffuse term's below-horizon scale)
//           (through its includes: PBR_MIN_PERCEPTUAL_ROUGHNESS[_MEDIUMP] from dispatch.hlsl,
//           PBR_MIN_NDOTV and PBR_MIN_HALF_VECTOR_LENGTH_SQUARED from common/guards.hlsl)
// Include:  "pbr/shading/standard.hlsl" (path relative to hlsl_ports/)
// Config macros read: those of pbr/shading/dispatch.hlsl (PBR_QUALITY, PBR_SPECULAR_D,
//           PBR_SPECULAR_V, PBR_SPECULAR_F, PBR_DIFFUSE).
//
// The lecture's "General Cook-Torrance specular" (Cook & Torrance 1982; the lecture's
// combined BRDF, RTR 3rd ed. eq. 7.49 generalised):
//   BRDF = diffuseColor · Fd + D(NdotH) · V(l, v) · F(VdotH),   V = G / (4 NdotL NdotV),
// with Fd = 1/π for Lambert. Returns the BRDF in 1/sr (no light, no cosine: see
// pbr/lighting/punctual.hlsl). Variants through pbr/shading/dispatch.hlsl.
//
// Contract: n, v and l unit vectors (to float32 rounding: interpolated normals are
// normalised by the caller; a far camera's direction through pbr_safe_normalize first: an
// unnormalised v longer than 1e19 overflows |l + v|²). Edges (all mirrored in
// harness/pbrlab/reference/shading.py):
//  - NdotL <= 0: the light is below the horizon; returns 0 (the diffuse term is scaled by
//    saturate(NdotL · 2^126), 0 at or below 0 and 1 from float32's smallest normal up: one
//    multiply with a free clamp on AMD GPUs instead of a compare and a select).
//  - perceptualRoughness is clamped to [PBR_TIER_MIN_PERCEPTUAL_ROUGHNESS, 1] here (0.045,
//    or 0.089 in the LOW tier), far above the raw terms' PBR_MIN_ALPHA floor.
//  - NdotV is clamped to [PBR_MIN_NDOTV, 1], so back-facing views from normal mapping or
//    interpolated normals stay finite. NdotL > 0 is passed as it is: the fused D · V
//    quotients need no floor, the unfused V terms floor it themselves.
//  - Guards are established once, here, for the whole BRDF: the clamped roughness, the
//    NdotV clamp, NdotL > 0 and n·(l + v) >= PBR_MIN_NDOT_HALF_SUM (so |l + v|² in
//    [2^-100, 4]) are the preconditions under which the selected D · V needs none of its own
//    (pbr_specular_DV).
//  - h = (l + v) / |l + v| is never formed: D · V takes n·(l + v), |n × (l + v)|² (so
//    1 - NdotH² has no cancellation at the peak of sharp lobes, d_ggx.hlsl) and |l + v|².
//  - h below the surface (n·(l + v) <= 0, which only a view below the horizon gives): the
//    lobe is 0, the χ+(n·h) of Walter et al. 2007 eq. 33.
//  - D · V passes through the tier's pbr_specular_lobe_limit (identity in HIGH).
//  - LdotH = VdotH = |l + v| / 2, the exact identity for unit l and v
//    (l·(l+v)/|l+v| = (1 + l·v)/|l+v| = |l+v|/2), as 0.5 · sqrt(|l + v|²): no normalised h,
//    continuous at l = -v; F and Burley's diffuse saturate it.
//  - l = -v (n·(l + v) < PBR_MIN_NDOT_HALF_SUM, 2^-50, in every tier): no half vector
//    exists; the specular lobe is defined as 0 (it would reflect light back into the
//    surface: with NdotL > 0 the view is below the horizon) and the diffuse term is returned
//    alone. The test is on n·(l + v), not on |l + v|²: a grazing mirror (l + v = 2c·n at
//    NdotL = NdotV = c) has a short l + v but a well-defined h = n and a lobe that grows as
//    c -> 0, which a threshold on |l + v|² dropped (issue 25: below c = 3.9e-3 in LOW, where
//    the lobe is 5069 1/sr at roughness 0.5). The lobe also needs NdotL >= 2^-50 (one min
//    folds both tests into one compare).
//  - No branches: NdotL <= 0, l = -v and h below the surface are a select and a saturated
//    multiply at the end (a divergent branch costs mask bookkeeping on GPUs and llvmpipe
//    alike; measured: README). They cost 4 RDNA3 instructions per light (docs/bench).
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_SHADING_STANDARD_HLSL
#define PBR_SHADING_STANDARD_HLSL
#include "pbr/common/shim.hlsl"  // generated from glsl/pbr/shading/standard.glsl by harness/pbrlab/port_hlsl.py: edit the GLSL, then regenerate

#include "pbr/common/conventions.hlsl"
#include "pbr/common/guards.hlsl"
#include "pbr/material/remap.hlsl"
#include "pbr/shading/dispatch.hlsl"

// 2^126: NdotL · 2^126 >= 1 from float32's smallest normal (2^-126) up, so
// saturate(NdotL · PBR_LIT_SCALE) is 1 for every lit normal float32 and 0 at or below 0.
#define PBR_LIT_SCALE 8.507059e37

float pbr_clamp_perceptual_roughness(float perceptualRoughness) {
    return clamp(perceptualRoughness, PBR_TIER_MIN_PERCEPTUAL_ROUGHNESS, 1.0);
}

// Everything but the colours: the diffuse term Fd, the specular lobe D · V (both already
// selected to 0 where the header says) and LdotH = VdotH, for F. Shared by the two forms below,
// which differ only in the F90 their Fresnel takes (computed last in both, so the plain form
// compiles to the program it was before the explicit F90 existed).
void pbr_brdf_standard_terms(float3 n, float3 v, float3 l, float perceptualRoughness,
                             out float Fd, out float DV, out float LdotH) {
    float NdotL = dot(n, l);
    float nDotV = dot(n, v);
    float NdotV = clamp(nDotV, PBR_MIN_NDOTV, 1.0);
    float roughness = pbr_clamp_perceptual_roughness(perceptualRoughness);
    float alpha = pbr_alpha_from_perceptual_roughness(roughness);

    // h = (l + v) / |l + v| is never formed (see header).
    float3 halfSum = l + v;
    float halfLength2 = dot(halfSum, halfSum);
    LdotH = 0.5 * sqrt(halfLength2);  // == VdotH, see header
    // n·(l + v) = NdotL + n·v (one add, not a dot product), and |n × (l + v)|² as the squared
    // length of (l + v)'s rejection from n, (l + v) - n (n·(l + v)): equal for unit n
    // (Lagrange's identity), as accurate near the mirror (both lose only float32's rounding of
    // the small difference) and three instructions fewer than the cross product's six
    // multiplies and three adds (issue 25, measured on RDNA3/RDNA2/GCN5: docs/bench).
    float nDotHalfSum = NdotL + nDotV;
    float3 halfRejection = halfSum - nDotHalfSum * n;

    Fd = pbr_diffuse_Fd(NdotV, NdotL, LdotH, roughness);
    DV = pbr_specular_lobe_limit(pbr_specular_DV(
        nDotHalfSum, dot(halfRejection, halfRejection), halfLength2, NdotL, NdotV, LdotH, alpha));
    // No branches: a GPU or llvmpipe runs no divergent control flow. The diffuse term is
    // scaled by saturate(NdotL · 2^126) (a multiply whose clamp is free on AMD GPUs), the lobe
    // selected where NdotL and n·(l + v) both reach PBR_MIN_NDOT_HALF_SUM (one min, one
    // compare): both computed, the selected values finite (see header).
    Fd *= clamp(NdotL * PBR_LIT_SCALE, 0.0, 1.0);
    DV = min(NdotL, nDotHalfSum) >= PBR_MIN_NDOT_HALF_SUM ? DV : 0.0;
}

float3 pbr_brdf_standard(float3 n, float3 v, float3 l, float3 diffuseColor, float3 f0,
                       float perceptualRoughness) {
    float Fd, DV, LdotH;
    pbr_brdf_standard_terms(n, v, l, perceptualRoughness, Fd, DV, LdotH);
    return diffuseColor * Fd + DV * pbr_specular_F(f0, LdotH);
}

float3 pbr_brdf_standard_f90(float3 n, float3 v, float3 l, float3 diffuseColor, float3 f0, float f90,
                           float perceptualRoughness) {
    float Fd, DV, LdotH;
    pbr_brdf_standard_terms(n, v, l, perceptualRoughness, Fd, DV, LdotH);
    return diffuseColor * Fd + DV * pbr_specular_F_f90(f0, f90, LdotH);
}

#endif // PBR_SHADING_STANDARD_HLSL
