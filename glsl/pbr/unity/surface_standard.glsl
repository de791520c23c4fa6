// pbr/unity/surface_standard.glsl: Unity's Standard-shader surface API, by Unity's names.
//
// Provides: struct SurfaceOutputStandard, struct SurfaceOutputStandardSpecular;
//           UnityLight, UnityIndirect, UnityGI (aliases of pbr_Light, pbr_Indirect, pbr_GI);
//           unity_ColorSpaceDielectricSpec;
//           vec4 LightingStandard(SurfaceOutputStandard s, vec3 viewDir, UnityGI gi)
//           vec4 LightingStandardSpecular(SurfaceOutputStandardSpecular s, vec3 viewDir, UnityGI gi)
//           vec3 DiffuseAndSpecularFromMetallic(vec3 albedo, float metallic, out vec3 specColor,
//                                               out float oneMinusReflectivity)
//           vec3 EnergyConservationBetweenDiffuseAndSpecular(vec3 albedo, vec3 specColor,
//                                                            out float oneMinusReflectivity)
//           float OneMinusReflectivityFromMetallic(float metallic)
//           float SpecularStrength(vec3 specular)
//           float SmoothnessToPerceptualRoughness(float smoothness)
//           float PerceptualRoughnessToRoughness(float perceptualRoughness)
//           float PerceptualRoughnessToSmoothness(float perceptualRoughness)
//           vec3 PreMultiplyAlpha(vec3 diffColor, float alpha, float oneMinusReflectivity,
//                                 out float outModifiedAlpha)
//           vec3 UnpackNormal(vec4 packednormal), vec3 UnpackScaleNormal(vec4 packednormal, float bumpScale)
//           The BRDF model's GI step, for the caller that builds UnityGI (Unity's
//           LightingStandard_GI / UnityGlobalIllumination):
//           float pbr_unity_gi_occlusion(float occlusion)  (the factor the GI step applies to
//                 gi.indirect: occlusion in the unity model, 1 in the pbrlab model)
//           vec3 pbr_unity_surface_normal(vec3 normal)  (the normal the lighting reads:
//                 normalize(normal), or normal itself where PBR_UNITY_NORMAL_IS_UNIT is 1)
//           float pbr_unity_environment_lod(float perceptualRoughness, float lodCount)  (the
//                 mip of a prefiltered chain whose level i is filtered for perceptual roughness
//                 i / (lodCount - 1): Unity_GlossyEnvironment's remap in the unity model)
//           and, through pbr/unity/brdf_unity.glsl, Unity's BRDFs and UnityLight/UnityIndirect/UnityGI.
// Include:  "pbr/unity/surface_standard.glsl" (path relative to glsl/). Not part of the
//           umbrella pbr/pbr.glsl: these names are Unity's, and an engine that already
//           defines them skips this one file and calls pbr_lighting_standard directly.
// Config macros read: PBR_ALPHA_MODE (PBR_ALPHA_MODE_OPAQUE default, _CUTOUT, _FADE,
//           _TRANSPARENT: Unity's Rendering Mode; TRANSPARENT premultiplies the diffuse
//           by alpha and keeps the specular, Unity's _ALPHAPREMULTIPLY_ON);
//           PBR_BRDF_MODEL (pbr/shading/dispatch.glsl: PBR_BRDF_MODEL_PBRLAB default,
//           PBR_BRDF_MODEL_UNITY: LightingStandard[Specular] shade with Unity's BRDF of the
//           tier, pbr/unity/brdf_unity.glsl); those of pbr/surface/lighting_standard.glsl
//           and pbr/unity/brdf_unity.glsl; PBR_UNITY_NORMAL_IS_UNIT (0 by default: LightingStandard
//           and the layered lighting normalise s.Normal, as UnityPBSLighting.cginc does, since a
//           surface function may write any length | 1: the caller guarantees a unit s.Normal and
//           the second normalisation is left out; pbrlab's scene programs, which normalise the
//           normal they build from the tangent frame, define it: 8 to 12 RDNA3 instructions a pixel);
//           PBR_UNITY_NORMAL_MAP_ENCODING (how UnpackNormal / UnpackScaleNormal read a normal-map
//           texel: PBR_UNITY_NORMAL_MAP_ENCODING_RGB default, xyz = rgb * 2 - 1, Unity's UNITY_NO_DXT5nm
//           branch, the glTF-style maps of pbrlab's own materials | PBR_UNITY_NORMAL_MAP_ENCODING_DXT5NM:
//           Unity's desktop branch, UnpackNormalmapRGorAG: x = r * a, y = g, scaled, z rebuilt,
//           which reads DXT5nm (1, y, 1, x) and BC5 (x, y, 0, 1) alike; the Unity importer's).
//
// Semantics are Unity's (docs.unity3d.com, "Writing Surface Shaders"; UnityPBSLighting.cginc
// and UnityStandardUtils.cginc of Unity 5-2019). Two models (PBR_BRDF_MODEL):
//  - pbrlab (default): the BRDF is pbrlab's (exact height-correlated Smith, split-sum
//    environment BRDF, energy compensation), and gi.indirect arrives without occlusion:
//    LightingStandard applies s.Occlusion (pbr_unity_gi_occlusion returns 1);
//  - unity: Unity's BRDF1/2/3_Unity_PBS formula for formula, and occlusion belongs to the GI
//    step as in Unity's LightingStandard_GI (pbr_unity_gi_occlusion returns it; the caller
//    multiplies gi.indirect by it), so LightingStandard does not apply it again.
// README.md, "Unity surface API", lists the differences. s.Normal is in world space when
// LightingStandard runs, as in Unity (the caller transforms the tangent-space normal a
// surface function writes).
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_UNITY_SURFACE_STANDARD_GLSL
#define PBR_UNITY_SURFACE_STANDARD_GLSL
#include "pbr/surface/lighting_standard.glsl"
#include "pbr/unity/brdf_unity.glsl"
#include "pbr/ibl/environment_brdf.glsl"
#include "pbr/material/workflow.glsl"
#include "pbr/material/remap.glsl"
#include "pbr/common/math.glsl"

