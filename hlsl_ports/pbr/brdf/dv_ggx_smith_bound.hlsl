// pbr/brdf/dv_ggx_smith_bound.hlsl: GGX D times the square-root-free bound of the
// height-correlated Smith V, as one quotient (the LOW tier's specular lobe).
//
// Provides: float pbr_DV_GGX_SmithBound(float nDotH, float nCrossH2, float h2, float NdotL,
//                                       float NdotV, float alpha)
// Include:  "pbr/brdf/dv_ggx_smith_bound.hlsl" (path relative to hlsl_ports/)
// Config macros read: none.
//
// D = alpha² / (π dn²), dn = 1 - NdotH² (1 - alpha²) (Walter et al. 2007 eq. 33), with NdotH²
// = (n·h)² / |h|² from an unnormalised h (dv_ggx_smith_correlated.hlsl); V = 0.5 / (NdotL +
// NdotV) (v_smith_ggx_bound.hlsl, Heitz 2014 eq. 99 with each square root bounded by 1).
// For h = l + v, NdotL + NdotV = n·(l + v) = nDotH (= 2 LdotH NdotH: V = 1 / (4 LdotH NdotH),
// Kelemen & Szirmay-Kalos 2001's 1 / (4 LdotH²) with one LdotH replaced by NdotH), so
//   D · V = (alpha² / 2π) / (dn² n·(l + v)),
// with n·v as it is (no clamp: n·(l + v) >= PBR_MIN_NDOT_HALF_SUM wherever the caller uses
// the lobe). NdotL and NdotV are not read (the dispatcher's common signature).
// Cheaper than the other tiers' lobes on three counts (issue 25, measured: docs/bench): no
// square root in V, dn from NdotH² in the cancelling form 1 - NdotH² (1 - alpha²) instead of
// |n × h|² (one multiply-add instead of six; float32 rounding of NdotH² near 1 is 2^-24
// absolute, so dn, which is >= alpha², is within 2^-23 / alpha² relative: 1.9e-3 at the LOW
// tier's floor alpha² = 0.089⁴ = 6.3e-5, 2.9 % at the HIGH floor: use it with the LOW floor),
// and V from n·(l + v), which the caller has (no add, no clamp of NdotV).
// Preconditions (pbr_brdf_standard establishes them): alpha >= PBR_MIN_PERCEPTUAL_ROUGHNESS_MEDIUMP²,
// h = l + v with l, v unit, h2 = |h|² in [2^-100, 4], nDotH = n·h >= PBR_MIN_NDOT_HALF_SUM
// (below the horizon, where NdotL = 0 stands in n·(l + v), h2 may be shorter than nDotH²:
// cos² is saturated, so the value stays finite; elsewhere the caller does not select it).
// nCrossH2 is not read either. Range: dn >= alpha², D · V <= 1 / (2π alpha² n·(l + v)) <= 2.8e18.
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_BRDF_DV_GGX_SMITH_BOUND_HLSL
#define PBR_BRDF_DV_GGX_SMITH_BOUND_HLSL
#include "pbr/common/shim.hlsl"  // generated from glsl/pbr/brdf/dv_ggx_smith_bound.glsl by harness/pbrlab/gpu/port_hlsl.py: edit the GLSL, then regenerate

#include "pbr/common/constants.hlsl"

float pbr_DV_GGX_SmithBound(float nDotH, float nCrossH2, float h2, float NdotL, float NdotV,
                            float alpha) {
    float a2 = alpha * alpha;
    // NdotH² saturated (a free output modifier on AMD): a short l + v can round it above 1,
    // where dn would reach 0; saturated, dn >= alpha² > 0
    float cos2 = clamp(nDotH * nDotH * (1.0 / h2), 0.0, 1.0);
    float dn = 1.0 - cos2 * (1.0 - a2);
    return (a2 * (0.5 * PBR_INV_PI)) / (dn * dn * nDotH);
}

#endif // PBR_BRDF_DV_GGX_SMITH_BOUND_HLSL
