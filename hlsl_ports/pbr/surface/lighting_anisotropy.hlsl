// pbr/surface/lighting_anisotropy.hlsl: pbr_lighting_standard with KHR_materials_anisotropy's
// specular lobe: one surface point lit by one punctual light and by the environment, the
// base's specular stretched along a direction in the surface.
//
// Provides: struct pbr_Anisotropy, struct pbr_AnisotropicFrame
//           vec3 pbr_anisotropic_tangent(vec3 n, vec3 direction)
//           pbr_AnisotropicFrame pbr_anisotropic_frame(vec3 n, pbr_Anisotropy anisotropy)
//           vec3 pbr_lighting_anisotropic_light(pbr_PreparedSurface s, pbr_AnisotropicFrame frame,
//                                               pbr_Light light)
//           vec3 pbr_anisotropic_reflection_normal(vec3 n, vec3 v, pbr_Anisotropy anisotropy,
//                                                  float perceptualRoughness)
//           vec3 pbr_lighting_anisotropic_dfg(vec3 diffuseColor, vec3 f0, vec3 coatF0,
//                                             float perceptualRoughness, float occlusion,
//                                             vec3 n, vec3 v, pbr_GI gi,
//                                             pbr_Anisotropy anisotropy, vec2 dfg)
//           vec3 pbr_lighting_anisotropic(vec3 diffuseColor, vec3 f0, vec3 coatF0,
//                                         float perceptualRoughness, float occlusion, vec3 n,
//                                         vec3 v, pbr_GI gi, pbr_Anisotropy anisotropy)
//           vec3 pbr_lighting_anisotropic_f90(vec3 diffuseColor, vec3 f0, float f90, vec3 coatF0,
//                                             float coatF90, float perceptualRoughness,
//                                             float occlusion, vec3 n, vec3 v, pbr_GI gi,
//                                             pbr_Anisotropy anisotropy)  (an explicit F90)
// Include:  "pbr/surface/lighting_anisotropy.hlsl" (path relative to hlsl_ports/)
// Config macros read: those of pbr/surface/lighting_standard.hlsl and
//           pbr/shading/anisotropy.hlsl.
//
// Everything is pbr_lighting_standard_dfg's (pbr/surface/lighting_standard.hlsl: units,
// energy, the diffuse coupled to the coat over it, occlusion on indirect light only) except
// the specular lobe of direct light, which is pbr_brdf_anisotropic_specular
// (pbr/shading/anisotropy.hlsl: KHR_materials_anisotropy's alphaT = mix(alpha, 1, s²),
// alphaB = alpha, anisotropic GGX D and height-correlated Smith V, Schlick F), and the
// environment's prefiltered radiance, which the caller reads along reflect(-v, bent) with
// bent = pbr_anisotropic_reflection_normal (the Khronos sample viewer's bent normal, a
// heuristic measured at up to +205 % against the exact integral: pbr/shading/anisotropy.hlsl).
// Direct light: lightRadiance · (diffuse · Fd + D · V · F) · π · NdotL, pbr_shade_punctual's
// formula, so the diffuse term is pbr_lighting_standard's to float32 rounding (pbr_brdf_standard
// forms the sum with 1/π factored out, pbr/shading/standard.hlsl; here Fd is multiplied in).
// Once per pixel, as pbr_lighting_standard (issue 25): pbr_prepare_surface[_dfg] (the table,
// the coupling, the environment's albedo) and pbr_anisotropic_frame (the tangent frame)
// before the loop over lights, pbr_lighting_anisotropic_light per light,
// pbr_lighting_standard_add_environment once; pbr_lighting_anisotropic[_dfg] is that
// composition for one light. An explicit F90 (KHR_materials_specular: pbr_prepare_surface_f90)
// reaches the anisotropic lobe's Fresnel through the prepared surface (s.f90,
// pbr_brdf_anisotropic_specular_f90), and the split sum and the diffuse's coupling as in
// pbr_lighting_standard_f90: the Sample Renderer applies its dielectric Fresnel
// F_Schlick(f0 · specularWeight, specularWeight, VdotH) to whichever lobe it computed and
// scales its image-based term by the specularWeight (getIBLGGXFresnel) whatever the lobe;
// pbr_lighting_anisotropic_f90 is that composition for one light.
// Decided:
//  - The lobe is the exact anisotropic GGX / height-correlated Smith / Schlick one at every
//    tier and whatever PBR_SPECULAR_* selects (the library has no other anisotropic V); at
//    strength 0 it equals pbr_brdf_standard's specular to float32 rounding where that is the
//    same model (the HIGH tier with the default selectors: tested through the renderer),
//    and differs by the MEDIUM/LOW tiers' fast V (at most 29 %) elsewhere.
//  - The split sum (its DFG values, the coupling of the diffuse to the coat, the energy
//    compensation) is the isotropic one at the material's roughness, as the sample viewer
//    reads its GGX table at the isotropic roughness: stretching the lobe (alphaT >= alpha)
//    only lowers its single-scattering albedo, so the diffuse keeps at most what the
//    anisotropic lobe leaves and a white furnace stays <= 1.
//  - anisotropy.direction: the anisotropic tangent in world space, any length; it is made
//    orthogonal to n (Gram-Schmidt: the lobe's contract wants t, b ⟂ n, and a normal map
//    tilts n away from the mesh's tangent plane) and normalised; where it is zero or within
//    PBR_ANISOTROPY_MIN_SIN of n (sin of the angle), any tangent of n (pbr_tangent_to_world)
//    stands in. b = cross(n, t).
// Python twin: harness/pbrlab/maths/reference/surface.py lighting_anisotropic.
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_SURFACE_LIGHTING_ANISOTROPY_HLSL
#define PBR_SURFACE_LIGHTING_ANISOTROPY_HLSL
#include "pbr/common/shim.hlsl"  // generated from glsl/pbr/surface/lighting_anisotropy.glsl by harness/pbrlab/gpu/port_hlsl.py: edit the GLSL, then regenerate
#include "pbr/common/conventions.hlsl"
#include "pbr/common/guards.hlsl"
#include "pbr/ibl/importance_sampling.hlsl"
#include "pbr/shading/anisotropy.hlsl"
#include "pbr/surface/lighting_standard.hlsl"

