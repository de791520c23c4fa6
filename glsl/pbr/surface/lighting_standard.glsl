// pbr/surface/lighting_standard.glsl: one surface point lit by one punctual light and by
// the environment (indirect diffuse and specular): the core of the Unity-style API.
//
// Provides: struct pbr_Light, struct pbr_Indirect, struct pbr_GI, struct pbr_PreparedSurface
//           vec3 pbr_indirect_specular_split_sum(vec3 prefiltered, vec3 f0, float roughness,
//                                                float NdotV, float occlusion, vec2 dfg)
//           vec3 pbr_indirect_diffuse_color(vec3 diffuseColor, vec3 coatF0, vec2 dfg)
//           vec3 pbr_lighting_standard(vec3 diffuseColor, vec3 f0, vec3 coatF0,
//                                      float perceptualRoughness, float occlusion, vec3 n,
//                                      vec3 v, pbr_GI gi)
//           vec3 pbr_lighting_standard_dfg(vec3 diffuseColor, vec3 f0, vec3 coatF0,
//                                          float perceptualRoughness, float occlusion, vec3 n,
//                                          vec3 v, pbr_GI gi, vec2 dfg)
//           pbr_PreparedSurface pbr_prepare_surface_dfg(vec3 diffuseColor, vec3 f0, vec3 coatF0,
//                                          float perceptualRoughness, float occlusion, vec3 n,
//                                          vec3 v, vec2 dfg)
//           pbr_PreparedSurface pbr_prepare_surface(vec3 diffuseColor, vec3 f0, vec3 coatF0,
//                                          float perceptualRoughness, float occlusion, vec3 n, vec3 v)
//           vec3 pbr_lighting_standard_light(pbr_PreparedSurface s, pbr_Light light)
//           vec3 pbr_lighting_standard_add_environment(pbr_PreparedSurface s, pbr_Indirect indirect,
//                                                      vec3 radiance)
//           pbr_PreparedSurface pbr_prepare_surface_f90_dfg(vec3 diffuseColor, vec3 f0, float f90,
//                                          vec3 coatF0, float coatF90, float perceptualRoughness,
//                                          float occlusion, vec3 n, vec3 v, vec2 dfg)
//           pbr_PreparedSurface pbr_prepare_surface_f90(..., vec3 n, vec3 v)  (the table fetched)
//           vec3 pbr_lighting_standard_f90(vec3 diffuseColor, vec3 f0, float f90, vec3 coatF0,
//                                          float coatF90, float perceptualRoughness,
//                                          float occlusion, vec3 n, vec3 v, pbr_GI gi)
//           vec3 pbr_lighting_standard_f90_dfg(..., pbr_GI gi, vec2 dfg)  (the same, given dfg)
//           vec3 pbr_indirect_specular_albedo_f90(vec3 f0, float f90, vec2 dfg)
//           vec3 pbr_indirect_specular_split_sum_f90(vec3 prefiltered, vec3 f0, float f90, ...)
//           vec3 pbr_indirect_diffuse_color_f90(vec3 diffuseColor, vec3 coatF0, float coatF90,
//                                               vec2 dfg)
// Include:  "pbr/surface/lighting_standard.glsl" (path relative to glsl/)
// Config macros read: PBR_ENERGY_COMPENSATION (1, the HIGH and MEDIUM tiers' default: compensate
//           multiple scattering in the environment specular; 0, LOW's: single scattering only);
//           those of pbr/shading/dispatch.glsl and pbr/ibl/environment_brdf.glsl;
//           PBR_LIGHT_NDOTL (0 default; 1: pbr_Light has Unity's unread ndotl member).
//           (Unity's own BRDFs, its environment term included, are a model of their own:
//           PBR_BRDF_MODEL_UNITY, pbr/unity/brdf_unity.glsl.)
//
// The structs mirror Unity's UnityLight / UnityIndirect / UnityGI (pbr/unity/ aliases
// them), with pbrlab's units: light.color is the radiance arriving from a punctual light
// (colour * intensity * attenuation, "pi times too bright"); light.dir points from the
// surface to the light; indirect.diffuse is the irradiance divided by pi (what a white
// Lambert surface reflects, e.g. pbr_sh9_irradiance(sh, n) / pi); indirect.specular is
// the prefiltered environment radiance along reflect(-v, n), already at the mip of this
// roughness. Without a light, set light.color to 0.
//
// Energy: diffuseColor is the workflow's diffuse colour (pbr_diffuse_from_metallic /
// pbr_diffuse_from_specular, Unity's diffColor); coatF0 is the F0 of the dielectric coat
// over the diffuse: vec3(PBR_DIELECTRIC_F0) in the metallic workflow (f0 also holds the
// metal's part, which has no diffuse under it), the specular colour (= f0) in the specular
// workflow. The diffuse lobe is coupled to the coat by pbr_coupled_diffuse_color
// (pbr/shading/energy_conservation.glsl): it gets 1 - E of the light, E the coat's
// directional albedo at NdotV from the same DFG values as the split sum (single
// scattering for direct light, times the compensation for the environment when
// PBR_ENERGY_COMPENSATION is on). F90 follows F0 (pbr_f90_from_f0), so
// f0 = 0 has no specular; the _f90 forms take the caller's F90 instead, for f0
// (f90) and for the coat's F0 (coatF90): KHR_materials_specular's F90 = specularFactor ·
// specularTexture.a (the dielectric's; a metallic m blends it towards 1, F90 = mix(f90, 1, m)),
// in the direct lobe, the split sum and both couplings of the diffuse. Each needs f90 >= every
// channel of its F0 (pbr_specular_F_f90). Under a uniform white environment every tier reflects at most 1
// (tests/render/test_white_furnace.py).
//
// Once per pixel, not per light (issue 25): everything that depends only on the point, the
// view and the material (the DFG values, the coat's albedo bound and the diffuse colour
// coupled to it, the environment's albedo with its compensation, the specular occlusion) is
// pbr_prepare_surface[_dfg], computed before the loop over lights; each light then costs
// pbr_lighting_standard_light (the BRDF and its cosine: no table, no coupling), and the
// environment is added once by pbr_lighting_standard_add_environment:
//   pbr_PreparedSurface s = pbr_prepare_surface(diffuseColor, f0, coatF0, roughness, ao, n, v);
//   vec3 c = vec3(0.0);
//   for (...) c += pbr_lighting_standard_light(s, light[i]);
//   c = pbr_lighting_standard_add_environment(s, indirect, c);
// pbr_lighting_standard[_dfg] (one light and the environment) is that composition, with the
// same operations in the same order as before the split (bit for bit: the golden tests).
// An explicit F90 is part of the preparation only when asked for: pbr_prepare_surface_f90[_dfg]
// fill the same struct with the caller's F90s (s.f90 for f0's Fresnel; the couplings and the
// split sum with them), pbr_prepare_surface[_dfg] with pbr_f90_from_f0; the light and the
// environment read the struct alike, and pbr_lighting_standard_f90[_dfg] are the same
// composition over pbr_prepare_surface_f90[_dfg].
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_SURFACE_LIGHTING_STANDARD_GLSL
#define PBR_SURFACE_LIGHTING_STANDARD_GLSL
#include "pbr/lighting/punctual.glsl"
#include "pbr/ibl/environment_brdf.glsl"
#include "pbr/shading/standard.glsl"
#include "pbr/shading/energy_conservation.glsl"
#include "pbr/common/math.glsl"

