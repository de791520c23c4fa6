// pbr/unity/surface_layers.glsl: the layers of current engines' materials beside Unity's
// SurfaceOutputStandard, by the names Unity's URP and HDRP give them.
//
// Provides: struct SurfaceOutputStandardLayers
//           vec4 LightingStandardLayers(vec4 base, SurfaceOutputStandardLayers s, vec3 normal,
//                                       vec3 viewDir, UnityGI gi, vec3 sheenIndirect,
//                                       vec3 coatIndirectSpecular, float occlusion)
//           vec4 LightingStandardLayersBase(SurfaceOutputStandard s,
//                                           SurfaceOutputStandardLayers layers, vec3 viewDir,
//                                           UnityGI gi)
//           vec4 LightingStandardSpecularLayersBase(SurfaceOutputStandardSpecular s,
//                                                   SurfaceOutputStandardLayers layers,
//                                                   vec3 viewDir, UnityGI gi)
//           vec4 LightingStandardLayersBaseTransmission(SurfaceOutputStandard s,
//                                                       SurfaceOutputStandardLayers layers,
//                                                       vec3 viewDir, UnityGI gi,
//                                                       vec3 transmittedIndirect)
//           vec4 LightingStandardSpecularLayersBaseTransmission(
//                    SurfaceOutputStandardSpecular s, SurfaceOutputStandardLayers layers,
//                    vec3 viewDir, UnityGI gi, vec3 transmittedIndirect)
//           vec3 TransmittedDirection(vec3 normal, vec3 viewDir,
//                                     SurfaceOutputStandardLayers layers)
//           vec3 AnisotropicReflectionNormal(vec3 normal, vec3 viewDir,
//                                            SurfaceOutputStandardLayers layers,
//                                            float smoothness)
//           (these in the pbrlab model only: PBR_BRDF_MODEL_PBRLAB)
// Include:  "pbr/unity/surface_layers.glsl" (path relative to glsl/; it includes
//           pbr/unity/surface_standard.glsl).
// Config macros read: PBR_LAYERS_SHEEN, PBR_LAYERS_CLEARCOAT, PBR_LAYERS_ANISOTROPY,
//           PBR_LAYERS_IRIDESCENCE, PBR_LAYERS_TRANSMISSION (1 by default), PBR_LAYERS_SPECULAR_F90
//           (0 by default: F90 follows F0), PBR_LAYERS_DIELECTRIC_SPECULAR (0 by default: the
//           metallic workflow's dielectric F0 is 0.04; a caller that knows a layer is absent
//           defines it 0 and LightingStandardLayers / LightingStandard[Specular]LayersBase
//           skip that layer's code); PBR_BRDF_MODEL (the LayersBase functions exist in the
//           pbrlab model only); those of pbr/surface/lighting_clearcoat.glsl,
//           pbr/surface/lighting_sheen.glsl, pbr/surface/lighting_anisotropy.glsl,
//           pbr/surface/lighting_iridescence.glsl and pbr/surface/lighting_transmission.glsl;
//           PBR_UNITY_NORMAL_IS_UNIT (pbr/unity/surface_standard.glsl).
//
// Unity's built-in pipeline has no layers; its Standard struct stays as Unity defines it.
// The fields here are named as URP's SurfaceData names them (clearCoatMask,
// clearCoatSmoothness: URP 12+, "Clear Coat" of the Complex Lit shader), capitalised as
// Unity's surface structs are. ClearCoatNormal is pbrlab's (URP coats along the geometric
// normal): tangent space as a surface function writes it, (0, 0, 1) being the interpolated
// normal, not the base's normal map (KHR_materials_clearcoat: "If clearcoatNormalTexture is
// not given, no normal mapping is applied to the clear coat layer"); the caller transforms it
// to world space before lighting, as it does s.Normal. LightingStandardLayers coats a
// base LightingStandard[Specular] result: base.rgb as pbr_lighting_clearcoat reads it (the
// emission added before, it lies under the coat), alpha kept. coatIndirectSpecular: the
// prefiltered environment along reflect(-viewDir, ClearCoatNormal) at the coat's roughness.
// The sheen (KHR_materials_sheen) lies on the base, under the coat, as the specification
// and the Khronos Sample Renderer order them: LightingStandardLayers applies
// pbr_lighting_sheen to base.rgb, then coats the result. SheenColor (linear, 0 = no sheen:
// KHR's sheenColor) and SheenSmoothness (1 - KHR's sheenRoughness, Unity's smoothness
// vocabulary as ClearCoatSmoothness) are pbrlab's names: Unity has no sheen layer beside
// its Standard model (HDRP's Fabric material, whose whole specular lobe is a sheen, calls
// the colour "Specular Color" and its roughness "Smoothness": SurfaceData.specularColor,
// perceptualSmoothness). normal: the base's world-space normal (the sheen's, per KHR);
// sheenIndirect: the prefiltered environment along reflect(-viewDir, normal) at the sheen's
// roughness.
// The anisotropy (KHR_materials_anisotropy) and the iridescence (KHR_materials_iridescence)
// are not layers over the base but change the base itself: its specular lobe stretched, its
// F0 turned into a thin film's. LightingStandard[Specular]LayersBase stand in for
// LightingStandard[Specular] (the same workflow maths, Unity's premultiplied alpha; the F0
// and the coat's F0 through pbr_iridescent_f0, pbr/surface/lighting_iridescence.glsl; then
// pbr_lighting_anisotropic, pbr/surface/lighting_anisotropy.glsl, or pbr_lighting_standard)
// and their result is what LightingStandardLayers layers. With both layers off (mask 0,
// strength 0) they return LightingStandard[Specular]'s value (the anisotropic lobe at
// strength 0: to float32 rounding at the HIGH tier). Anisotropy is the strength in [0, 1] (0: the isotropic lobe; KHR's
// anisotropyStrength x texture.b; HDRP's Lit SurfaceData.anisotropy, whose sign pbrlab does not
// use: KHR's strength is never negative). AnisotropyDirection: the direction the highlight's
// roughness grows along, tangent space as a surface function writes it ((1, 0, 0): the mesh's
// tangent; KHR's anisotropyTexture.rg x 2 - 1 rotated by anisotropyRotation); the caller
// transforms it to world space before lighting, as ClearCoatNormal. The environment's
// prefiltered radiance in gi.indirect.specular is read along reflect(-viewDir, n') with n' =
// AnisotropicReflectionNormal. IridescenceMask (HDRP's Lit name; KHR's iridescenceFactor x
// texture.r, 0 = no film), IridescenceIor (the film's IOR) and IridescenceThickness (nm,
// pbr_iridescence_thickness; HDRP's 0..1 remap is not used). Unity's BRDFs
// (PBR_BRDF_MODEL_UNITY) have neither an anisotropic lobe nor an F0 to replace: there these
// three functions are not defined.
// SpecularF90 (read only where PBR_LAYERS_SPECULAR_F90 is 1): the dielectric's reflectance at
// grazing incidence, KHR_materials_specular's specularFactor x specularTexture.a (the
// extension's README, "Implementation": dielectric_f90 = specular); the F0 the surface writes
// (Specular, or the metallic workflow's) must not exceed it in any channel, as the extension's
// min(..., 1) x specular never does. A metallic surface blends it towards 1, F90 =
// mix(SpecularF90, 1, Metallic) (pbr_f90_from_metallic), as the extension's F90 = lerp(dielectric_f90, 1, metallic).
// Neither URP nor HDRP names a user-facing F90 (HDRP derives its fresnel90 from F0 inside the
// BSDF), so the name is pbrlab's, after what it sets. With the layer off, F90 follows F0
// (pbr_f90_from_f0) and none of this is compiled. The F90 reaches every term of the base that
// reads one: the isotropic or the anisotropic lobe, the split sum, the diffuse's coupling, the
// film (pbr_iridescent_f0_f90: the film over F0 / F90, scaled by F90) and the transmission's
// weight (pbr_lighting_transmission_f90); the sheen and the coat over the base have their own
// Fresnel (the sheen none, the coat F0 0.04 and F90 1), as the Sample Renderer's layers do.
// DielectricSpecular (read only where PBR_LAYERS_DIELECTRIC_SPECULAR is 1; the metallic workflow,
// LightingStandardLayersBase[Transmission]): the F0 of the dielectric share of a metallic surface,
// linear RGB, KHR_materials_specular's dielectric_f0 = min(((ior - 1) / (ior + 1))² ·
// specularColor, 1) · specular (KHR_materials_ior's ior); F0 = mix(DielectricSpecular, Albedo,
// Metallic), the diffuse Albedo (1 - max(DielectricSpecular)) (1 - Metallic), and the coat over
// the diffuse (coatF0) is DielectricSpecular (pbr_unity_dielectric_f0; pbr/material/workflow.glsl).
// Its default 0.04 (unity_ColorSpaceDielectricSpec) gives LightingStandard's values; each channel
// must not exceed SpecularF90 where both are written. Unity names the specular workflow's F0
// Specular; the dielectric share's is pbrlab's name after it. With the layer off none of this is
// compiled.
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_UNITY_SURFACE_LAYERS_GLSL
#define PBR_UNITY_SURFACE_LAYERS_GLSL
#include "pbr/unity/surface_standard.glsl"
#include "pbr/surface/lighting_clearcoat.glsl"
#include "pbr/surface/lighting_sheen.glsl"
#include "pbr/surface/lighting_anisotropy.glsl"
#include "pbr/surface/lighting_iridescence.glsl"
#include "pbr/surface/lighting_transmission.glsl"
#include "pbr/material/remap.glsl"

