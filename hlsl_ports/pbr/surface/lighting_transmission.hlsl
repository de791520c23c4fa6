// pbr/surface/lighting_transmission.hlsl: KHR_materials_transmission and KHR_materials_volume
// on the base: the light the diffuse would have scattered passes through the surface instead.
//
// Provides: struct pbr_Transmission
//           vec3 pbr_transmission_diffuse_color(vec3 diffuseColor, float transmission)
//           vec3 pbr_transmitted_direction(vec3 n, vec3 v, pbr_Transmission tr)
//           vec3 pbr_lighting_transmission(vec3 diffuseColor, vec3 coatF0,
//                                          float perceptualRoughness, float occlusion, vec3 n,
//                                          vec3 v, pbr_GI gi, vec3 transmittedIndirect,
//                                          pbr_Transmission tr)
//           struct pbr_PreparedTransmission
//           pbr_PreparedTransmission pbr_prepare_transmission_dfg(vec3 diffuseColor, vec3 coatF0,
//                                          float perceptualRoughness, float occlusion, vec3 n,
//                                          vec3 v, pbr_Transmission tr, vec2 dfg)
//           vec3 pbr_transmission_direct(pbr_PreparedTransmission t, pbr_Light light)
//           vec3 pbr_lighting_transmission_light(pbr_PreparedTransmission t, pbr_Light light)
//           vec3 pbr_lighting_transmission_environment(pbr_PreparedTransmission t,
//                                                      vec3 transmittedIndirect)
//           vec3 pbr_lighting_transmission_f90(vec3 diffuseColor, vec3 coatF0, float coatF90,
//                                              float perceptualRoughness, float occlusion, vec3 n,
//                                              vec3 v, pbr_GI gi, vec3 transmittedIndirect,
//                                              pbr_Transmission tr)  (an explicit F90)
//           pbr_PreparedTransmission pbr_prepare_transmission_f90_dfg(vec3 diffuseColor,
//                                          vec3 coatF0, float coatF90, float perceptualRoughness,
//                                          float occlusion, vec3 n, vec3 v, pbr_Transmission tr,
//                                          vec2 dfg)
//           pbr_PreparedTransmission pbr_prepare_transmission_from_surface(pbr_PreparedSurface s,
//                                          vec3 diffuseColor, vec3 coatF0, pbr_Transmission tr)
//           vec3 pbr_lighting_transmission_prepared(pbr_PreparedTransmission t, pbr_Light light,
//                                                   vec3 transmittedIndirect)
// Include:  "pbr/surface/lighting_transmission.hlsl" (path relative to hlsl_ports/)
// Config macros read: those of pbr/surface/lighting_standard.hlsl.
//
// KHR_materials_transmission ("Transmission BTDF"): dielectric_brdf =
// fresnel_mix(ior, mix(diffuse_brdf, specular_btdf · baseColor, transmission), specular_brdf):
// the transmission takes the diffuse's place, under the same coat. pbrlab keeps its diffuse
// coupling (pbr/shading/energy_conservation.hlsl: the diffuse gets rho (1 − E_coat), Fdez-Agüera
// 2019 §4) and splits that weight:
//   the diffuse lobe                 diffuseColor (1 − transmission)   (the caller passes
//                                    pbr_transmission_diffuse_color to its base lighting)
//   the transmission (this function) transmission · A · (direct + indirect), with
//     A = pbr_volume_attenuation(thickness, attenuationColor, attenuationDistance)
//         (KHR_materials_volume, Beer-Lambert over the thickness; 1 for a thin wall)
//     direct, a light behind the surface (n.l < 0):
//       thin wall (thickness 0): pbr_transmission_thin_punctual tinted by rho (1 − E_coat),
//         E_coat the coat's single-scattering albedo (the direct diffuse's weight,
//         pbr_specular_albedo_bound)
//       volume (thickness > 0): pbr_transmission_punctual (Walter et al. 2007, eta = ior:
//         the light inside the volume, the view in air) tinted by rho; Walter's BTDF carries
//         its own 1 − F(v.h) (pbr_T_Dielectric), so the coat's 1 − E is not applied twice
//     indirect: transmittedIndirect (the caller's radiance seen along
//       pbr_transmitted_direction at the base's roughness: pbrlab's harness passes its copy
//       of the scene behind the surface over the prefiltered environment,
//       harness/pbrlab/templates/transmission_scene.inc) · rho (1 − E_coat) · occlusion,
//       E_coat with the environment's compensation: the indirect diffuse's weight
//       (pbr_indirect_diffuse_color), so a white, fully transmissive dielectric in a white
//       furnace returns E_spec + (1 − E_spec) = 1 (tests/render/test_white_furnace.py).
// pbr_transmitted_direction: straight through (−v) for a thin wall (two parallel interfaces:
// the light leaves unbent); the refracted direction (pbr_refraction_direction, Snell) into a
// volume. Decided: the roughness is the base's (the Sample Renderer scales it by
// clamp(2 ior − 2, 0, 1) for its framebuffer's mip: not done here); the refracted ray is not
// bent again where it leaves the volume.
// An explicit F90 (KHR_materials_specular: the _f90 forms, coatF90 the F90 of coatF0): the
// extension's fresnel_mix(spec_weight, base = mix(diffuse, specular_btdf, transmission),
// specular_brdf) weights the transmission as the diffuse, by 1 − spec_weight · F, so both
// E_coat above become coatF0 A + coatF90 B (the diffuse's coupling with the same F90; the
// Sample Renderer: mix(f_diffuse, f_transmission, transmission) under its
// getIBLGGXFresnel(..., specularWeight)). The volume's Walter BTDF keeps its own 1 − F at
// the volume's IOR (the Sample Renderer's getPunctualRadianceTransmission also reads F90 = 1
// there, not the specular weight): a lobe reflecting F90 · F <= F leaves at most 1 − F to
// transmit, so energy holds.
// transmission = 0 adds 0 · (finite terms) and the caller's diffuse colour is multiplied by 1:
// the base's value bit for bit.
// Once per pixel (issue 25, as pbr/surface/lighting_standard.hlsl): pbr_prepare_transmission_dfg
// (the surface prepared for the transmission's diffuse colour: its coupled colours; rho; the
// weight transmission · A) before the loop over lights, pbr_lighting_transmission_light per
// light, pbr_lighting_transmission_environment once; pbr_lighting_transmission (one light and
// the environment) is that composition, in the order it always summed.
// Python twin: harness/pbrlab/maths/reference/surface.py lighting_transmission.
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_SURFACE_LIGHTING_TRANSMISSION_HLSL
#define PBR_SURFACE_LIGHTING_TRANSMISSION_HLSL
#include "pbr/common/shim.hlsl"  // generated from glsl/pbr/surface/lighting_transmission.glsl by harness/pbrlab/gpu/port_hlsl.py: edit the GLSL, then regenerate
#include "pbr/common/math.hlsl"
#include "pbr/shading/transmission.hlsl"
#include "pbr/shading/energy_conservation.hlsl"
#include "pbr/surface/lighting_standard.hlsl"

