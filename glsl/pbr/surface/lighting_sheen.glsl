// pbr/surface/lighting_sheen.glsl: KHR_materials_sheen's sheen over a lit base, for one
// punctual light and the environment: the sheen layer of the surface API
// (pbr/unity/surface_layers.glsl gives it Unity's names; the clear coat goes over it).
//
// Provides: struct pbr_Sheen, PBR_SHEEN_ENERGY_* values
//           float pbr_sheen_energy_scale(float E)
//           float pbr_sheen_effective_albedo(float E)
//           vec3 pbr_lighting_sheen(vec3 base, pbr_Sheen sheen, vec3 n, vec3 v, pbr_GI gi,
//                                   vec3 sheenPrefiltered, float occlusion)
// Include:  "pbr/surface/lighting_sheen.glsl" (path relative to glsl/)
// Config macros read: PBR_SHEEN_ENERGY = PBR_SHEEN_ENERGY_NORMALIZED (1, default) |
//           PBR_SHEEN_ENERGY_SPECIFICATION (2); those of pbr/shading/sheen.glsl
//           (PBR_SHEEN_V, PBR_SHEEN_LUT_LOOKUP).
//
// The layer (KHR_materials_sheen, "Implementation Notes"; the Khronos Sample Renderer's
// pbr.frag does the same, sheen on the base and the coat over both):
//   result = base · (1 - max3(c) E'(NdotV))
//          + s(NdotV) · π · c · D_Charlie · V · NdotL · light          (one punctual light)
//          + sheenPrefiltered · c · E'(NdotV) · occlusion              (the environment)
// with E = pbr_sheen_albedo(NdotV, r) the directional albedo of the white lobe. The base is
// scaled by the view-only form 1 - max3(c) E(NdotV) for light and environment alike
// (KHR's cheaper form; a v-only factor like the coat's, so one call may carry a light, the
// environment or both). sheenPrefiltered: the environment prefiltered along
// reflect(-v, n) at the sheen's roughness. The Sample Renderer reads a Charlie-prefiltered
// radiance there (getIBLRadianceCharlie: lod = sheenRoughness x (mips - 1), times its
// lut_charlie.b); pbrlab's harness passes its GGX-prefiltered chain at the sheen roughness
// (exact for a constant environment). n: the base's normal (world, unit).
// Energy (PBR_SHEEN_ENERGY):
//   _SPECIFICATION  s = 1, E' = E: the specification's raw form. KHR's fitted Λ makes E of a
//                   white sheen exceed 1 at grazing views for sheen roughness < 0.27, up to
//                   E = 2.94 (r = 0.07 floor, NdotV 1.7e-3; pbr/shading/sheen.glsl): a white
//                   sheen over a white base then returns up to 2.94 in a white furnace (the
//                   base's scaling clamps at 0).
//   _NORMALIZED     s = 1 / max(1, E(NdotV)), E' = min(E, 1) = s E: the lobe and its
//                   environment term are scaled where their albedo exceeds 1, so the sheen
//                   reflects at most E' ≤ 1 and base (1 - max3(c) E') + c E' ≤ 1 for any
//                   base ≤ 1 (white furnace through the renderer ≤ 1 + 1e-4 for every layer
//                   combination: tests/render/test_white_furnace.py). Identical to the
//                   specification wherever E ≤ 1 (every view for r ≥ 0.27; NdotV ≳ 0.1 below).
//                   Reciprocity is broken only where the raw lobe created energy.
// Python twin: harness/pbrlab/maths/reference/sheen.py lighting_sheen.
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_SURFACE_LIGHTING_SHEEN_GLSL
#define PBR_SURFACE_LIGHTING_SHEEN_GLSL
#include "pbr/common/conventions.glsl"
#include "pbr/surface/lighting_standard.glsl"
#include "pbr/shading/sheen.glsl"

#define PBR_SHEEN_ENERGY_NORMALIZED 1
#define PBR_SHEEN_ENERGY_SPECIFICATION 2
#ifndef PBR_SHEEN_ENERGY
// PBR_SHEEN_ENERGY_NORMALIZED as a number (glsl/README.md, one-level preprocessors)
#define PBR_SHEEN_ENERGY 1
#endif
#if PBR_SHEEN_ENERGY != PBR_SHEEN_ENERGY_NORMALIZED && PBR_SHEEN_ENERGY != PBR_SHEEN_ENERGY_SPECIFICATION
#error PBR_SHEEN_ENERGY: unknown value
#endif

struct pbr_Sheen {
    vec3 color;                 // linear, 0: no sheen (glTF sheenColorFactor x texture.rgb)
    float perceptualRoughness;  // glTF sheenRoughnessFactor x texture.a
};

// The factor of the sheen lobe and its environment term at this view's albedo E.
float pbr_sheen_energy_scale(float E) {
#if PBR_SHEEN_ENERGY == PBR_SHEEN_ENERGY_NORMALIZED
    return 1.0 / max(E, 1.0);
#else
    return 1.0;
#endif
}

// What the (scaled) white sheen reflects of a white environment: min(E, 1) or E.
float pbr_sheen_effective_albedo(float E) {
#if PBR_SHEEN_ENERGY == PBR_SHEEN_ENERGY_NORMALIZED
    return min(E, 1.0);
#else
    return E;
#endif
}

vec3 pbr_lighting_sheen(vec3 base, pbr_Sheen sheen, vec3 n, vec3 v, pbr_GI gi,
                        vec3 sheenPrefiltered, float occlusion) {
    float NdotV = max(dot(n, v), PBR_MIN_NDOTV);
    float E = pbr_sheen_albedo(NdotV, sheen.perceptualRoughness);
    float albedo = pbr_sheen_effective_albedo(E);
    vec3 l = gi.light.dir;
    float NdotL = clamp(dot(n, l), 0.0, 1.0);
    vec3 h = pbr_safe_normalize(l + v);
    float NdotH = clamp(dot(n, h), 0.0, 1.0);
    vec3 direct = pbr_sheen_lobe(NdotL, NdotV, NdotH, sheen.color, sheen.perceptualRoughness)
                * gi.light.color * (PBR_LIGHT_UNIT_SCALE * NdotL * pbr_sheen_energy_scale(E));
    vec3 environment = sheenPrefiltered * sheen.color * (albedo * occlusion);
    return base * pbr_sheen_albedo_scaling(sheen.color, albedo) + direct + environment;
}
#endif
