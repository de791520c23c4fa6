// pbr/brdf/d_beckmann.glsl: the Beckmann normal distribution.
//
// Provides: float pbr_D_Beckmann(float NdotH, float alpha)
// Include:  "pbr/brdf/d_beckmann.glsl" (path relative to glsl/)
// Config macros read: none.
//
// Beckmann & Spizzichino 1963; Walter et al. 2007, "Microfacet Models for Refraction
// through Rough Surfaces", eq. 25:
//   D_B = exp(-tan²θ / alpha²) / (π alpha² cos⁴θ),  cos θ = NdotH,
//       = exp((NdotH² - 1) / (alpha² NdotH²)) / (π alpha² NdotH⁴).
// tan²θ·cos²θ = 1 - NdotH² is computed as (1 - NdotH)(1 + NdotH) (exact cancellation, see
// d_ggx.glsl). At NdotH = 0 the formula is 0/0 while the limit is 0: returned as 0 (the
// limit, not a clamp). alpha here is the Beckmann RMS slope; using the GGX alpha gives a
// similar highlight for small alpha (Walter 2007 §5.2). Domain NdotH in [0, 1],
// alpha in (0, 1]. Normalised (tested by quadrature). float32: exp(x) carries a relative
// error ~ |x| · 2^-24 from the rounding of its argument x = -tan²θ/alpha².
#ifndef PBR_BRDF_D_BECKMANN_GLSL
#define PBR_BRDF_D_BECKMANN_GLSL

#include "pbr/common/constants.glsl"

float pbr_D_Beckmann(float NdotH, float alpha) {
    if (NdotH <= 0.0) return 0.0;
    float a2 = alpha * alpha;
    float NdotH2 = NdotH * NdotH;
    float oneMinusNdotH2 = (1.0 - NdotH) * (1.0 + NdotH);
    return exp(-oneMinusNdotH2 / (a2 * NdotH2)) / (PBR_PI * a2 * NdotH2 * NdotH2);
}

#endif // PBR_BRDF_D_BECKMANN_GLSL