// pbr/shading/dispatch.glsl (included above) defines PBR_BRDF_MODEL's values and default;
// this file's own default is the same.
#ifndef PBR_BRDF_MODEL
// PBR_BRDF_MODEL_PBRLAB as a number (glsl/README.md, one-level preprocessors)
#define PBR_BRDF_MODEL 1
#endif

#define PBR_ALPHA_MODE_OPAQUE 1
#define PBR_ALPHA_MODE_CUTOUT 2
#define PBR_ALPHA_MODE_FADE 3
#define PBR_ALPHA_MODE_TRANSPARENT 4
#ifndef PBR_ALPHA_MODE
// PBR_ALPHA_MODE_OPAQUE as a number (glsl/README.md, one-level preprocessors)
#define PBR_ALPHA_MODE 1
#endif
#if PBR_ALPHA_MODE != PBR_ALPHA_MODE_OPAQUE && PBR_ALPHA_MODE != PBR_ALPHA_MODE_CUTOUT && PBR_ALPHA_MODE != PBR_ALPHA_MODE_FADE && PBR_ALPHA_MODE != PBR_ALPHA_MODE_TRANSPARENT
#error PBR_ALPHA_MODE: unknown value
#endif

#define PBR_UNITY_NORMAL_MAP_ENCODING_RGB 1
#define PBR_UNITY_NORMAL_MAP_ENCODING_DXT5NM 2
#ifndef PBR_UNITY_NORMAL_MAP_ENCODING
// PBR_UNITY_NORMAL_MAP_ENCODING_RGB as a number (glsl/README.md, one-level preprocessors)
#define PBR_UNITY_NORMAL_MAP_ENCODING 1
#endif
#if PBR_UNITY_NORMAL_MAP_ENCODING != PBR_UNITY_NORMAL_MAP_ENCODING_RGB && PBR_UNITY_NORMAL_MAP_ENCODING != PBR_UNITY_NORMAL_MAP_ENCODING_DXT5NM
#error PBR_UNITY_NORMAL_MAP_ENCODING: unknown value
#endif

// Unity: half4(0.04, 0.04, 0.04, 1.0 - 0.04) in linear colour space.
#define unity_ColorSpaceDielectricSpec vec4(vec3(PBR_DIELECTRIC_F0), 1.0 - PBR_DIELECTRIC_F0)

