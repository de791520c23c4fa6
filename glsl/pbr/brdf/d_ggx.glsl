// pbr/brdf/d_ggx.glsl: the GGX / Trowbridge-Reitz normal distribution.
//
// Provides: float pbr_D_GGX(float NdotH, float alpha)
//           float pbr_D_GGX(vec3 n, vec3 h, float alpha)            (cancellation-free, preferred)
//           float pbr_D_GGX_fromOneMinusNdotH2(float NdotH, float oneMinusNdotH2, float alpha)
// Include:  "pbr/brdf/d_ggx.glsl" (path relative to glsl/)
// Config macros read: none.
//
// Walter, Marschner, Li, Torrance 2007, "Microfacet Models for Refraction through Rough
// Surfaces", eq. 33 (Trowbridge & Reitz 1975), in the lecture's form:
//   D_GGX = alpha² / (π · ((NdotH)² (alpha² - 1) + 1)²),   alpha = perceptualRoughness².
// Rearranged for float32 precision: (NdotH)²(alpha² - 1) + 1 = (1 - NdotH²) + (NdotH·alpha)²
// and 1 - NdotH² = (1 - NdotH)(1 + NdotH). The textbook form cancels catastrophically at
// the peak: for alpha = 1e-3, NdotH = 1 it computes 1 + (alpha² - 1) with alpha² = 1e-6
// below half an ulp of 1 and loses ~6 % (12 % after squaring); here every term is positive
// and 1 - NdotH is exact (Sterbenz) for NdotH in [0.5, 1]. Same idea as Filament's
// D_GGX (Guy & Agopian, "Physically Based Rendering in Filament", §4.4.1, which uses
// |n × h|² for mediump).
// (1 - NdotH)(1 + NdotH) is exact only for an exact NdotH: a float32 dot product n·h carries
// an absolute error of ~1e-7, which near the peak of a sharp lobe (1 - NdotH² ~ alpha²,
// 4e-6 at the minimum roughness) is a 2-3 % error in D (the 2.4 % highlights of the
// smoothness-1 chart spheres). Where the caller has the vectors, the vec3 overload takes
// 1 - NdotH² = |n × h|² (pbr_one_minus_dot2, error relative to |n × h| itself); measured
// over 1e6 random unit n with h within 3 alpha of n at alpha = 0.045²: worst relative error
// 4.0e-5 for the vec3 form against 14 % for the scalar form from dot(n, h)
// (tests/checking/hardcases/test_guards.py). pbr_brdf_standard uses it. In half
// precision the scalar forms collapse the lobe entirely (glsl/README.md, half precision).
// Guards (pbr/common/guards.glsl): NdotH is saturated (interpolated normals give NdotH
// slightly above 1), alpha is clamped to [PBR_MIN_ALPHA, 1]; at alpha = 0, D is a Dirac
// and the maths has no value: the library returns D at alpha = PBR_MIN_ALPHA (peak
// 3.2e13). The denominator (1 - NdotH²) + NdotH² alpha² is >= alpha² for every NdotH in
// [0, 1] (its minimum, at the peak), so it is floored at alpha²: this changes nothing for a
// consistent 1 - NdotH² and keeps D <= 1/(π alpha²) when a caller passes an inconsistent one.
// Bit-identical to the unguarded formula for NdotH in [0, 1], alpha in [1e-7, 1].
// Normalised: ∫ D (n·h) dω_h = 1 (tested).
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_BRDF_D_GGX_GLSL
#define PBR_BRDF_D_GGX_GLSL

#include "pbr/common/constants.glsl"
#include "pbr/common/guards.glsl"

// The common core: NdotH in [0, 1] and 1 - NdotH² given separately, so each caller picks
// the most accurate 1 - NdotH² it can form.
float pbr_D_GGX_fromOneMinusNdotH2(float NdotH, float oneMinusNdotH2, float alpha) {
    alpha = clamp(alpha, PBR_MIN_ALPHA, 1.0);
    float a = pbr_saturate(NdotH) * alpha;
    float k = alpha / max(oneMinusNdotH2 + a * a, alpha * alpha);
    return k * k * PBR_INV_PI;
}

float pbr_D_GGX(float NdotH, float alpha) {
    NdotH = pbr_saturate(NdotH);
    return pbr_D_GGX_fromOneMinusNdotH2(NdotH, (1.0 - NdotH) * (1.0 + NdotH), alpha);
}

// n, h unit vectors (h = normalize(l + v)).
float pbr_D_GGX(vec3 n, vec3 h, float alpha) {
    return pbr_D_GGX_fromOneMinusNdotH2(dot(n, h), pbr_one_minus_dot2(n, h), alpha);
}

#endif // PBR_BRDF_D_GGX_GLSL
