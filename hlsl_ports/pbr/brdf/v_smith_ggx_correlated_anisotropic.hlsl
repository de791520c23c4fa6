// pbr/brdf/v_smith_ggx_correlated_anisotropic.hlsl: height-correlated anisotropic Smith GGX
// visibility.
//
// Provides: float pbr_V_SmithGGXCorrelated_Anisotropic(float NdotL, float NdotV, float TdotV,
//                 float BdotV, float TdotL, float BdotL, float alphaT, float alphaB)
// Include:  "pbr/brdf/v_smith_ggx_correlated_anisotropic.hlsl" (path relative to hlsl_ports/)
// Config macros read: none.
//
// Heitz 2014, "Understanding the Masking-Shadowing Function in Microfacet-Based BRDFs",
// JCGT 3(2): height-correlated G2 = 1 / (1 + Λ(v) + Λ(l)) (eq. 99) with the anisotropic GGX
// Λ(ω) = (-1 + sqrt(1 + α(ω)² tan²θ)) / 2, whose projected roughness is
// α(ω)² = cos²φ alphaT² + sin²φ alphaB² (its section on anisotropic distributions, by
// stretching). For a unit ω in the frame (t, b, n):
//   α(ω)² tan²θ = (alphaT² TdotX² + alphaB² BdotX²) / NdotX²,
// so 1 + 2Λ(x) = |(alphaT TdotX, alphaB BdotX, NdotX)| / NdotX and
//   V = G2 / (4 NdotL NdotV)
//     = 0.5 / (NdotL |(alphaT TdotV, alphaB BdotV, NdotV)| + NdotV |(alphaT TdotL, alphaB BdotL, NdotL)|),
// the form of KHR_materials_anisotropy and Filament (no tangents of θ, no 0/0 at grazing).
// alphaT = alphaB = alpha gives pbr_V_SmithGGXCorrelated (tested to float32 rounding).
// KHR's sample code clamps V to [0, 1]; V exceeds 1 legitimately at grazing (0.5/(2 NdotL NdotV)
// for alpha -> 0), so it is not clamped here.
// Guards (pbr/common/guards.hlsl), bit-identical for cosines NdotL, NdotV in [1e-4, 1],
// the tangential cosines in [-1, 1] and alphas in [1e-7, 1]: NdotL, NdotV clamped to
// [PBR_MIN_NDOTV, 1] (as every V: V <= 0.5/(2 · 1e-4 · 1e-4) = 2.5e7); TdotX, BdotX clamped to
// [-1, 1]; alphas to [PBR_MIN_ALPHA, 1].
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_BRDF_V_SMITH_GGX_CORRELATED_ANISOTROPIC_HLSL
#define PBR_BRDF_V_SMITH_GGX_CORRELATED_ANISOTROPIC_HLSL
#include "pbr/common/shim.hlsl"  // generated from glsl/pbr/brdf/v_smith_ggx_correlated_anisotropic.glsl by harness/pbrlab/gpu/port_hlsl.py: edit the GLSL, then regenerate

#include "pbr/common/guards.hlsl"

float pbr_V_SmithGGXCorrelated_Anisotropic(float NdotL, float NdotV, float TdotV, float BdotV,
                                           float TdotL, float BdotL, float alphaT, float alphaB) {
    NdotL = clamp(NdotL, PBR_MIN_NDOTV, 1.0);
    NdotV = clamp(NdotV, PBR_MIN_NDOTV, 1.0);
    alphaT = clamp(alphaT, PBR_MIN_ALPHA, 1.0);
    alphaB = clamp(alphaB, PBR_MIN_ALPHA, 1.0);
    float3 stretchedV = float3(alphaT * clamp(TdotV, -1.0, 1.0), alphaB * clamp(BdotV, -1.0, 1.0), NdotV);
    float3 stretchedL = float3(alphaT * clamp(TdotL, -1.0, 1.0), alphaB * clamp(BdotL, -1.0, 1.0), NdotL);
    float lambdaV = NdotL * sqrt(dot(stretchedV, stretchedV));
    float lambdaL = NdotV * sqrt(dot(stretchedL, stretchedL));
    return 0.5 / (lambdaV + lambdaL);
}

#endif // PBR_BRDF_V_SMITH_GGX_CORRELATED_ANISOTROPIC_HLSL
