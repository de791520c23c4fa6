// pbr/brdf/v_smith_ggx_correlated.hlsl: height-correlated Smith GGX visibility.
//
// Provides: float pbr_V_SmithGGXCorrelated(float NdotL, float NdotV, float alpha)      (exact)
//           float pbr_V_SmithGGXCorrelatedFast(float NdotL, float NdotV, float alpha)  (approx.)
// Include:  "pbr/brdf/v_smith_ggx_correlated.hlsl" (path relative to hlsl_ports/)
// Config macros read: none.
//
// Exact: Heitz 2014, "Understanding the Masking-Shadowing Function in Microfacet-Based
// BRDFs", JCGT 3(2), eq. 99 (height-correlated masking-shadowing) with the GGX Lambda:
//   G2 = 1 / (1 + Λ(v) + Λ(l)),   Λ(x) = (sqrt(1 + alpha² tan²θx) - 1) / 2.
// Substituting tan²θ = (1 - c²)/c² and dividing by 4 NdotL NdotV gives the visibility
//   V = G2 / (4 NdotL NdotV)
//     = 0.5 / (NdotL sqrt(NdotV² (1 - alpha²) + alpha²) + NdotV sqrt(NdotL² (1 - alpha²) + alpha²)),
// the form of Lagarde & de Rousiers 2014, "Moving Frostbite to Physically Based Rendering",
// and Filament: no tangents, no 0/0 for NdotL or NdotV -> 0 while alpha > 0.
// Fast: Hammon 2017, "PBR Diffuse Lighting for GGX+Smith Microsurfaces" (GDC), removes the
// square roots: G2 ≈ 2 NdotL NdotV / lerp(2 NdotL NdotV, NdotL + NdotV, alpha), i.e.
//   V ≈ 0.5 / (NdotL (NdotV (1 - alpha) + alpha) + NdotV (NdotL (1 - alpha) + alpha)).
// It is exact at alpha = 1 and for NdotL = NdotV = 1. Worst relative error against the
// exact form over cosines in (0, 1] and alpha in [0.002025, 1] (the shading model's range):
// 0.2922 (29 %), at NdotL = NdotV ≈ alpha, i.e. grazing and smooth (float64 search with
// scipy; the GPU is checked against PBR_V_SMITH_GGX_CORRELATED_FAST_MAX_REL_ERROR by
// tests/library/test_brdf_terms.py::test_V_SmithGGXCorrelatedFast_error_bound). Away from
// grazing it is closer but not close: 13 % for cosines >= 0.5, 5 % for cosines >= 0.8. Domain: cosines in (0, 1], alpha in (0, 1].
// Guards (pbr/common/guards.hlsl): both cosines clamped to [PBR_MIN_NDOTV, 1] (at
// NdotL = NdotV = 0 both forms are 0.5/0), alpha to [PBR_MIN_ALPHA, 1]; bit-identical for
// cosines in [1e-4, 1] and alpha in [1e-7, 1].
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_BRDF_V_SMITH_GGX_CORRELATED_HLSL
#define PBR_BRDF_V_SMITH_GGX_CORRELATED_HLSL
#include "pbr/common/shim.hlsl"  // generated from glsl/pbr/brdf/v_smith_ggx_correlated.glsl by harness/pbrlab/gpu/port_hlsl.py: edit the GLSL, then regenerate

#include "pbr/common/guards.hlsl"

// Bound on the fast form's relative error (measured 0.2922, see above); shared with
// reference/brdf.py V_SMITH_GGX_CORRELATED_FAST_MAX_REL_ERROR.
#define PBR_V_SMITH_GGX_CORRELATED_FAST_MAX_REL_ERROR 0.293

float pbr_V_SmithGGXCorrelated(float NdotL, float NdotV, float alpha) {
    NdotL = clamp(NdotL, PBR_MIN_NDOTV, 1.0);
    NdotV = clamp(NdotV, PBR_MIN_NDOTV, 1.0);
    alpha = clamp(alpha, PBR_MIN_ALPHA, 1.0);
    float a2 = alpha * alpha;
    float lambdaV = NdotL * sqrt(NdotV * NdotV * (1.0 - a2) + a2);
    float lambdaL = NdotV * sqrt(NdotL * NdotL * (1.0 - a2) + a2);
    return 0.5 / (lambdaV + lambdaL);
}

float pbr_V_SmithGGXCorrelatedFast(float NdotL, float NdotV, float alpha) {
    NdotL = clamp(NdotL, PBR_MIN_NDOTV, 1.0);
    NdotV = clamp(NdotV, PBR_MIN_NDOTV, 1.0);
    alpha = clamp(alpha, PBR_MIN_ALPHA, 1.0);
    float lambdaV = NdotL * (NdotV * (1.0 - alpha) + alpha);
    float lambdaL = NdotV * (NdotL * (1.0 - alpha) + alpha);
    return 0.5 / (lambdaV + lambdaL);
}

#endif // PBR_BRDF_V_SMITH_GGX_CORRELATED_HLSL