struct pbr_Transmission {
    float factor;               // 0 = none .. 1 (glTF transmissionFactor x texture.r)
    float thickness;            // scene units, 0 = thin-walled (glTF thicknessFactor x texture.g x scale)
    float3 attenuationColor;      // linear, the colour white light becomes after attenuationDistance
    float attenuationDistance;  // > 0, +Inf: no attenuation (the extension's default)
    float ior;                  // the volume's index of refraction (>= 1)
};

// The diffuse colour left to the diffuse lobe: (1 − transmission) of it.
float3 pbr_transmission_diffuse_color(float3 diffuseColor, float transmission) {
    return diffuseColor * (1.0 - pbr_saturate(transmission));
}

float3 pbr_transmitted_direction(float3 n, float3 v, pbr_Transmission tr) {
    return tr.thickness > 0.0 ? pbr_refraction_direction(n, v, tr.ior) : -v;
}

// The per-pixel part of the transmission.
struct pbr_PreparedTransmission {
    pbr_PreparedSurface s;  // pbr_prepare_surface_dfg for the transmission's diffuse colour (f0 = coatF0)
    float3 rho;               // the diffuse albedo under the coat (the volume's tint)
    float3 weight;            // saturate(transmission) · A (A = 1 for a thin wall)
    bool volume;            // thickness > 0
    float ior;              // the volume's
};