struct SurfaceOutputStandardLayers {
    float ClearCoatMask;        // 0 = no coat .. 1 (the harness's default: 0)
    float ClearCoatSmoothness;  // 0 = rough .. 1 = smooth (default 1: glTF's roughness 0)
    vec3 ClearCoatNormal;       // tangent space (default (0, 0, 1): the interpolated normal)
    vec3 SheenColor;            // linear (default 0: no sheen)
    float SheenSmoothness;      // 0 = rough .. 1 = smooth (default 1: glTF's sheenRoughness 0)
    float Anisotropy;           // 0 = isotropic .. 1 (default 0)
    vec3 AnisotropyDirection;   // tangent space (default (1, 0, 0): the tangent)
    float IridescenceMask;      // 0 = no film .. 1 (default 0)
    float IridescenceIor;       // the film's IOR (default 1.3: KHR's)
    float IridescenceThickness; // nanometres (default 400: KHR's maximum)
    float Transmission;         // 0 = none .. 1 (default 0)
    float Thickness;            // scene units (default 0: thin-walled)
    vec3 AttenuationColor;      // linear (default 1: no attenuation)
    float AttenuationDistance;  // > 0 (default +Inf: no attenuation)
    float TransmissionIor;      // the volume's IOR (default 1.5: KHR_materials_ior's)
    float SpecularF90;          // grazing reflectance, >= every channel of F0 (default 1: KHR's)
    vec3 DielectricSpecular;    // the metallic workflow's dielectric F0, linear (default 0.04)
};