struct SurfaceOutputStandard {
    vec3 Albedo;      // base (diffuse or specular) colour
    vec3 Normal;      // tangent-space normal when written by a surface function
    vec3 Emission;
    float Metallic;   // 0 = dielectric, 1 = metal
    float Smoothness; // 0 = rough, 1 = smooth
    float Occlusion;  // 1 = unoccluded (default)
    float Alpha;
};

struct SurfaceOutputStandardSpecular {
    vec3 Albedo;      // diffuse colour
    vec3 Specular;    // specular colour (F0)
    vec3 Normal;
    vec3 Emission;
    float Smoothness;
    float Occlusion;
    float Alpha;
};

// Unity's UnpackScaleNormal (UnityStandardUtils.cginc's UnpackScaleNormalRGorAG), by
// PBR_UNITY_NORMAL_MAP_ENCODING: RGB (Unity's UNITY_NO_DXT5nm branch) xyz = rgb * 2 - 1, xy
// scaled; DXT5nm (Unity's desktop branch, where the editor stores a normal map as DXT5nm
// (1, y, 1, x) or BC5 (x, y, 0, 1)): x = r * a, y = g, both * 2 - 1 and scaled, z rebuilt as
// sqrt(1 - saturate(x^2 + y^2)), so the scale tilts the rebuilt normal.
vec3 UnpackScaleNormal(vec4 packednormal, float bumpScale) {
#if PBR_UNITY_NORMAL_MAP_ENCODING == PBR_UNITY_NORMAL_MAP_ENCODING_DXT5NM
    vec2 xy = (vec2(packednormal.x * packednormal.w, packednormal.y) * 2.0 - 1.0) * bumpScale;
    return vec3(xy, sqrt(1.0 - clamp(dot(xy, xy), 0.0, 1.0)));
#else
    vec3 n = packednormal.xyz * 2.0 - 1.0;
    n.xy *= bumpScale;
    return n;
#endif
}

// Unity's UnpackNormal (UnityCG.cginc): UnpackScaleNormal at scale 1, in either encoding (RGB:
// rgb * 2 - 1; DXT5nm: UnpackNormalmapRGorAG).
vec3 UnpackNormal(vec4 packednormal) {
    return UnpackScaleNormal(packednormal, 1.0);
}

float SmoothnessToPerceptualRoughness(float smoothness) {
    return pbr_perceptual_roughness_from_smoothness(smoothness);
}

float PerceptualRoughnessToRoughness(float perceptualRoughness) {
    return pbr_alpha_from_perceptual_roughness(perceptualRoughness);
}

float PerceptualRoughnessToSmoothness(float perceptualRoughness) {
    return 1.0 - perceptualRoughness;
}

float SpecularStrength(vec3 specular) {
    return pbr_max3(specular);
}

float OneMinusReflectivityFromMetallic(float metallic) {
    float oneMinusDielectricSpec = unity_ColorSpaceDielectricSpec.a;
    return oneMinusDielectricSpec - metallic * oneMinusDielectricSpec;
}

vec3 DiffuseAndSpecularFromMetallic(vec3 albedo, float metallic, out vec3 specColor,
                                    out float oneMinusReflectivity) {
    specColor = pbr_f0_from_metallic(albedo, metallic);
    oneMinusReflectivity = OneMinusReflectivityFromMetallic(metallic);
    return pbr_diffuse_from_metallic(albedo, metallic);
}

vec3 EnergyConservationBetweenDiffuseAndSpecular(vec3 albedo, vec3 specColor,
                                                 out float oneMinusReflectivity) {
    oneMinusReflectivity = 1.0 - SpecularStrength(specColor);
    return pbr_diffuse_from_specular(albedo, specColor);
}

// Transparent mode: the diffuse part fades with alpha, the specular (reflection) does not;
// the output alpha grows with reflectivity (Unity: UnityStandardUtils.cginc).
vec3 PreMultiplyAlpha(vec3 diffColor, float alpha, float oneMinusReflectivity,
                      out float outModifiedAlpha) {
#if PBR_ALPHA_MODE == PBR_ALPHA_MODE_TRANSPARENT
    diffColor *= alpha;
    outModifiedAlpha = 1.0 - oneMinusReflectivity + alpha * oneMinusReflectivity;
#else
    outModifiedAlpha = alpha;
#endif
    return diffColor;
}

