// pbr/shading/standard.hlsl: the standard shading model, diffuse + Cook-Torrance specular.
//
// Provides: vec3  pbr_brdf_standard(vec3 n, vec3 v, vec3 l, vec3 diffuseColor, vec3 f0,
//                                   float perceptualRoughness)
//           void  pbr_brdf_standard_terms(vec3 n, vec3 v, vec3 l, float perceptualRoughness,
//                                         out float piFd, out float piDV, out float LdotH)
//                 (π·Fd and π·D·V: the terms in units of 1/π, see the sum below)
//           vec3  pbr_brdf_standard_f90(vec3 n, vec3 v, vec3 l, vec3 diffuseColor, vec3 f0,
//                                       float f90, float perceptualRoughness)
//                 (an explicit F90, pbr_specular_F_f90: KHR_materials_specular's specularFactor;
//                 pbr_brdf_standard takes F90 = pbr_f90_from_f0(f0))
//           float pbr_clamp_perceptual_roughness(float perceptualRoughness)
//           (through its includes: PBR_MIN_PERCEPTUAL_ROUGHNESS[_MEDIUMP] from dispatch.hlsl,
//           PBR_MIN_NDOTV and PBR_MIN_NDOT_HALF_SUM from common/guards.hlsl)
// Include:  "pbr/shading/standard.hlsl" (path relative to hlsl_ports/)
// Config macros read: those of pbr/shading/dispatch.hlsl (PBR_QUALITY, PBR_SPECULAR_D,
//           PBR_SPECULAR_V, PBR_SPECULAR_F, PBR_DIFFUSE).
//
// The lecture's "General Cook-Torrance specular" (Cook & Torrance 1982; the lecture's
// combined BRDF, RTR 3rd ed. eq. 7.49 generalised):
//   BRDF = diffuseColor · Fd + D(NdotH) · V(l, v) · F(VdotH),   V = G / (4 NdotL NdotV),
// with Fd = 1/π for Lambert. Returns the BRDF in 1/sr (no light, no cosine: see
// pbr/lighting/punctual.hlsl). Variants through pbr/shading/dispatch.hlsl.
// The sum is formed with 1/π factored out, (diffuseColor · π·Fd + π·D·V · F) · (1/π), where
// π·Fd = 1 for Lambert (PBR_PI · PBR_INV_PI is exactly 1 in float32, so the multiply folds
// away): the diffuse colour is then only ever an fma's addend, never a factor of a product
// with a constant. Written as diffuseColor · (1/π) + D·V·F, a program whose diffuse colour is
// a specialised constant folds diffuseColor · (1/π) into one rounded constant while the full
// program fuses the product into fma(diffuseColor, 1/π, D·V·F) unrounded: the two differed by
// 1 ulp in 0.4 % of values (tests/render/specialisation: chart_f0, chart_metallic[_environment],
// chart_terms; measured). Factored, both programs round the same operations, and the
// runtime diffuse scale that otherwise kept them identical (2.4 RDNA3 instructions per light)
// is not needed.
//
// Contract: n, v and l unit vectors (to float32 rounding: interpolated normals are
// normalised by the caller; a far camera's direction through pbr_safe_normalize first: an
// unnormalised v longer than 1e19 overflows |l + v|²). Edges (all mirrored in
// harness/pbrlab/maths/reference/shading.py):
//  - NdotL is saturated (a free output modifier on AMD GPUs) and every NdotL of the
//    formula, n·(l + v) = NdotL + n·v included, is that saturated cosine. So a light below
//    the horizon (n·l <= 0) gives the value at NdotL = 0: finite and non-negative, and
//    multiplied by the caller's max(0, NdotL) (pbr_shade_punctual, the rendering equation's
//    cosine) into exactly 0 light. The BRDF itself is not 0 there (issue 25: the former
//    decided 0, a saturate(NdotL · 2^126) scale on the diffuse term and a min in the lobe's
//    selection, cost 3.4 RDNA3 instructions per light and changed no rendered value).
//  - perceptualRoughness is clamped to [PBR_TIER_MIN_PERCEPTUAL_ROUGHNESS, 1] here (0.045,
//    or 0.089 in the LOW tier), far above the raw terms' PBR_MIN_ALPHA floor.
//  - NdotV is clamped to [PBR_MIN_NDOTV, 1], so back-facing views from normal mapping or
//    interpolated normals stay finite (with n·v < 0 the Smith lambdas' sum can cancel to 0).
//    The fused D · V quotients need no floor on NdotL, the unfused V terms floor it
//    themselves.
//  - Guards are established once, here, for the whole BRDF: the clamped roughness, the
//    NdotV clamp, the saturated NdotL and |l + v|² + 2^-126 (pbr_length2_nonzero, free: a
//    fused multiply-add; without it l = -v gives 1/0) are the preconditions under which
//    the selected D · V needs none of its own and is finite everywhere (pbr_specular_DV).
//  - h = (l + v) / |l + v| is never formed: D · V takes n·(l + v), |n × (l + v)|² (so
//    1 - NdotH² has no cancellation at the peak of sharp lobes, d_ggx.hlsl) and |l + v|².
//  - h below the surface (n·(l + v) < PBR_MIN_NDOT_HALF_SUM, 2^-50, in every tier, which a
//    lit light only gives with a view below the horizon): the lobe is 0, the χ+(n·h) of
//    Walter et al. 2007 eq. 33, and the diffuse term is returned alone. That includes l = -v
//    with n·l > 0 (n·(l + v) = NdotL + (-NdotL) = 0 exactly): no half vector exists. The
//    test is on n·(l + v), not on |l + v|²: a grazing mirror (l + v = 2c·n at NdotL = NdotV
//    = c) has a short l + v but a well-defined h = n and a lobe that grows as c -> 0, which a
//    threshold on |l + v|² dropped (issue 25: below c = 3.9e-3 in LOW, where the lobe is
//    5069 1/sr at roughness 0.5).
//  - D · V passes through the tier's pbr_specular_lobe_limit (identity in HIGH).
//  - LdotH = VdotH = |l + v| / 2, the exact identity for unit l and v
//    (l·(l+v)/|l+v| = (1 + l·v)/|l+v| = |l+v|/2), as 0.5 · sqrt(|l + v|²): no normalised h,
//    continuous at l = -v; F and Burley's diffuse saturate it.
//  - No branches: the χ+ selection is one compare and one select at the end (a divergent
//    branch costs mask bookkeeping on GPUs and llvmpipe alike; measured: README).
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_SHADING_STANDARD_HLSL
#define PBR_SHADING_STANDARD_HLSL
#include "pbr/common/shim.hlsl"  // generated from glsl/pbr/shading/standard.glsl by harness/pbrlab/gpu/port_hlsl.py: edit the GLSL, then regenerate