// The transmission's part of the preparation, given the surface prepared for its diffuse
// colour (f0 = coatF0).
pbr_PreparedTransmission pbr_prepare_transmission_from_surface(pbr_PreparedSurface s, float3 diffuseColor,
                                                               float3 coatF0, pbr_Transmission tr) {
    pbr_PreparedTransmission t;
    t.s = s;
    t.rho = pbr_diffuse_albedo_from_diffuse_color(diffuseColor, coatF0);
    t.volume = tr.thickness > 0.0;
    float3 attenuation = t.volume ? pbr_volume_attenuation(tr.thickness, tr.attenuationColor, tr.attenuationDistance)
                                : ((float3)(1.0));
    t.weight = pbr_saturate(tr.factor) * attenuation;
    t.ior = tr.ior;
    return t;
}

pbr_PreparedTransmission pbr_prepare_transmission_dfg(float3 diffuseColor, float3 coatF0, float perceptualRoughness,
                                                      float occlusion, float3 n, float3 v, pbr_Transmission tr,
                                                      float2 dfg) {
    return pbr_prepare_transmission_from_surface(
        pbr_prepare_surface_dfg(diffuseColor, coatF0, coatF0, perceptualRoughness, occlusion, n, v, dfg),
        diffuseColor, coatF0, tr);
}

// With an explicit F90 of the coat's F0 (coatF90: KHR_materials_specular's specularFactor):
// the weights rho (1 - E_coat) take E_coat = coatF0 A + coatF90 B (see the header).
pbr_PreparedTransmission pbr_prepare_transmission_f90_dfg(float3 diffuseColor, float3 coatF0, float coatF90,
                                                          float perceptualRoughness, float occlusion, float3 n,
                                                          float3 v, pbr_Transmission tr, float2 dfg) {
    return pbr_prepare_transmission_from_surface(
        pbr_prepare_surface_f90_dfg(diffuseColor, coatF0, coatF90, coatF0, coatF90, perceptualRoughness, occlusion,
                                    n, v, dfg),
        diffuseColor, coatF0, tr);
}

// One light behind the surface, before the weight (see the header).
float3 pbr_transmission_direct(pbr_PreparedTransmission t, pbr_Light light) {
    float3 direct;
    if (t.volume) {
        direct = pbr_transmission_punctual(t.s.n, t.s.v, light.dir, light.color, t.rho, t.s.perceptualRoughness,
                                           t.ior);
    } else {
        direct = pbr_transmission_thin_punctual(t.s.n, t.s.v, light.dir, light.color, t.s.directDiffuseColor,
                                                t.s.perceptualRoughness);
    }
    return direct;
}

float3 pbr_lighting_transmission_light(pbr_PreparedTransmission t, pbr_Light light) {
    return t.weight * pbr_transmission_direct(t, light);
}

float3 pbr_lighting_transmission_environment(pbr_PreparedTransmission t, float3 transmittedIndirect) {
    return t.weight * (t.s.indirectDiffuseColor * transmittedIndirect * t.s.occlusion);
}

// One light and the environment, prepared: the sum pbr_lighting_transmission always made.
float3 pbr_lighting_transmission_prepared(pbr_PreparedTransmission t, pbr_Light light, float3 transmittedIndirect) {
    return t.weight * (pbr_transmission_direct(t, light)
                       + t.s.indirectDiffuseColor * transmittedIndirect * t.s.occlusion);
}

float3 pbr_lighting_transmission(float3 diffuseColor, float3 coatF0, float perceptualRoughness, float occlusion,
                               float3 n, float3 v, pbr_GI gi, float3 transmittedIndirect, pbr_Transmission tr) {
    float roughness = pbr_clamp_perceptual_roughness(perceptualRoughness);
    float2 dfg = pbr_env_brdf(max(dot(n, v), PBR_MIN_NDOTV), roughness);
    return pbr_lighting_transmission_prepared(
        pbr_prepare_transmission_dfg(diffuseColor, coatF0, roughness, occlusion, n, v, tr, dfg), gi.light,
        transmittedIndirect);
}

float3 pbr_lighting_transmission_f90(float3 diffuseColor, float3 coatF0, float coatF90, float perceptualRoughness,
                                   float occlusion, float3 n, float3 v, pbr_GI gi, float3 transmittedIndirect,
                                   pbr_Transmission tr) {
    float roughness = pbr_clamp_perceptual_roughness(perceptualRoughness);
    float2 dfg = pbr_env_brdf(max(dot(n, v), PBR_MIN_NDOTV), roughness);
    return pbr_lighting_transmission_prepared(
        pbr_prepare_transmission_f90_dfg(diffuseColor, coatF0, coatF90, roughness, occlusion, n, v, tr, dfg),
        gi.light, transmittedIndirect);
}
#endif