// PBR_ENERGY_COMPENSATION's default is the tier's (pbr/shading/dispatch.glsl: 1 in HIGH and
// MEDIUM, 0 in LOW), set there through environment_brdf.glsl's include; this file's own
// default (every file that reads a selector has one) is therefore never the one taken.
#ifndef PBR_ENERGY_COMPENSATION
#define PBR_ENERGY_COMPENSATION 1
#endif

// PBR_LIGHT_NDOTL 1 gives pbr_Light a third member, float ndotl, which nothing here reads: Unity's
// UnityLight (pbr/unity/brdf_unity.glsl aliases it to this struct) declares it, deprecated and
// unread by Unity's own functions (UnityLightingCommon.cginc), and older shaders still assign and
// read it. The harness sets it for Unity programs; by default the struct keeps two members, so
// pbr_Light(color, dir) constructs it.
#ifndef PBR_LIGHT_NDOTL
#define PBR_LIGHT_NDOTL 0
#endif
#if PBR_LIGHT_NDOTL != 0 && PBR_LIGHT_NDOTL != 1
#error PBR_LIGHT_NDOTL: unknown value (0 or 1)
#endif

struct pbr_Light {
    vec3 color;
    vec3 dir;
#if PBR_LIGHT_NDOTL != 0
    float ndotl;
#endif
};

