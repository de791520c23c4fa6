// pbr/brdf/v_kelemen.hlsl: the Kelemen / Szirmay-Kalos geometric term.
//
// Provides: float pbr_G_Kelemen(float NdotL, float NdotV, float VdotH), float pbr_V_Kelemen(float VdotH)
// Include:  "pbr/brdf/v_kelemen.hlsl" (path relative to hlsl_ports/)
// Config macros read: none.
//
// Kelemen & Szirmay-Kalos 2001, "A Microfacet Based Coupled Specular-Matte BRDF Model
// with Importance Sampling" (Eurographics short paper): G / (NdotL NdotV) ≈ 1 / (VdotH)²,
//   G_K = NdotL NdotV / VdotH²,   V_K = G_K / (4 NdotL NdotV) = 1 / (4 VdotH²).
// V_K matches the lecture's Viz_K = 1/(4 (V·H)²) (and Filament's V_Kelemen). Lecture
// discrepancy: its slide writes G_K = (n·L)(n·V) / (4 (V·H)²), which with the lecture's own
// Viz = G / (4 (n·L)(n·V)) would give 1/(16 (V·H)²); the extra 1/4 in G_K is a typo. Cheap
// (no dependence on roughness) and fast with VdotH = LdotH. Domain VdotH in (0, 1].
// Guards (pbr/common/guards.hlsl): VdotH clamped to [PBR_MIN_VDOTH, 1] (V <= 1e12),
// cosines saturated, and G capped at 1: for consistent directions VdotH² = (1 + l·v)/2 >=
// NdotL NdotV, so G <= 1 holds and the cap changes nothing; it only bounds inconsistent
// cosines. Bit-identical for VdotH in [5e-6, 1] and consistent geometry.
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_BRDF_V_KELEMEN_HLSL
#define PBR_BRDF_V_KELEMEN_HLSL
#include "pbr/common/shim.hlsl"  // generated from glsl/pbr/brdf/v_kelemen.glsl by harness/pbrlab/gpu/port_hlsl.py: edit the GLSL, then regenerate

#include "pbr/common/guards.hlsl"

float pbr_G_Kelemen(float NdotL, float NdotV, float VdotH) {
    float VdotHSafe = clamp(VdotH, PBR_MIN_VDOTH, 1.0);
    return min(1.0, pbr_saturate(NdotL) * pbr_saturate(NdotV) / (VdotHSafe * VdotHSafe));
}

float pbr_V_Kelemen(float VdotH) {
    float VdotHSafe = clamp(VdotH, PBR_MIN_VDOTH, 1.0);
    return 0.25 / (VdotHSafe * VdotHSafe);
}

#endif // PBR_BRDF_V_KELEMEN_HLSL