#ifndef PBR_LAYERS_SHEEN
#define PBR_LAYERS_SHEEN 1
#endif
#ifndef PBR_LAYERS_CLEARCOAT
#define PBR_LAYERS_CLEARCOAT 1
#endif
#ifndef PBR_LAYERS_ANISOTROPY
#define PBR_LAYERS_ANISOTROPY 1
#endif
#ifndef PBR_LAYERS_IRIDESCENCE
#define PBR_LAYERS_IRIDESCENCE 1
#endif
#ifndef PBR_LAYERS_TRANSMISSION
#define PBR_LAYERS_TRANSMISSION 1
#endif
#ifndef PBR_LAYERS_SPECULAR_F90
#define PBR_LAYERS_SPECULAR_F90 0
#endif
#ifndef PBR_LAYERS_DIELECTRIC_SPECULAR
#define PBR_LAYERS_DIELECTRIC_SPECULAR 0
#endif
// pbr/shading/dispatch.glsl (included above) defines PBR_BRDF_MODEL's values and default;
// this file's own default is the same.
#ifndef PBR_BRDF_MODEL
// PBR_BRDF_MODEL_PBRLAB as a number (glsl/README.md, one-level preprocessors)
#define PBR_BRDF_MODEL 1
#endif

vec4 LightingStandardLayers(vec4 base, SurfaceOutputStandardLayers s, vec3 normal, vec3 viewDir, UnityGI gi,
                            vec3 sheenIndirect, vec3 coatIndirectSpecular, float occlusion) {
    vec3 c = base.rgb;
#if PBR_LAYERS_SHEEN != 0
    pbr_Sheen sheen;
    sheen.color = s.SheenColor;
    sheen.perceptualRoughness = pbr_perceptual_roughness_from_smoothness(s.SheenSmoothness);
    c = pbr_lighting_sheen(c, sheen, normal, viewDir, gi, sheenIndirect, occlusion);
#endif
#if PBR_LAYERS_CLEARCOAT != 0
    pbr_ClearCoat coat;
    coat.mask = s.ClearCoatMask;
    coat.perceptualRoughness = pbr_perceptual_roughness_from_smoothness(s.ClearCoatSmoothness);
    coat.normal = normalize(s.ClearCoatNormal);
    c = pbr_lighting_clearcoat(c, coat, viewDir, gi, coatIndirectSpecular, occlusion);
#endif
    return vec4(c, base.a);
}

