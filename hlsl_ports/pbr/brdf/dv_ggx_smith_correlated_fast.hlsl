// pbr/brdf/dv_ggx_smith_correlated_fast.hlsl: GGX D times Hammon's approximate
// height-correlated Smith V, as one quotient (the MEDIUM tier's specular lobe).
//
// Provides: float pbr_DV_GGX_SmithCorrelatedFast(float nDotH, float nCrossH2, float h2,
//                                                float NdotL, float NdotV, float alpha)
//           float pbr_DV_GGX_SmithCorrelatedFast_half(...)  (same arguments, half's range)
// Include:  "pbr/brdf/dv_ggx_smith_correlated_fast.hlsl" (path relative to hlsl_ports/)
// Config macros read: PBR_FLOAT16 (pbr/common/precision.hlsl), for the _half form.
//
// D as in dv_ggx_smith_correlated.hlsl (Walter et al. 2007 eq. 33, from an unnormalised h);
// V = 0.5 / (lambdaV + lambdaL) with Hammon's linear lambdas (GDC 2017, "PBR Diffuse
// Lighting for GGX+Smith Microsurfaces"; v_smith_ggx_correlated.hlsl's fast form):
//   lambdaV + lambdaL = NdotL (NdotV (1 - alpha) + alpha) + NdotV (NdotL (1 - alpha) + alpha)
//                     = mix(2 NdotL NdotV, NdotL + NdotV, alpha),
// so D · V = (alpha² / 2π) h2² / (d² mix(...)): no square root at all, one reciprocal.
// Preconditions and range: those of pbr_DV_GGX_SmithCorrelated (mix(...) >= NdotV alpha
// like the exact lambdas). Error: V's, at most 29 % (PBR_V_SMITH_GGX_CORRELATED_FAST_MAX_REL_ERROR).
// The _half form is the same value evaluated inside half's range (the LOW tier where
// PBR_HALF_ARITHMETIC: PBR_FLOAT16 or GLSL ES mediump), in PBR_HALF, from the same
// normalised dn (Filament's mobile D_GGX form), whose two squares are divided by h2 in
// float32 before they are converted, so a short l + v never reaches half:
//   dn = (|n × h|² + (n·h)² alpha²) / h2 in [alpha², 1],  k = alpha / dn <= 1 / alpha,
//   D · V = k² / π · 0.5 / mix(...).
// With alpha >= 0.089² (the LOW floor) dn >= 6.3e-5 and k² <= 1.6e4 fit half, each of dn's
// two terms computed within [0, 1] so that neither relies on half denormals (mediump need
// not keep them); mix(...) is floored at half's smallest normal 2^-14 (V <= 8192: it differs
// from the float32 form only where NdotL + NdotV < 7.7e-3). The product may pass 65504 and
// become +Inf, which the LOW tier's lobe cap (pbr_specular_lobe_limit, a min) maps to 65504;
// k² > 0, so no Inf · 0. It costs a second reciprocal: measured in docs/bench.
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_BRDF_DV_GGX_SMITH_CORRELATED_FAST_HLSL
#define PBR_BRDF_DV_GGX_SMITH_CORRELATED_FAST_HLSL
#include "pbr/common/shim.hlsl"  // generated from glsl/pbr/brdf/dv_ggx_smith_correlated_fast.glsl by harness/pbrlab/gpu/port_hlsl.py: edit the GLSL, then regenerate

#include "pbr/common/constants.hlsl"
#include "pbr/common/precision.hlsl"
#include "pbr/brdf/dv_ggx_smith_correlated.hlsl"

float pbr_DV_GGX_SmithCorrelatedFast(float nDotH, float nCrossH2, float h2, float NdotL,
                                     float NdotV, float alpha) {
    return pbr_DV_GGX_fromLambdaSum(nDotH, nCrossH2, h2, alpha,
                                    lerp(2.0 * NdotL * NdotV, NdotL + NdotV, alpha));
}

float pbr_DV_GGX_SmithCorrelatedFast_half(float nDotH, float nCrossH2, float h2, float NdotL,
                                          float NdotV, float alpha) {
    PBR_HALF a = PBR_HALF(alpha);
    PBR_HALF cosL = PBR_HALF(NdotL);
    PBR_HALF cosV = PBR_HALF(NdotV);
    float invH2 = 1.0 / h2;
    // each term of dn in [0, 1] before it is added, so neither depends on half denormals:
    // sin² ≈ 1 where cos² · alpha² underflows, and cos² · alpha² >= alpha² at the peak
    PBR_HALF dn = PBR_HALF(nCrossH2 * invH2) + PBR_HALF(nDotH * nDotH * invH2) * (a * a);
    PBR_HALF k = a / dn;
    PBR_HALF lambdas = max(lerp(PBR_HALF(2.0) * cosL * cosV, cosL + cosV, a), PBR_HALF(PBR_HALF_MIN_NORMAL));
    return float(k * k * (PBR_HALF(0.5 * PBR_INV_PI) / lambdas));
}

#endif // PBR_BRDF_DV_GGX_SMITH_CORRELATED_FAST_HLSL
