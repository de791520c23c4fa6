// pbr/shading/transmission.glsl: light through a surface (KHR_materials_transmission) and
// through the volume behind it (KHR_materials_volume).
//
// Provides: vec3  pbr_transmission_punctual(vec3 n, vec3 v, vec3 l, vec3 lightRadiance,
//                                           vec3 baseColor, float perceptualRoughness, float eta)
//           vec3  pbr_transmission_thin_punctual(vec3 n, vec3 v, vec3 l, vec3 lightRadiance,
//                                                vec3 baseColor, float perceptualRoughness)
//           vec3  pbr_mirror_through_surface(vec3 n, vec3 l)
//           vec3  pbr_volume_attenuation(float distance, vec3 attenuationColor,
//                                        float attenuationDistance)
//           float pbr_beer_lambert(float c, float x)
//           vec3  pbr_refraction_direction(vec3 n, vec3 v, float eta)
// Include:  "pbr/shading/transmission.glsl" (path relative to glsl/)
// Config macros read: those of pbr/shading/standard.glsl (the tier's roughness clamp).
//
// A light below the surface (n.l < 0) seen from above (n.v > 0), in the lecture's light
// units (C_light · π · BTDF · |n.l|, as pbr_shade_punctual):
//   pbr_transmission_punctual       a refracting interface: Walter et al. 2007's rough BTDF
//                                   (pbr/brdf/btdf_walter.glsl), eta = index behind / in front,
//                                   tinted by baseColor as KHR_materials_transmission tints it
//                                   ("the base color ... tints the transmitted light").
//   pbr_transmission_thin_punctual  a thin wall (no volume: the extension's thin-walled case):
//                                   the light passes two parallel interfaces and leaves
//                                   unbent, so the lobe is the reflection lobe about the light
//                                   mirrored through the surface's plane, D(h') V(l', v) with
//                                   h' = normalize(l' + v), tinted by baseColor (the form of the
//                                   extension's "Transmission BTDF" and the Khronos sample
//                                   viewer's punctual transmission).
// Volume (KHR_materials_volume, "Attenuation"): sigma_t = -ln(attenuationColor) /
// attenuationDistance, T(d) = exp(-sigma_t d) = attenuationColor^(d / attenuationDistance)
// (Beer-Lambert); an infinite attenuationDistance (the extension's default) or d = 0
// transmits everything; a channel of 0 absorbs everything over any d > 0 (log 0 is -Inf:
// decided by a select, never 0 · Inf).
// pbr_refraction_direction: Snell's law in vector form (Glassner 1989, as GLSL's refract),
// the direction light from v continues in after entering a medium of relative index eta;
// total internal reflection (possible for eta < 1) returns vec3(0).
// Contract: n, v, l unit; perceptualRoughness clamped by the tier; eta in [1/16, 16].
// float64 twin: harness/pbrlab/maths/reference/transmission.py.
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_SHADING_TRANSMISSION_GLSL
#define PBR_SHADING_TRANSMISSION_GLSL

#include "pbr/common/conventions.glsl"
#include "pbr/common/guards.glsl"
#include "pbr/brdf/btdf_walter.glsl"
#include "pbr/brdf/d_ggx.glsl"
#include "pbr/brdf/v_smith_ggx_correlated.glsl"
#include "pbr/shading/standard.glsl"

vec3 pbr_transmission_punctual(vec3 n, vec3 v, vec3 l, vec3 lightRadiance, vec3 baseColor,
                               float perceptualRoughness, float eta) {
    float r = pbr_clamp_perceptual_roughness(perceptualRoughness);
    float ftCosine = pbr_BTDF_Walter_GGX_cosine(n, v, l, r * r, eta);
    return lightRadiance * baseColor * (PBR_LIGHT_UNIT_SCALE * ftCosine);
}

vec3 pbr_mirror_through_surface(vec3 n, vec3 l) {
    return l - 2.0 * dot(n, l) * n;
}

vec3 pbr_transmission_thin_punctual(vec3 n, vec3 v, vec3 l, vec3 lightRadiance, vec3 baseColor,
                                    float perceptualRoughness) {
    float r = pbr_clamp_perceptual_roughness(perceptualRoughness);
    float alpha = r * r;
    vec3 lm = pbr_mirror_through_surface(n, l);
    vec3 h = pbr_safe_normalize(lm + v);
    float NdotLm = clamp(dot(n, lm), 0.0, 1.0);
    float NdotV = clamp(dot(n, v), PBR_MIN_NDOTV, 1.0);
    float lobe = pbr_D_GGX(clamp(dot(n, h), 0.0, 1.0), alpha)
                 * pbr_V_SmithGGXCorrelated(max(NdotLm, PBR_MIN_NDOTV), NdotV, alpha);
    bool through = dot(n, l) < 0.0 && dot(n, v) > 0.0;
    return through ? lightRadiance * baseColor * (PBR_LIGHT_UNIT_SCALE * lobe * NdotLm) : vec3(0.0);
}

// One channel: c^x for x >= 0, with c = 0 absorbing everything over x > 0 and nothing
// over x = 0; c is saturated (a colour above 1 would amplify), x capped at
// PBR_BEER_LAMBERT_MAX_PATH (log2(c) · Inf is NaN at c = 1).
// The cap: every channel below 1 is already 0 there (log2(1 - 2^-24) · 1e30 = -8.6e22), and
// 1e30 times any log2 of a float32 in (0, 1] (>= -149) stays finite.
#define PBR_BEER_LAMBERT_MAX_PATH 1e30
float pbr_beer_lambert(float c, float x) {
    float cs = clamp(c, 0.0, 1.0);
    float xs = clamp(x, 0.0, PBR_BEER_LAMBERT_MAX_PATH);
    return cs > 0.0 ? exp2(log2(cs) * xs) : (xs > 0.0 ? 0.0 : 1.0);
}

vec3 pbr_volume_attenuation(float distance, vec3 attenuationColor, float attenuationDistance) {
    // x = d / D: 0 for D = +Inf (IEEE) and for d <= 0; D > 0 by the extension, floored at
    // PBR_FLT_MIN (D -> 0+: everything but a white channel absorbed)
    float x = distance > 0.0 ? distance / max(attenuationDistance, PBR_FLT_MIN) : 0.0;
    return vec3(pbr_beer_lambert(attenuationColor.x, x), pbr_beer_lambert(attenuationColor.y, x),
                pbr_beer_lambert(attenuationColor.z, x));
}

vec3 pbr_refraction_direction(vec3 n, vec3 v, float eta) {
    return refract(-v, n, 1.0 / eta);
}

#endif // PBR_SHADING_TRANSMISSION_GLSL