// The smallest sine of the angle between the direction and n that still gives the tangent:
// d - n (n·d) of unit d carries float32 rounding of about 2^-23 per component, so at sin 1e-3
// the tangent's own direction is off by at most ~2e-4 rad; closer to n (a normal map tilted
// 89.94° from the mesh's plane) the direction says nothing and the fallback tangent is used.
// Shared with reference/surface.py ANISOTROPY_MIN_SIN.
#define PBR_ANISOTROPY_MIN_SIN 1e-3

struct pbr_Anisotropy {
    float strength;   // 0 = isotropic .. 1 (glTF anisotropyStrength x texture.b)
    float3 direction;   // world space: the direction the highlight's roughness grows along
};

// The unit tangent along direction in the plane of n (Gram-Schmidt), or any tangent of n
// where direction is zero or within PBR_ANISOTROPY_MIN_SIN of n. Branch-free: both candidates
// are formed and one selected (glslang turns a ?: whose operand is a call into a branch), so a
// program that inlines it twice with the same n and direction (the environment's bent normal
// and the lights' frame) evaluates it once: the two branches kept a copy each
// (benchmarks/whole_program_cost.py, anisotropy with one light and an environment, RDNA3:
// 638 -> 597 instructions, 48 VGPRs). The selected values are the same.
float3 pbr_anisotropic_tangent(float3 n, float3 direction) {
    float3 d = pbr_safe_normalize(direction);
    float3 t = d - n * dot(n, d);
    float t2 = dot(t, t);
    float3 projected = t * rsqrt(max(t2, PBR_FLT_MIN));
    float3 fallback = pbr_tangent_to_world(float3(1.0, 0.0, 0.0), n);
    return t2 > PBR_ANISOTROPY_MIN_SIN * PBR_ANISOTROPY_MIN_SIN ? projected : fallback;
}

