// pbr/brdf/btdf_walter.glsl: the rough dielectric BTDF, GGX microfacets (light through an
// interface: KHR_materials_transmission with a volume, glass, water).
//
// Provides: float pbr_BTDF_Walter_GGX(vec3 n, vec3 v, vec3 l, float alpha, float eta)
//           float pbr_BTDF_Walter_GGX_cosine(vec3 n, vec3 v, vec3 l, float alpha, float eta)
// Include:  "pbr/brdf/btdf_walter.glsl" (path relative to glsl/)
// Config macros read: none.
//
// Walter, Marschner, Li & Torrance 2007, "Microfacet Models for Refraction through Rough
// Surfaces", eq. 21, for light arriving from l (below the interface, n.l < 0) and leaving
// towards v (above, n.v > 0); eta = index on l's side / index on v's side (1.5: light from
// inside glass seen from air):
//   h  = -(eta l + v) / |eta l + v|, on n's side                       (eq. 16)
//   ft = |l.h| |v.h| / (|n.l| |n.v|) · (1 - F(v.h)) G D / (eta (l.h) + (v.h))²
// with D the GGX distribution (eq. 33), G = G1(v) G1(l) the separable Smith masking
// (eqs. 23, 34) and F the exact dielectric Fresnel (eq. 22; 1 - F as pbr_T_Dielectric of
// pbr/brdf/f_dielectric.glsl, which keeps its precision near the critical angle).
// Radiance convention: eq. 21 carries eta_o² / eta_i² (light squeezed into a denser medium
// is brighter); a smooth interface gives eta² ∫ ft |n.l| dl = 1 - F(n.v) (tested in float64).
// Rearranged: eta (l.h) + (v.h) = h.(eta l + v) = -|eta l + v|, so the squared denominator
// is |eta l + v|², the unnormalised half vector's own length: no cancellation, and
// pbr_BTDF_Walter_GGX_cosine (ft |n.l|, what a light integral needs) drops |n.l| exactly.
// Zero where no refraction joins l and v: v and l on one side of the microfacet
// ((l.h)(v.h) >= 0), l above the surface or v below it, and where |eta l + v|² <
// PBR_MIN_HALF_VECTOR_LENGTH_SQUARED (eta = 1, l = -v: an index-matched interface passes
// light straight through, a Dirac; decided 0). Domain: n, v, l unit, alpha in [0, 1],
// eta in [1/16, 16]; alpha is floored at PBR_MIN_ALPHA, |n.v| at PBR_MIN_NDOTV.
// float64 twin: harness/pbrlab/maths/reference/transmission.py (eq. 21 as printed).
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_BRDF_BTDF_WALTER_GLSL
#define PBR_BRDF_BTDF_WALTER_GLSL

#include "pbr/common/guards.glsl"
#include "pbr/brdf/d_ggx.glsl"
#include "pbr/brdf/g_smith_ggx.glsl"
#include "pbr/brdf/f_dielectric.glsl"

// ft |n.l|: eq. 21 with the |n.l| of the light integral cancelled.
float pbr_BTDF_Walter_GGX_cosine(vec3 n, vec3 v, vec3 l, float alpha, float eta) {
    vec3 ht = -(eta * l + v);
    float length2 = dot(ht, ht);
    float NdotV = dot(n, v);
    float NdotL = dot(n, l);
    vec3 h = ht * inversesqrt(max(length2, PBR_MIN_HALF_VECTOR_LENGTH_SQUARED));
    h = dot(n, h) < 0.0 ? -h : h;
    float VdotH = dot(v, h);
    float LdotH = dot(l, h);
    bool refracts = VdotH * LdotH < 0.0 && NdotV > 0.0 && NdotL < 0.0
                    && length2 >= PBR_MIN_HALF_VECTOR_LENGTH_SQUARED;
    float a = max(alpha, PBR_MIN_ALPHA);
    float D = pbr_D_GGX(clamp(dot(n, h), 0.0, 1.0), a);
    float G = pbr_G1_SmithGGX(NdotV, a) * pbr_G1_SmithGGX(-NdotL, a);
    float T = pbr_T_Dielectric(VdotH, eta);  // 1 - F without the cancellation near F = 1
    float ft = abs(LdotH) * abs(VdotH) / max(NdotV, PBR_MIN_NDOTV) * T * G * D
               / max(length2, PBR_MIN_HALF_VECTOR_LENGTH_SQUARED);
    return refracts ? ft : 0.0;
}

float pbr_BTDF_Walter_GGX(vec3 n, vec3 v, vec3 l, float alpha, float eta) {
    return pbr_BTDF_Walter_GGX_cosine(n, v, l, alpha, eta) / max(-dot(n, l), PBR_MIN_NDOTV);
}

#endif // PBR_BRDF_BTDF_WALTER_GLSL
