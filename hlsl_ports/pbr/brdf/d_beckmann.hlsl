// pbr/brdf/d_beckmann.hlsl: the Beckmann normal distribution.
//
// Provides: float pbr_D_Beckmann(float NdotH, float alpha)
//           float pbr_D_Beckmann_fromOneMinusNdotH2(float NdotH, float oneMinusNdotH2, float alpha)
//           PBR_BECKMANN_MIN_NDOTH
// Include:  "pbr/brdf/d_beckmann.hlsl" (path relative to hlsl_ports/)
// Config macros read: none.
//
// Beckmann & Spizzichino 1963; Walter et al. 2007, "Microfacet Models for Refraction
// through Rough Surfaces", eq. 25:
//   D_B = exp(-tan²θ / alpha²) / (π alpha² cos⁴θ),  cos θ = NdotH,
//       = exp((NdotH² - 1) / (alpha² NdotH²)) / (π alpha² NdotH⁴).
// tan²θ·cos²θ = 1 - NdotH² is computed as (1 - NdotH)(1 + NdotH) (exact cancellation, see
// d_ggx.hlsl; the fromOneMinusNdotH2 form takes |n × h|² like D_GGX). Guards: NdotH is
// saturated and alpha clamped to [PBR_MIN_ALPHA, 1] (as D_GGX); below
// PBR_BECKMANN_MIN_NDOTH the result is 0 (at NdotH = 0 the formula is 0/0 while the limit
// is 0, and NdotH² underflows long before). alpha here is the Beckmann RMS slope; using the GGX alpha gives a
// similar highlight for small alpha (Walter 2007 §5.2). Domain NdotH in [0, 1],
// alpha in (0, 1]. Normalised (tested by quadrature). float32: exp(x) carries a relative
// error ~ |x| · 2^-24 from the rounding of its argument x = -tan²θ/alpha².
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_BRDF_D_BECKMANN_HLSL
#define PBR_BRDF_D_BECKMANN_HLSL
#include "pbr/common/shim.hlsl"  // generated from glsl/pbr/brdf/d_beckmann.glsl by harness/pbrlab/gpu/port_hlsl.py: edit the GLSL, then regenerate

#include "pbr/common/constants.hlsl"
#include "pbr/common/guards.hlsl"

// NdotH below which D_Beckmann returns 0: for alpha <= 1, exp(-tan²θ/alpha²) < e^-99 there,
// below float32's smallest normal (e^-87.3), and D < e^-99 / (π · 0.1⁴) = 3.2e-40 1/sr.
// Cost: an absolute error below 3.2e-40 1/sr (a float32 denormal).
#define PBR_BECKMANN_MIN_NDOTH 0.1

float pbr_D_Beckmann_fromOneMinusNdotH2(float NdotH, float oneMinusNdotH2, float alpha) {
    if (!(NdotH >= PBR_BECKMANN_MIN_NDOTH)) return 0.0;
    alpha = clamp(alpha, PBR_MIN_ALPHA, 1.0);
    float a2 = alpha * alpha;
    float NdotH2 = min(NdotH * NdotH, 1.0);
    return exp(-oneMinusNdotH2 / (a2 * NdotH2)) / (PBR_PI * a2 * NdotH2 * NdotH2);
}

float pbr_D_Beckmann(float NdotH, float alpha) {
    NdotH = pbr_saturate(NdotH);
    return pbr_D_Beckmann_fromOneMinusNdotH2(NdotH, (1.0 - NdotH) * (1.0 + NdotH), alpha);
}

#endif // PBR_BRDF_D_BECKMANN_HLSL