// The normal whose mirror direction reflect(-v, ·) the caller reads its prefiltered
// environment along (pbr_anisotropic_bent_normal with the anisotropic bitangent, as the
// sample viewer's getIBLRadianceAnisotropy passes it).
float3 pbr_anisotropic_reflection_normal(float3 n, float3 v, pbr_Anisotropy anisotropy, float perceptualRoughness) {
    float3 b = cross(n, pbr_anisotropic_tangent(n, anisotropy.direction));
    return pbr_anisotropic_bent_normal(n, v, b, anisotropy.strength,
                                       pbr_clamp_perceptual_roughness(perceptualRoughness));
}

// The anisotropic frame at this point: t, b orthonormal, orthogonal to n (see the header).
struct pbr_AnisotropicFrame {
    float3 t;          // pbr_anisotropic_tangent(n, anisotropy.direction)
    float3 b;          // cross(n, t)
    float strength;
};

pbr_AnisotropicFrame pbr_anisotropic_frame(float3 n, pbr_Anisotropy anisotropy) {
    pbr_AnisotropicFrame frame;
    frame.t = pbr_anisotropic_tangent(n, anisotropy.direction);
    frame.b = cross(n, frame.t);
    frame.strength = anisotropy.strength;
    return frame;
}

// One punctual light: pbr_shade_punctual with pbr_brdf_standard's diffuse half (the same
// value, to float32 rounding) and the anisotropic specular lobe.
float3 pbr_lighting_anisotropic_light(pbr_PreparedSurface s, pbr_AnisotropicFrame frame, pbr_Light light) {
    float3 l = light.dir;
    float nDotL = dot(s.n, l);
    float3 halfSum = l + s.v;
    float LdotH = 0.5 * sqrt(dot(halfSum, halfSum));
    float Fd = pbr_diffuse_Fd(clamp(dot(s.n, s.v), PBR_MIN_NDOTV, 1.0), nDotL, LdotH, s.perceptualRoughness);
    Fd = nDotL > 0.0 ? Fd : 0.0;
    float3 brdf = s.directDiffuseColor * Fd
              + pbr_brdf_anisotropic_specular_f90(s.n, s.v, l, frame.t, frame.b, s.f0, s.f90,
                                                  s.perceptualRoughness, frame.strength);
    return light.color * brdf * (PBR_LIGHT_UNIT_SCALE * clamp(nDotL, 0.0, 1.0));
}

float3 pbr_lighting_anisotropic_dfg(float3 diffuseColor, float3 f0, float3 coatF0, float perceptualRoughness,
                                  float occlusion, float3 n, float3 v, pbr_GI gi, pbr_Anisotropy anisotropy,
                                  float2 dfg) {
    pbr_PreparedSurface s = pbr_prepare_surface_dfg(diffuseColor, f0, coatF0, perceptualRoughness, occlusion,
                                                    n, v, dfg);
    return pbr_lighting_standard_add_environment(
        s, gi.indirect, pbr_lighting_anisotropic_light(s, pbr_anisotropic_frame(n, anisotropy), gi.light));
}

float3 pbr_lighting_anisotropic_f90(float3 diffuseColor, float3 f0, float f90, float3 coatF0, float coatF90,
                                  float perceptualRoughness, float occlusion, float3 n, float3 v, pbr_GI gi,
                                  pbr_Anisotropy anisotropy) {
    pbr_PreparedSurface s = pbr_prepare_surface_f90(diffuseColor, f0, f90, coatF0, coatF90, perceptualRoughness,
                                                    occlusion, n, v);
    return pbr_lighting_standard_add_environment(
        s, gi.indirect, pbr_lighting_anisotropic_light(s, pbr_anisotropic_frame(n, anisotropy), gi.light));
}

float3 pbr_lighting_anisotropic(float3 diffuseColor, float3 f0, float3 coatF0, float perceptualRoughness,
                              float occlusion, float3 n, float3 v, pbr_GI gi, pbr_Anisotropy anisotropy) {
    pbr_PreparedSurface s = pbr_prepare_surface(diffuseColor, f0, coatF0, perceptualRoughness, occlusion, n, v);
    return pbr_lighting_standard_add_environment(
        s, gi.indirect, pbr_lighting_anisotropic_light(s, pbr_anisotropic_frame(n, anisotropy), gi.light));
}
#endif