#if PBR_BRDF_MODEL == PBR_BRDF_MODEL_PBRLAB
// The base's terms that read F90, each with the surface's own F90 where PBR_LAYERS_SPECULAR_F90
// (f90 for f0, coatF90 for coatF0: the _f90 forms) and F90 from F0 elsewhere (the plain
// forms, so a program without the layer compiles as it did before it existed). These hold the
// file's only PBR_LAYERS_SPECULAR_F90 choices (and the film's, in pbr_unity_lighting_layers_base);
// each exists only where its layer is compiled in.
#if PBR_LAYERS_ANISOTROPY != 0
vec3 pbr_layers_lighting_anisotropic(vec3 diffColor, vec3 specColor, float f90, vec3 coatF0, float coatF90,
                                     float perceptualRoughness, float occlusion, vec3 n, vec3 viewDir, UnityGI gi,
                                     pbr_Anisotropy anisotropy) {
#if PBR_LAYERS_SPECULAR_F90 != 0
    return pbr_lighting_anisotropic_f90(diffColor, specColor, f90, coatF0, coatF90, perceptualRoughness, occlusion,
                                        n, viewDir, gi, anisotropy);
#else
    return pbr_lighting_anisotropic(diffColor, specColor, coatF0, perceptualRoughness, occlusion, n, viewDir, gi,
                                    anisotropy);
#endif
}
#endif

vec3 pbr_layers_lighting_standard(vec3 diffColor, vec3 specColor, float f90, vec3 coatF0, float coatF90,
                                  float perceptualRoughness, float occlusion, vec3 n, vec3 viewDir, UnityGI gi) {
#if PBR_LAYERS_SPECULAR_F90 != 0
    return pbr_lighting_standard_f90(diffColor, specColor, f90, coatF0, coatF90, perceptualRoughness, occlusion, n,
                                     viewDir, gi);
#else
    return pbr_lighting_standard(diffColor, specColor, coatF0, perceptualRoughness, occlusion, n, viewDir, gi);
#endif
}

#if PBR_LAYERS_TRANSMISSION != 0
vec3 pbr_layers_lighting_transmission(vec3 diffColor, vec3 coatF0, float coatF90, float perceptualRoughness,
                                      float occlusion, vec3 n, vec3 viewDir, UnityGI gi, vec3 transmittedIndirect,
                                      pbr_Transmission tr) {
#if PBR_LAYERS_SPECULAR_F90 != 0
    return pbr_lighting_transmission_f90(diffColor, coatF0, coatF90, perceptualRoughness, occlusion, n, viewDir, gi,
                                         transmittedIndirect, tr);
#else
    return pbr_lighting_transmission(diffColor, coatF0, perceptualRoughness, occlusion, n, viewDir, gi,
                                     transmittedIndirect, tr);
#endif
}
#endif