struct pbr_Indirect {
    vec3 diffuse;
    vec3 specular;
};

struct pbr_GI {
    pbr_Light light;
    pbr_Indirect indirect;
};

// The directional albedo of the specular lobe under environment light: single scattering
// (pbr_specular_albedo_f90: F0 A + F90 B) times, by default, the multiple-scattering
// compensation (at F0: see pbr_energy_compensation). The plain forms take F90 =
// pbr_f90_from_f0(f0), as the BRDF does (pbr/shading/dispatch.glsl), in bodies of their own:
// written as calls of the _f90 forms, the F90's earlier computation moved the HLSL port's
// filmed scene programs by -3 .. -5 RDNA3 instructions (see pbr_prepare_surface_f90_dfg).
vec3 pbr_indirect_specular_albedo_f90(vec3 f0, float f90, vec2 dfg) {
    vec3 albedo = pbr_specular_albedo_f90(f0, f90, dfg);
#if PBR_ENERGY_COMPENSATION != 0
    albedo *= pbr_energy_compensation(f0, dfg);
#endif
    return albedo;
}

vec3 pbr_indirect_specular_albedo(vec3 f0, vec2 dfg) {
    vec3 albedo = pbr_specular_albedo(f0, dfg);
#if PBR_ENERGY_COMPENSATION != 0
    albedo *= pbr_energy_compensation(f0, dfg);
#endif
    return albedo;
}

// The environment's specular reflection as pbrlab computes it: prefiltered radiance times
// the split-sum albedo (Karis 2013), with specular occlusion and, by default,
// multiple-scattering compensation. dfg = pbr_env_brdf(NdotV, roughness).
vec3 pbr_indirect_specular_split_sum_f90(vec3 prefiltered, vec3 f0, float f90, float roughness,
                                         float NdotV, float occlusion, vec2 dfg) {
    return prefiltered * pbr_indirect_specular_albedo_f90(f0, f90, dfg)
         * pbr_specular_occlusion(NdotV, occlusion, roughness * roughness);
}

vec3 pbr_indirect_specular_split_sum(vec3 prefiltered, vec3 f0, float roughness,
                                     float NdotV, float occlusion, vec2 dfg) {
    return prefiltered * pbr_indirect_specular_albedo(f0, dfg)
         * pbr_specular_occlusion(NdotV, occlusion, roughness * roughness);
}

// The diffuse colour the environment lights: coupled to the coat's environment albedo
// (with its compensation), as the split sum reflects it.
vec3 pbr_indirect_diffuse_color_f90(vec3 diffuseColor, vec3 coatF0, float coatF90, vec2 dfg) {
    return pbr_coupled_diffuse_color(diffuseColor, coatF0, pbr_indirect_specular_albedo_f90(coatF0, coatF90, dfg));
}

vec3 pbr_indirect_diffuse_color(vec3 diffuseColor, vec3 coatF0, vec2 dfg) {
    return pbr_coupled_diffuse_color(diffuseColor, coatF0, pbr_indirect_specular_albedo(coatF0, dfg));
}

// The per-pixel part of the lighting: what depends on the point, the view and the material
// only (pbr_prepare_surface[_f90]_dfg fills it; the per-light and environment functions read it).
struct pbr_PreparedSurface {
    vec3 n;                       // unit normal
    vec3 v;                       // unit direction to the viewer
    vec3 f0;
    float f90;                    // f0's F90: pbr_f90_from_f0(f0), or the caller's (the _f90 forms)
    float perceptualRoughness;    // clamped to the tier's floor (pbr_clamp_perceptual_roughness)
    float occlusion;              // ambient occlusion (indirect light only)
    vec3 directDiffuseColor;      // coupled to the coat's single-scattering albedo bound (direct light)
    vec3 indirectDiffuseColor;    // coupled to the coat's environment albedo (pbr_indirect_diffuse_color)
    vec3 indirectSpecularAlbedo;  // the split sum's albedo (pbr_indirect_specular_albedo)
    float specularOcclusion;      // pbr_specular_occlusion at this NdotV
};