#include "pbr/common/conventions.hlsl"
#include "pbr/common/guards.hlsl"
#include "pbr/material/remap.hlsl"
#include "pbr/shading/dispatch.hlsl"

float pbr_clamp_perceptual_roughness(float perceptualRoughness) {
    return clamp(perceptualRoughness, PBR_TIER_MIN_PERCEPTUAL_ROUGHNESS, 1.0);
}

// Everything but the colours, in units of 1/π: π·Fd (1 for Lambert) and π·D·V (the lobe already
// selected to 0 where the header says), and LdotH = VdotH, for F. Shared by the two forms below,
// which differ only in the F90 their Fresnel takes (computed last in both, so the plain form
// compiles to the program it was before the explicit F90 existed).
void pbr_brdf_standard_terms(float3 n, float3 v, float3 l, float perceptualRoughness,
                             out float piFd, out float piDV, out float LdotH) {
    float NdotL = clamp(dot(n, l), 0.0, 1.0);  // below the horizon: the value at 0 (header)
    float nDotV = dot(n, v);
    float NdotV = clamp(nDotV, PBR_MIN_NDOTV, 1.0);
    float roughness = pbr_clamp_perceptual_roughness(perceptualRoughness);
    float alpha = pbr_alpha_from_perceptual_roughness(roughness);

    // h = (l + v) / |l + v| is never formed (see header).
    float3 halfSum = l + v;
    float halfLength2 = pbr_length2_nonzero(halfSum);  // |l + v|² + 2^-126: never 0
    LdotH = 0.5 * sqrt(halfLength2);  // == VdotH, see header
    // n·(l + v) = NdotL + n·v (one add, not a dot product), and |n × (l + v)|² as the squared
    // length of (l + v)'s rejection from n, (l + v) - n (n·(l + v)): equal for unit n
    // (Lagrange's identity), as accurate near the mirror (both lose only float32's rounding of
    // the small difference) and three instructions fewer than the cross product's six
    // multiplies and three adds (issue 25, measured on RDNA3/RDNA2/GCN5: docs/bench). Below
    // the horizon NdotL is 0 and this rejects l + v along n·v, not along n·(l + v): finite,
    // which is all the value there needs (header).
    float nDotHalfSum = NdotL + nDotV;
    float3 halfRejection = halfSum - nDotHalfSum * n;

    // π·Fd and π·D·V: the constant products fold (π · (1/π) is 1.0 in float32, and the fused
    // quotients' (0.5/π)·π is 0.5: measured, no RDNA3 instruction against dropping D's 1/π).
    piFd = PBR_PI * pbr_diffuse_Fd(NdotV, NdotL, LdotH, roughness);
    piDV = PBR_PI * pbr_specular_lobe_limit(pbr_specular_DV(
        nDotHalfSum, dot(halfRejection, halfRejection), halfLength2, NdotL, NdotV, LdotH, alpha));
    // No branches: a GPU or llvmpipe runs no divergent control flow. D · V is finite
    // everywhere (pbr_specular_DV's preconditions hold for every input), selected where h is
    // above the surface (χ+: one compare, one select).
    piDV = nDotHalfSum >= PBR_MIN_NDOT_HALF_SUM ? piDV : 0.0;
}

float3 pbr_brdf_standard(float3 n, float3 v, float3 l, float3 diffuseColor, float3 f0,
                       float perceptualRoughness) {
    float piFd, piDV, LdotH;
    pbr_brdf_standard_terms(n, v, l, perceptualRoughness, piFd, piDV, LdotH);
    return (diffuseColor * piFd + piDV * pbr_specular_F(f0, LdotH)) * PBR_INV_PI;
}

float3 pbr_brdf_standard_f90(float3 n, float3 v, float3 l, float3 diffuseColor, float3 f0, float f90,
                           float perceptualRoughness) {
    float piFd, piDV, LdotH;
    pbr_brdf_standard_terms(n, v, l, perceptualRoughness, piFd, piDV, LdotH);
    return (diffuseColor * piFd + piDV * pbr_specular_F_f90(f0, f90, LdotH)) * PBR_INV_PI;
}

#endif // PBR_SHADING_STANDARD_HLSL
