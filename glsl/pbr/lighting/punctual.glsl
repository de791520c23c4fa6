// pbr/lighting/punctual.glsl: punctual (directional, point, spot) light integration.
//
// Provides: vec3 pbr_shade_punctual(vec3 n, vec3 v, vec3 l, vec3 lightRadiance,
//                                   vec3 diffuseColor, vec3 f0, float perceptualRoughness)
//           vec3 pbr_shade_punctual_f90(vec3 n, vec3 v, vec3 l, vec3 lightRadiance,
//                                       vec3 diffuseColor, vec3 f0, float f90,
//                                       float perceptualRoughness)  (an explicit F90)
// Include:  "pbr/lighting/punctual.glsl" (path relative to glsl/)
// Config macros read: those of pbr/shading/dispatch.glsl.
//
// The lecture's "Bidirectional Reflectance Functions" slide, for punctual lights:
//   C_final = C_light ⊗ π · BRDF(l, v) · max(0, NdotL)
// with the π named PBR_LIGHT_UNIT_SCALE (pbr/common/conventions.glsl §5: "lights are π
// times too bright"). A white Lambert surface (diffuseColor 1, f0 0) lit by
// lightRadiance = 1 along n returns exactly 1 (tested). lightRadiance is the light's
// colour times intensity, already attenuated (distance, spot cone, shadow) by the caller;
// l points from the surface to the light. NdotL <= 0 returns 0 (max(0, NdotL) times the
// BRDF's finite value there); l = -v returns the diffuse part only (see
// pbr/shading/standard.glsl for every edge).
// PBR_LIGHT_UNIT_SCALE is π (conventions §5) and pbr_brdf_standard[_f90] is (diffuseColor πFd +
// πDV F) / π (pbr_brdf_standard_terms), so the light's term is written as π BRDF times
// NdotL: the 1/π and the π cancel here, in the source. Left to the compiler they stay two
// multiplications (x / π · π is not x in float: 4 RDNA3 instructions a light, measured in
// the scene programs); the value differs from the two-step form by float rounding only.
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_LIGHTING_PUNCTUAL_GLSL
#define PBR_LIGHTING_PUNCTUAL_GLSL

#include "pbr/common/conventions.glsl"
#include "pbr/shading/standard.glsl"

vec3 pbr_shade_punctual(vec3 n, vec3 v, vec3 l, vec3 lightRadiance,
                        vec3 diffuseColor, vec3 f0, float perceptualRoughness) {
    float NdotL = clamp(dot(n, l), 0.0, 1.0);
    float piFd, piDV, LdotH;
    pbr_brdf_standard_terms(n, v, l, perceptualRoughness, piFd, piDV, LdotH);
    vec3 piBrdf = diffuseColor * piFd + piDV * pbr_specular_F(f0, LdotH);  // PBR_LIGHT_UNIT_SCALE · BRDF
    return lightRadiance * piBrdf * NdotL;
}

// The same with an explicit F90 (pbr_brdf_standard_f90: KHR_materials_specular's specularFactor).
vec3 pbr_shade_punctual_f90(vec3 n, vec3 v, vec3 l, vec3 lightRadiance,
                            vec3 diffuseColor, vec3 f0, float f90, float perceptualRoughness) {
    float NdotL = clamp(dot(n, l), 0.0, 1.0);
    float piFd, piDV, LdotH;
    pbr_brdf_standard_terms(n, v, l, perceptualRoughness, piFd, piDV, LdotH);
    vec3 piBrdf = diffuseColor * piFd + piDV * pbr_specular_F_f90(f0, f90, LdotH);  // PBR_LIGHT_UNIT_SCALE · BRDF
    return lightRadiance * piBrdf * NdotL;
}

#endif // PBR_LIGHTING_PUNCTUAL_GLSL