// Direct: the diffuse coupled to the coat's single-scattering specular albedo
// (pbr_specular_albedo_bound: the tier's own lobe). Indirect: the diffuse coupled to the
// coat's environment albedo, the split-sum albedo (Karis 2013) with, by default,
// multiple-scattering compensation, and the specular occlusion. dfg must be
// pbr_env_brdf(max(dot(n, v), PBR_MIN_NDOTV), pbr_clamp_perceptual_roughness(perceptualRoughness)):
// engines that fetch their own table call the _dfg forms; pbr_prepare_surface[_f90] fetch it
// through PBR_DFG_LUT_LOOKUP (or the analytic fit: pbr/ibl/environment_brdf.glsl).
// The _f90 form takes the caller's F90 for f0 (f90) and for the coat's F0 (coatF90)
// (KHR_materials_specular: see the header); the plain form fills the same struct with F90 =
// pbr_f90_from_f0 of each, in its own body: written as a call of the _f90 form, the two F90s
// were computed ahead of the coupling and 14 of the 108 GLSL programs of tests/render/specialisation's
// scenes (sheened, anisotropic, filmed, transmissive) moved by -3 .. +3 RDNA3 instructions; in
// this order (F90 from F0 where the albedos need it, s.f90 last) every GLSL program without an
// explicit F90 compiles as before. (The HLSL port's three filmed isotropic programs lose 3 to
// 5 instructions: their light reads s.f90 where it re-derived F90 from the film's F0.)
pbr_PreparedSurface pbr_prepare_surface_f90_dfg(vec3 diffuseColor, vec3 f0, float f90, vec3 coatF0, float coatF90,
                                                float perceptualRoughness, float occlusion, vec3 n, vec3 v,
                                                vec2 dfg) {
    pbr_PreparedSurface s;
    s.n = n;
    s.v = v;
    s.f0 = f0;
    s.f90 = f90;
    s.perceptualRoughness = pbr_clamp_perceptual_roughness(perceptualRoughness);
    s.occlusion = occlusion;
    s.directDiffuseColor = pbr_coupled_diffuse_color(diffuseColor, coatF0,
                                                     pbr_specular_albedo_bound_f90(coatF0, coatF90, dfg));
    s.indirectDiffuseColor = pbr_indirect_diffuse_color_f90(diffuseColor, coatF0, coatF90, dfg);
    s.indirectSpecularAlbedo = pbr_indirect_specular_albedo_f90(f0, f90, dfg);
    s.specularOcclusion = pbr_specular_occlusion(max(dot(n, v), PBR_MIN_NDOTV), occlusion,
                                                 s.perceptualRoughness * s.perceptualRoughness);
    return s;
}

pbr_PreparedSurface pbr_prepare_surface_dfg(vec3 diffuseColor, vec3 f0, vec3 coatF0, float perceptualRoughness,
                                            float occlusion, vec3 n, vec3 v, vec2 dfg) {
    pbr_PreparedSurface s;
    s.n = n;
    s.v = v;
    s.f0 = f0;
    s.perceptualRoughness = pbr_clamp_perceptual_roughness(perceptualRoughness);
    s.occlusion = occlusion;
    s.directDiffuseColor = pbr_coupled_diffuse_color(diffuseColor, coatF0, pbr_specular_albedo_bound(coatF0, dfg));
    s.indirectDiffuseColor = pbr_indirect_diffuse_color(diffuseColor, coatF0, dfg);
    s.indirectSpecularAlbedo = pbr_indirect_specular_albedo(f0, dfg);
    s.specularOcclusion = pbr_specular_occlusion(max(dot(n, v), PBR_MIN_NDOTV), occlusion,
                                                 s.perceptualRoughness * s.perceptualRoughness);
    s.f90 = pbr_f90_from_f0(f0);
    return s;
}

