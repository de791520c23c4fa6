// pbr/shading/standard.glsl: the standard shading model, diffuse + Cook-Torrance specular.
//
// Provides: vec3  pbr_brdf_standard(vec3 n, vec3 v, vec3 l, vec3 diffuseColor, vec3 f0,
//                                   float perceptualRoughness)
//           float pbr_clamp_perceptual_roughness(float perceptualRoughness)
//           (through its includes: PBR_MIN_PERCEPTUAL_ROUGHNESS[_MEDIUMP] from dispatch.glsl,
//           PBR_MIN_NDOTV and PBR_MIN_HALF_VECTOR_LENGTH_SQUARED from common/guards.glsl)
// Include:  "pbr/shading/standard.glsl" (path relative to glsl/)
// Config macros read: those of pbr/shading/dispatch.glsl (PBR_QUALITY, PBR_SPECULAR_D,
//           PBR_SPECULAR_V, PBR_SPECULAR_F, PBR_DIFFUSE).
//
// The lecture's "General Cook-Torrance specular" (Cook & Torrance 1982; the lecture's
// combined BRDF, RTR 3rd ed. eq. 7.49 generalised):
//   BRDF = diffuseColor · Fd + D(NdotH) · V(l, v) · F(VdotH),   V = G / (4 NdotL NdotV),
// with Fd = 1/π for Lambert. Returns the BRDF in 1/sr (no light, no cosine: see
// pbr/lighting/punctual.glsl). Variants through pbr/shading/dispatch.glsl.
//
// Edges (all mirrored in harness/pbrlab/reference/shading.py):
//  - NdotL <= 0: the light is below the horizon; returns 0.
//  - perceptualRoughness is clamped to [PBR_TIER_MIN_PERCEPTUAL_ROUGHNESS, 1] here (0.045,
//    or 0.089 in the LOW tier), far above the raw terms' PBR_MIN_ALPHA floor.
//  - NdotV is clamped to [PBR_MIN_NDOTV, 1], so back-facing views from normal mapping or
//    interpolated normals stay finite; NdotL is floored at PBR_MIN_NDOTV for the specular
//    lobe (as every V term does on its own).
//  - Guards are established once, here, for the whole BRDF: the clamped roughness, the
//    NdotV clamp and the NdotL floor are the preconditions under which the selected D · V
//    needs none of its own (pbr_specular_DV; the fused GGX · correlated-Smith quotient of
//    the HIGH tier drops them).
//  - 1 - NdotH² for D is |n × h|² (pbr_one_minus_dot2), not 1 - NdotH²: no cancellation at
//    the peak of sharp lobes (d_ggx.glsl).
//  - D · V passes through the tier's pbr_specular_lobe_limit (identity in HIGH).
//  - LdotH = VdotH = |l + v| / 2, the exact identity for unit l and v
//    (l·(l+v)/|l+v| = (1 + l·v)/|l+v| = |l+v|/2), computed as |l+v|² · inversesqrt(|l+v|²)
//    from the reciprocal length h needs anyway (no second square root). It needs no
//    normalised h and is continuous at l = -v.
//  - l = -v (|l + v|² < PBR_TIER_MIN_HALF_VECTOR_LENGTH_SQUARED, 1e-10; 2^-14 in LOW): no half vector exists; the
//    specular lobe is defined as 0 (it would reflect light back into the surface: with
//    NdotL > 0 the view is below the horizon) and the diffuse term is returned alone. The
//    reciprocal length is taken of max(|l + v|², threshold), so the unselected lobe is
//    computed from finite values.
//  - No branches: NdotL <= 0 and l = -v are selects at the end (a divergent branch costs
//    mask bookkeeping on GPUs and llvmpipe alike; measured: docs/bench).
//  - NdotH and VdotH are clamped to [0, 1] against rounding.
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_SHADING_STANDARD_GLSL
#define PBR_SHADING_STANDARD_GLSL

#include "pbr/common/conventions.glsl"
#include "pbr/common/guards.glsl"
#include "pbr/material/remap.glsl"
#include "pbr/shading/dispatch.glsl"

float pbr_clamp_perceptual_roughness(float perceptualRoughness) {
    return clamp(perceptualRoughness, PBR_TIER_MIN_PERCEPTUAL_ROUGHNESS, 1.0);
}

vec3 pbr_brdf_standard(vec3 n, vec3 v, vec3 l, vec3 diffuseColor, vec3 f0,
                       float perceptualRoughness) {
    float NdotL = dot(n, l);
    float nDotV = dot(n, v);
    float NdotV = clamp(nDotV, PBR_MIN_NDOTV, 1.0);
    float roughness = pbr_clamp_perceptual_roughness(perceptualRoughness);
    float alpha = pbr_alpha_from_perceptual_roughness(roughness);

    // h = (l + v) / |l + v| is never formed: D · V takes n·(l + v) and |n × (l + v)|² with
    // |l + v|² (pbr_specular_DV). The cap keeps an unnormalised v (a far camera: |l + v|² =
    // +Inf) from Inf / Inf in it: the lobe becomes 0.
    vec3 halfSum = l + v;
    float halfLength2 = dot(halfSum, halfSum);
    float LdotH = 0.5 * sqrt(halfLength2);  // == VdotH, see header
    vec3 nCrossHalfSum = cross(n, halfSum);

    float Fd = pbr_diffuse_Fd(NdotV, NdotL, LdotH, roughness);
    float DV = pbr_specular_lobe_limit(pbr_specular_DV(
        dot(n, halfSum), dot(nCrossHalfSum, nCrossHalfSum), min(halfLength2, 4.0), NdotL, NdotV,
        LdotH, alpha));
    // Selects, not branches, and on the two scalars rather than the colours: both sides are
    // computed, the selected values are finite (see header), and a GPU or llvmpipe runs no
    // divergent control flow.
    bool lit = NdotL > 0.0;
    Fd = lit ? Fd : 0.0;
    DV = lit && halfLength2 >= PBR_TIER_MIN_HALF_VECTOR_LENGTH_SQUARED ? DV : 0.0;
    return diffuseColor * Fd + DV * pbr_specular_F(f0, LdotH);
}

#endif // PBR_SHADING_STANDARD_GLSL
