// pbr/brdf/f_dielectric.hlsl: exact unpolarised Fresnel reflectance of a dielectric interface.
//
// Provides: float pbr_F_Dielectric(float cosTheta, float eta)
//           float pbr_T_Dielectric(float cosTheta, float eta)
// Include:  "pbr/brdf/f_dielectric.hlsl" (path relative to hlsl_ports/)
// Config macros read: none.
//
// Walter et al. 2007, "Microfacet Models for Refraction through Rough Surfaces", eq. 22
// (the average of the s- and p-polarised Fresnel reflectances, Born & Wolf §1.5.3):
//   c = |cosTheta|,  g² = eta² - 1 + c²,
//   F = ½ ((g - c)/(g + c))² (1 + ((c (g + c) - 1) / (c (g - c) + 1))²),
//   F = 1 when g² < 0 (total internal reflection).
// cosTheta is the cosine between the incident direction and the (micro)normal, VdotH in
// microfacet use; eta = n_transmitted / n_incident (1.5 for air -> glass, 1/1.5 from
// inside). F(1, eta) = ((eta - 1)/(eta + 1))² = pbr_f0_from_ior(eta); F(0, eta) = 1.
// Rearranged for float32: eta² - 1 = (eta - 1)(eta + 1) (eta - 1 exact by Sterbenz for eta
// in [0.5, 2]) and g - c = (g² - c²)/(g + c) = (eta² - 1)/(g + c), so nothing cancels as
// eta -> 1 where F -> 0. Remaining ill-conditioning is physical: at the critical angle
// (g -> 0 from inside) dF/dc is unbounded. eta = 1 with c = 0 is 0/0: the maths has no
// value (F = 0 for eta = 1 at every c > 0, F -> 1 at c = 0 for eta != 1); decided 0 (no
// interface, no reflection), by flooring g + c at PBR_FLT_MIN. |cosTheta| is capped at 1,
// and F at 1 (at grazing (g - c)/(g + c) = 1 rounds to 1 + 2 ulp, found by the sweep).
// Bit-identical elsewhere. Domain eta in [1/16, 16] (eta² must not overflow).
// pbr_T_Dielectric = 1 - F, the transmittance, from the same amplitudes without the
// subtraction (1 - r² = 4ab / (a + b)² for r = (a - b)/(a + b)), so it keeps its relative
// precision where F -> 1 (near the critical angle 1 - F cancelled to 1 % in float32):
//   T = ½ (4 c g / (c + g)² + 4 eta² c g / (eta² c + g)²)   (s and p),
// g = eta cosθt as above; T = 0 under total internal reflection and at c = 0 (eta != 1);
// eta = 1 with c = 0 is 0/0, decided 1 (F's decided 0). Near g -> 0, dT/dc is unbounded
// as dF/dc is: that ill-conditioning is physical.
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_BRDF_F_DIELECTRIC_HLSL
#define PBR_BRDF_F_DIELECTRIC_HLSL
#include "pbr/common/shim.hlsl"  // generated from glsl/pbr/brdf/f_dielectric.glsl by harness/pbrlab/gpu/port_hlsl.py: edit the GLSL, then regenerate

#include "pbr/common/guards.hlsl"

float pbr_F_Dielectric(float cosTheta, float eta) {
    float c = min(abs(cosTheta), 1.0);
    float etaSquaredMinusOne = (eta - 1.0) * (eta + 1.0);
    float g2 = etaSquaredMinusOne + c * c;
    if (g2 < 0.0) return 1.0;  // total internal reflection
    float g = sqrt(g2);
    float gPlusC = max(g + c, PBR_FLT_MIN);
    float gMinusC = etaSquaredMinusOne / gPlusC;
    float a = gMinusC / gPlusC;
    float b = (c * (g + c) - 1.0) / (c * gMinusC + 1.0);
    return min(0.5 * a * a * (1.0 + b * b), 1.0);
}

float pbr_T_Dielectric(float cosTheta, float eta) {
    if (eta == 1.0) return 1.0;  // no interface: everything passes (c = 0 would be 0/0)
    float c = min(abs(cosTheta), 1.0);
    float eta2 = eta * eta;
    float g2 = (eta - 1.0) * (eta + 1.0) + c * c;
    if (g2 <= 0.0) return 0.0;  // total internal reflection
    float g = sqrt(g2);
    float cg4 = 4.0 * c * g;
    float s = cg4 / max((c + g) * (c + g), PBR_FLT_MIN);
    float p = eta2 * cg4 / max((eta2 * c + g) * (eta2 * c + g), PBR_FLT_MIN);
    return min(0.5 * (s + p), 1.0);
}

#endif // PBR_BRDF_F_DIELECTRIC_HLSL