pbr_PreparedSurface pbr_prepare_surface_f90(vec3 diffuseColor, vec3 f0, float f90, vec3 coatF0, float coatF90,
                                            float perceptualRoughness, float occlusion, vec3 n, vec3 v) {
    float roughness = pbr_clamp_perceptual_roughness(perceptualRoughness);
    vec2 dfg = pbr_env_brdf(max(dot(n, v), PBR_MIN_NDOTV), roughness);
    return pbr_prepare_surface_f90_dfg(diffuseColor, f0, f90, coatF0, coatF90, roughness, occlusion, n, v, dfg);
}

pbr_PreparedSurface pbr_prepare_surface(vec3 diffuseColor, vec3 f0, vec3 coatF0, float perceptualRoughness,
                                        float occlusion, vec3 n, vec3 v) {
    float roughness = pbr_clamp_perceptual_roughness(perceptualRoughness);
    vec2 dfg = pbr_env_brdf(max(dot(n, v), PBR_MIN_NDOTV), roughness);
    return pbr_prepare_surface_dfg(diffuseColor, f0, coatF0, roughness, occlusion, n, v, dfg);
}

// One punctual light: pbr_shade_punctual (the lecture's C_light * pi * BRDF * NdotL) with the
// prepared, coupled diffuse colour and the prepared F90. Nothing here depends on the table or
// the coupling.
vec3 pbr_lighting_standard_light(pbr_PreparedSurface s, pbr_Light light) {
    return pbr_shade_punctual_f90(s.n, s.v, light.dir, light.color, s.directDiffuseColor, s.f0, s.f90,
                                  s.perceptualRoughness);
}

// radiance plus the environment's light: coupled diffuse * irradiance/pi * occlusion, then the
// split-sum specular, prefiltered radiance * albedo * specular occlusion (added in this order,
// as pbr_lighting_standard_dfg always summed them). Occlusion darkens only indirect light, as
// in Unity.
vec3 pbr_lighting_standard_add_environment(pbr_PreparedSurface s, pbr_Indirect indirect, vec3 radiance) {
    return radiance + s.indirectDiffuseColor * indirect.diffuse * s.occlusion
         + indirect.specular * s.indirectSpecularAlbedo * s.specularOcclusion;
}

// One light and the environment: the composition of the three parts above.
vec3 pbr_lighting_standard_dfg(vec3 diffuseColor, vec3 f0, vec3 coatF0, float perceptualRoughness,
                               float occlusion, vec3 n, vec3 v, pbr_GI gi, vec2 dfg) {
    pbr_PreparedSurface s = pbr_prepare_surface_dfg(diffuseColor, f0, coatF0, perceptualRoughness, occlusion,
                                                    n, v, dfg);
    return pbr_lighting_standard_add_environment(s, gi.indirect, pbr_lighting_standard_light(s, gi.light));
}

vec3 pbr_lighting_standard(vec3 diffuseColor, vec3 f0, vec3 coatF0, float perceptualRoughness,
                           float occlusion, vec3 n, vec3 v, pbr_GI gi) {
    pbr_PreparedSurface s = pbr_prepare_surface(diffuseColor, f0, coatF0, perceptualRoughness, occlusion, n, v);
    return pbr_lighting_standard_add_environment(s, gi.indirect, pbr_lighting_standard_light(s, gi.light));
}

vec3 pbr_lighting_standard_f90_dfg(vec3 diffuseColor, vec3 f0, float f90, vec3 coatF0, float coatF90,
                                   float perceptualRoughness, float occlusion, vec3 n, vec3 v, pbr_GI gi,
                                   vec2 dfg) {
    pbr_PreparedSurface s = pbr_prepare_surface_f90_dfg(diffuseColor, f0, f90, coatF0, coatF90, perceptualRoughness,
                                                        occlusion, n, v, dfg);
    return pbr_lighting_standard_add_environment(s, gi.indirect, pbr_lighting_standard_light(s, gi.light));
}

vec3 pbr_lighting_standard_f90(vec3 diffuseColor, vec3 f0, float f90, vec3 coatF0, float coatF90,
                               float perceptualRoughness, float occlusion, vec3 n, vec3 v, pbr_GI gi) {
    pbr_PreparedSurface s = pbr_prepare_surface_f90(diffuseColor, f0, f90, coatF0, coatF90, perceptualRoughness,
                                                    occlusion, n, v);
    return pbr_lighting_standard_add_environment(s, gi.indirect, pbr_lighting_standard_light(s, gi.light));
}
#endif