// The GI step's occlusion factor for gi.indirect (see the header): Unity's
// UnityGI_Base / UnityGI_IndirectSpecular multiply both indirect terms by occlusion.
float pbr_unity_gi_occlusion(float occlusion) {
#if PBR_BRDF_MODEL == PBR_BRDF_MODEL_UNITY
    return occlusion;
#else
    return 1.0;
#endif
}

// The mip of the prefiltered environment (level i filtered for perceptual roughness
// i / (lodCount - 1)): pbrlab's tier-clamped roughness, or Unity_GlossyEnvironment's
// remap r (1.7 - 0.7 r), whose mip r' · UNITY_SPECCUBE_LOD_STEPS is the same fraction of
// Unity's chain.
float pbr_unity_environment_lod(float perceptualRoughness, float lodCount) {
#if PBR_BRDF_MODEL == PBR_BRDF_MODEL_UNITY
    return pbr_ibl_lod_from_perceptual_roughness(
        pbr_unity_glossy_environment_perceptual_roughness(perceptualRoughness), lodCount);
#else
    return pbr_ibl_lod_from_perceptual_roughness(pbr_clamp_perceptual_roughness(perceptualRoughness), lodCount);
#endif
}

// LightingStandard's body after the workflow: Unity's premultiplied alpha, then the model's
// BRDF (unity: UNITY_BRDF_PBS of the tier, gi.indirect already occluded by the GI step).
// coatF0: the dielectric coat over the diffuse (pbr_lighting_standard; the unity model,
// whose diffuse is Unity's diffColor, does not read it): unity_ColorSpaceDielectricSpec.rgb
// from LightingStandard, s.Specular from LightingStandardSpecular.
// The surface's normal as the lighting reads it: normalised unless the caller guarantees a unit
// one (PBR_UNITY_NORMAL_IS_UNIT, the file header). A function, not a function-like macro:
// engines' one-level preprocessors (Babylon.js) expand only object-like ones (glsl/README.md).
#ifndef PBR_UNITY_NORMAL_IS_UNIT
#define PBR_UNITY_NORMAL_IS_UNIT 0
#endif
vec3 pbr_unity_surface_normal(vec3 normal) {
#if PBR_UNITY_NORMAL_IS_UNIT != 0
    return normal;
#else
    return normalize(normal);
#endif
}

vec4 pbr_unity_lighting(vec3 diffColor, vec3 specColor, vec3 coatF0, float oneMinusReflectivity,
                        float smoothness, float occlusion, float alpha, vec3 normal,
                        vec3 viewDir, UnityGI gi) {
    float outputAlpha;
    diffColor = PreMultiplyAlpha(diffColor, alpha, oneMinusReflectivity, outputAlpha);
#if PBR_BRDF_MODEL == PBR_BRDF_MODEL_UNITY
    vec3 c = pbr_unity_brdf_pbs(diffColor, specColor, oneMinusReflectivity, smoothness, pbr_unity_surface_normal(normal),
                                viewDir, gi.light.color, gi.light.dir, gi.indirect.diffuse, gi.indirect.specular);
#else
    vec3 c = pbr_lighting_standard(diffColor, specColor, coatF0, SmoothnessToPerceptualRoughness(smoothness),
                                   occlusion, pbr_unity_surface_normal(normal), viewDir, gi);
#endif
    return vec4(c, outputAlpha);
}

vec4 LightingStandard(SurfaceOutputStandard s, vec3 viewDir, UnityGI gi) {
    vec3 specColor;
    float oneMinusReflectivity;
    vec3 diffColor = DiffuseAndSpecularFromMetallic(s.Albedo, s.Metallic, specColor, oneMinusReflectivity);
    return pbr_unity_lighting(diffColor, specColor, unity_ColorSpaceDielectricSpec.rgb, oneMinusReflectivity,
                              s.Smoothness,
                              s.Occlusion, s.Alpha, s.Normal, viewDir, gi);
}

vec4 LightingStandardSpecular(SurfaceOutputStandardSpecular s, vec3 viewDir, UnityGI gi) {
    float oneMinusReflectivity;
    vec3 diffColor = EnergyConservationBetweenDiffuseAndSpecular(s.Albedo, s.Specular, oneMinusReflectivity);
    return pbr_unity_lighting(diffColor, s.Specular, s.Specular, oneMinusReflectivity, s.Smoothness,
                              s.Occlusion, s.Alpha, s.Normal, viewDir, gi);
}
#endif
