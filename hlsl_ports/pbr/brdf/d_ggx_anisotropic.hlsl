// pbr/brdf/d_ggx_anisotropic.hlsl: the anisotropic GGX / Trowbridge-Reitz distribution.
//
// Provides: float pbr_D_GGX_Anisotropic(float NdotH, float TdotH, float BdotH, float alphaT, float alphaB)
// Include:  "pbr/brdf/d_ggx_anisotropic.hlsl" (path relative to hlsl_ports/)
// Config macros read: none.
//
// Burley 2012, "Physically-Based Shading at Disney", appendix B.2 (the anisotropic GTR2 = GGX);
// Heitz 2014, "Understanding the Masking-Shadowing Function in Microfacet-Based BRDFs", JCGT
// 3(2), its anisotropic GGX (the stretched distribution: roughness alphaT along the tangent t,
// alphaB along the bitangent b; KHR_materials_anisotropy's "D"):
//   D = 1 / (π alphaT alphaB (TdotH²/alphaT² + BdotH²/alphaB² + NdotH²)²).
// Multiplied through by (alphaT alphaB)² (the form of KHR_materials_anisotropy and Filament's
// D_GGX_Anisotropic): with a2 = alphaT alphaB, f = (alphaB TdotH, alphaT BdotH, a2 NdotH),
//   D = a2 · w2² / π,   w2 = a2 / |f|².
// Precision: t, b, n orthonormal and h unit, so the tangential part TdotH² + BdotH² is formed
// from its own components: no 1 - NdotH² and no cancellation at the peak (the isotropic
// pbr_D_GGX needs |n × h|² for that, d_ggx.hlsl). alphaT = alphaB = alpha gives
// pbr_D_GGX(NdotH, alpha) with 1 - NdotH² = TdotH² + BdotH² (tested to float32 rounding).
// Peak (h = n): 1 / (π alphaT alphaB). Normalised: ∫ D (n·h) dω_h = 1 (tested).
// Domain: h a unit vector in the frame (t, b, n) (then TdotH² + BdotH² + NdotH² = 1),
// alphaT, alphaB in (0, 1]. Guards (pbr/common/guards.hlsl), bit-identical inside it for
// alphas in [1e-7, 1]:
//  - alphas clamped to [PBR_MIN_ALPHA, 1]: alpha = 0 is a Dirac with no value; decided: D at
//    PBR_MIN_ALPHA (peak 1/(π 1e-14) = 3.2e13, as pbr_D_GGX).
//  - NdotH saturated (h below the surface counts as the horizon, as pbr_D_GGX; the shading
//    model zeroes that lobe itself); TdotH, BdotH clamped to [-1, 1] (only their squares
//    enter, and 1e30² would overflow to Inf).
//  - |f|² floored at a2²: for unit h, |f|² = alphaB² TdotH² + alphaT² BdotH² + a2² NdotH² >= a2²
//    because a2 <= min(alphaT, alphaB) (both <= 1), so the floor changes nothing for
//    consistent cosines and keeps D <= 1/(π a2) (finite, >= 0) for inconsistent ones (h = 0).
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_BRDF_D_GGX_ANISOTROPIC_HLSL
#define PBR_BRDF_D_GGX_ANISOTROPIC_HLSL
#include "pbr/common/shim.hlsl"  // generated from glsl/pbr/brdf/d_ggx_anisotropic.glsl by harness/pbrlab/gpu/port_hlsl.py: edit the GLSL, then regenerate

#include "pbr/common/constants.hlsl"
#include "pbr/common/guards.hlsl"

float pbr_D_GGX_Anisotropic(float NdotH, float TdotH, float BdotH, float alphaT, float alphaB) {
    alphaT = clamp(alphaT, PBR_MIN_ALPHA, 1.0);
    alphaB = clamp(alphaB, PBR_MIN_ALPHA, 1.0);
    float a2 = alphaT * alphaB;
    float3 f = float3(alphaB * clamp(TdotH, -1.0, 1.0), alphaT * clamp(BdotH, -1.0, 1.0), a2 * pbr_saturate(NdotH));
    float w2 = a2 / max(dot(f, f), a2 * a2);
    return a2 * w2 * w2 * PBR_INV_PI;
}

#endif // PBR_BRDF_D_GGX_ANISOTROPIC_HLSL