// pbr_unity_lighting (pbr/unity/surface_standard.glsl) with the layers that change the base:
// Unity's premultiplied alpha, the film's F0 (PBR_LAYERS_IRIDESCENCE), the anisotropic lobe
// (PBR_LAYERS_ANISOTROPY, AnisotropyDirection in world space) or the isotropic one, and the
// transmission in place of part of the diffuse (PBR_LAYERS_TRANSMISSION); each with the
// surface's F90 (the last two parameters: f90 for specColor, coatF90 for coatF0) where
// PBR_LAYERS_SPECULAR_F90 (the pbr_layers_* dispatch above).
vec4 pbr_unity_lighting_layers_base(vec3 diffColor, vec3 specColor, vec3 coatF0, float oneMinusReflectivity,
                                    float smoothness, float occlusion, float alpha, vec3 normal, vec3 viewDir,
                                    UnityGI gi, SurfaceOutputStandardLayers layers, vec3 transmittedIndirect,
                                    float f90, float coatF90) {
    float outputAlpha;
    diffColor = PreMultiplyAlpha(diffColor, alpha, oneMinusReflectivity, outputAlpha);
    vec3 n = pbr_unity_surface_normal(normal);
    float perceptualRoughness = SmoothnessToPerceptualRoughness(smoothness);
#if PBR_LAYERS_IRIDESCENCE != 0
    pbr_Iridescence film;
    film.factor = layers.IridescenceMask;
    film.ior = layers.IridescenceIor;
    film.thicknessNm = layers.IridescenceThickness;
    float NdotV = max(dot(n, viewDir), PBR_MIN_NDOTV);
#if PBR_LAYERS_SPECULAR_F90 != 0
    pbr_IridescentF0 filmF0 = pbr_iridescent_f0_f90_with_coat(specColor, f90, coatF0, coatF90, NdotV, film);
#else
    pbr_IridescentF0 filmF0 = pbr_iridescent_f0_with_coat(specColor, coatF0, NdotV, film);
#endif
    specColor = filmF0.f0;
    diffColor = pbr_iridescent_diffuse_color(diffColor, coatF0, filmF0.coatF0);
    coatF0 = filmF0.coatF0;
#endif
#if PBR_LAYERS_TRANSMISSION != 0
    vec3 transmissionDiffColor = diffColor;  // the whole diffuse colour: the transmission's weight
    diffColor = pbr_transmission_diffuse_color(diffColor, layers.Transmission);
#endif
#if PBR_LAYERS_ANISOTROPY != 0
    pbr_Anisotropy anisotropy;
    anisotropy.strength = layers.Anisotropy;
    anisotropy.direction = layers.AnisotropyDirection;
    vec3 c = pbr_layers_lighting_anisotropic(diffColor, specColor, f90, coatF0, coatF90, perceptualRoughness,
                                             occlusion, n, viewDir, gi, anisotropy);
#else
    vec3 c = pbr_layers_lighting_standard(diffColor, specColor, f90, coatF0, coatF90, perceptualRoughness, occlusion,
                                          n, viewDir, gi);
#endif
#if PBR_LAYERS_TRANSMISSION != 0
    pbr_Transmission tr;
    tr.factor = layers.Transmission;
    tr.thickness = layers.Thickness;
    tr.attenuationColor = layers.AttenuationColor;
    tr.attenuationDistance = layers.AttenuationDistance;
    tr.ior = layers.TransmissionIor;
    c += pbr_layers_lighting_transmission(transmissionDiffColor, coatF0, coatF90, perceptualRoughness, occlusion, n,
                                          viewDir, gi, transmittedIndirect, tr);
#endif
    return vec4(c, outputAlpha);
}

// The F0 of the metallic workflow's dielectric share, the coat over its diffuse: Unity's 0.04
// (unity_ColorSpaceDielectricSpec) or, where PBR_LAYERS_DIELECTRIC_SPECULAR, the surface's
// DielectricSpecular. The layer's one preprocessor conditional.
vec3 pbr_unity_dielectric_f0(SurfaceOutputStandardLayers layers) {
#if PBR_LAYERS_DIELECTRIC_SPECULAR != 0
    return layers.DielectricSpecular;
#else
    return unity_ColorSpaceDielectricSpec.rgb;
#endif
}

// Unity's OneMinusReflectivityFromMetallic with the dielectric's F0 for its 0.04:
// (1 - max(dielectricF0)) - metallic (1 - max(dielectricF0)), in Unity's form (PreMultiplyAlpha
// reads it).
float pbr_unity_one_minus_reflectivity_from_metallic(float metallic, vec3 dielectricF0) {
    float oneMinusDielectricSpec = 1.0 - pbr_max3(dielectricF0);
    return oneMinusDielectricSpec - metallic * oneMinusDielectricSpec;
}

// LightingStandardLayersBase[Transmission]: the metallic workflow's setup, Unity's
// DiffuseAndSpecularFromMetallic in its order (F0, oneMinusReflectivity, diffuse) with the
// dielectric's F0 (pbr/material/workflow.glsl's _dielectric forms; at 0.04 the same values and,
// measured, the same RDNA3 programs), then the base.
vec4 LightingStandardLayersBase(SurfaceOutputStandard s, SurfaceOutputStandardLayers layers, vec3 viewDir,
                                UnityGI gi) {
    vec3 coatF0 = pbr_unity_dielectric_f0(layers);
    vec3 specColor = pbr_f0_from_metallic_dielectric(s.Albedo, s.Metallic, coatF0);
    float oneMinusReflectivity = pbr_unity_one_minus_reflectivity_from_metallic(s.Metallic, coatF0);
    vec3 diffColor = pbr_diffuse_from_metallic_dielectric(s.Albedo, s.Metallic, coatF0);
    return pbr_unity_lighting_layers_base(diffColor, specColor, coatF0,
                                          oneMinusReflectivity, s.Smoothness, s.Occlusion, s.Alpha, s.Normal,
                                          viewDir, gi, layers, vec3(0.0, 0.0, 0.0),
                                          pbr_f90_from_metallic(layers.SpecularF90, s.Metallic), layers.SpecularF90);
}

vec4 LightingStandardLayersBaseTransmission(SurfaceOutputStandard s, SurfaceOutputStandardLayers layers,
                                            vec3 viewDir, UnityGI gi, vec3 transmittedIndirect) {
    vec3 coatF0 = pbr_unity_dielectric_f0(layers);
    vec3 specColor = pbr_f0_from_metallic_dielectric(s.Albedo, s.Metallic, coatF0);
    float oneMinusReflectivity = pbr_unity_one_minus_reflectivity_from_metallic(s.Metallic, coatF0);
    vec3 diffColor = pbr_diffuse_from_metallic_dielectric(s.Albedo, s.Metallic, coatF0);
    return pbr_unity_lighting_layers_base(diffColor, specColor, coatF0,
                                          oneMinusReflectivity, s.Smoothness, s.Occlusion, s.Alpha, s.Normal,
                                          viewDir, gi, layers, transmittedIndirect,
                                          pbr_f90_from_metallic(layers.SpecularF90, s.Metallic), layers.SpecularF90);
}

vec4 LightingStandardSpecularLayersBase(SurfaceOutputStandardSpecular s, SurfaceOutputStandardLayers layers,
                                        vec3 viewDir, UnityGI gi) {
    float oneMinusReflectivity;
    vec3 diffColor = EnergyConservationBetweenDiffuseAndSpecular(s.Albedo, s.Specular, oneMinusReflectivity);
    return pbr_unity_lighting_layers_base(diffColor, s.Specular, s.Specular, oneMinusReflectivity, s.Smoothness,
                                          s.Occlusion, s.Alpha, s.Normal, viewDir, gi, layers,
                                          vec3(0.0, 0.0, 0.0), layers.SpecularF90, layers.SpecularF90);
}

vec4 LightingStandardSpecularLayersBaseTransmission(SurfaceOutputStandardSpecular s,
                                                    SurfaceOutputStandardLayers layers, vec3 viewDir, UnityGI gi,
                                                    vec3 transmittedIndirect) {
    float oneMinusReflectivity;
    vec3 diffColor = EnergyConservationBetweenDiffuseAndSpecular(s.Albedo, s.Specular, oneMinusReflectivity);
    return pbr_unity_lighting_layers_base(diffColor, s.Specular, s.Specular, oneMinusReflectivity, s.Smoothness,
                                          s.Occlusion, s.Alpha, s.Normal, viewDir, gi, layers,
                                          transmittedIndirect, layers.SpecularF90, layers.SpecularF90);
}

// The direction the environment is seen along through the surface (world): straight through
// a thin wall, refracted into a volume (pbr_transmitted_direction).
vec3 TransmittedDirection(vec3 normal, vec3 viewDir, SurfaceOutputStandardLayers layers) {
    pbr_Transmission tr;
    tr.factor = layers.Transmission;
    tr.thickness = layers.Thickness;
    tr.attenuationColor = layers.AttenuationColor;
    tr.attenuationDistance = layers.AttenuationDistance;
    tr.ior = layers.TransmissionIor;
    return pbr_transmitted_direction(pbr_unity_surface_normal(normal), viewDir, tr);
}

// The normal (world) whose mirror direction the anisotropic base reads its prefiltered
// environment along: pbr_anisotropic_reflection_normal at the base's roughness.
vec3 AnisotropicReflectionNormal(vec3 normal, vec3 viewDir, SurfaceOutputStandardLayers layers,
                                 float smoothness) {
    pbr_Anisotropy anisotropy;
    anisotropy.strength = layers.Anisotropy;
    anisotropy.direction = layers.AnisotropyDirection;
    return pbr_anisotropic_reflection_normal(pbr_unity_surface_normal(normal), viewDir, anisotropy,
                                             SmoothnessToPerceptualRoughness(smoothness));
}
#endif
#endif
