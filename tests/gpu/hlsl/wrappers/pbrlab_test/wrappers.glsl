// pbrlab_test/wrappers.glsl: what the evaluator (one expression over float and vector
// inputs) needs to call the library functions that take arrays, structs or out parameters.
//
// Provides: test_gi, test_surface, test_surface_specular, test_light, test_indirect,
//           test_surface_legacy, test_gi_input, test_glossy_environment, test_clearcoat,
//           test_surface_layers, test_prepared_surface, test_anisotropic_frame_of,
//           test_prepared_transmission, test_thin_film (struct builders),
//           test_prepare_surface[_dfg], test_anisotropic_frame, test_prepare_transmission_dfg_*,
//           test_thin_film_fields, test_iridescent_f0[_f90]_with_coat
//           (struct results, their fields summed),
//           test_sh9_irradiance,
//           test_UnityGlossyEnvironmentSetup, test_UnityGlobalIllumination[_gloss][_indirect],
//           test_Lighting*_GI (the pbr/unity/ functions with struct results or inout GI),
//           test_DiffuseAndSpecularFromMetallic[_specColor],
//           test_EnergyConservationBetweenDiffuseAndSpecular, test_PreMultiplyAlpha,
//           test_pbr_brdf_standard_terms (its out parameters as one vec3).
// Include:  "pbrlab_test/wrappers.glsl" (path relative to tests/gpu/hlsl/wrappers/)
// Config macros read: those of the library.
//
// Test code, written once in GLSL: tests/gpu/hlsl ports it to HLSL with the library's own
// generator (pbrlab.gpu.port_hlsl), so the wrappers are as mechanical as the ports they test.
#ifndef PBRLAB_TEST_WRAPPERS_GLSL
#define PBRLAB_TEST_WRAPPERS_GLSL

#include "pbr/pbr.glsl"
#include "pbr/unity/surface_standard.glsl"
#include "pbr/unity/unity_cg.glsl"
#include "pbr/unity/global_illumination.glsl"
#include "pbr/unity/surface_layers.glsl"

pbr_Light test_light(vec3 lightColor, vec3 lightDir) {
    pbr_Light light;
    light.color = lightColor;
    light.dir = lightDir;
    return light;
}

pbr_Indirect test_indirect(vec3 indirectDiffuse, vec3 indirectSpecular) {
    pbr_Indirect indirect;
    indirect.diffuse = indirectDiffuse;
    indirect.specular = indirectSpecular;
    return indirect;
}

pbr_ClearCoat test_clearcoat(float mask, float perceptualRoughness, vec3 normal) {
    pbr_ClearCoat coat;
    coat.mask = mask;
    coat.perceptualRoughness = perceptualRoughness;
    coat.normal = normal;
    return coat;
}

SurfaceOutputStandardLayers test_surface_layers(float clearCoatMask, float clearCoatSmoothness,
                                                vec3 clearCoatNormal, vec3 sheenColor, float sheenSmoothness,
                                                float anisotropy, vec3 anisotropyDirection, float iridescenceMask,
                                                float iridescenceIor, float iridescenceThickness) {
    SurfaceOutputStandardLayers s;
    s.ClearCoatMask = clearCoatMask;
    s.ClearCoatSmoothness = clearCoatSmoothness;
    s.ClearCoatNormal = clearCoatNormal;
    s.SheenColor = sheenColor;
    s.SheenSmoothness = sheenSmoothness;
    s.Anisotropy = anisotropy;
    s.AnisotropyDirection = anisotropyDirection;
    s.IridescenceMask = iridescenceMask;
    s.IridescenceIor = iridescenceIor;
    s.IridescenceThickness = iridescenceThickness;
    s.Transmission = 0.0;  // no transmission (test_transmission exercises it)
    s.Thickness = 0.0;
    s.AttenuationColor = vec3(1.0, 1.0, 1.0);
    s.AttenuationDistance = 1.0;
    s.TransmissionIor = 1.5;
    s.SpecularF90 = 1.0;   // read only where PBR_LAYERS_SPECULAR_F90 is 1
    s.DielectricSpecular = vec3(0.04, 0.04, 0.04);  // read only where PBR_LAYERS_DIELECTRIC_SPECULAR is 1
    return s;
}

vec3 test_pbr_brdf_standard_terms(vec3 n, vec3 v, vec3 l, float perceptualRoughness) {
    float Fd;
    float DV;
    float LdotH;
    pbr_brdf_standard_terms(n, v, l, perceptualRoughness, Fd, DV, LdotH);
    return vec3(Fd, DV, LdotH);
}

pbr_Transmission test_transmission(float factor, float thickness, vec3 attenuationColor,
                                   float attenuationDistance, float ior) {
    pbr_Transmission tr;
    tr.factor = factor;
    tr.thickness = thickness;
    tr.attenuationColor = attenuationColor;
    tr.attenuationDistance = attenuationDistance;
    tr.ior = ior;
    return tr;
}

pbr_Iridescence test_iridescence(float factor, float ior, float thicknessNm) {
    pbr_Iridescence film;
    film.factor = factor;
    film.ior = ior;
    film.thicknessNm = thicknessNm;
    return film;
}

pbr_ThinFilm test_thin_film(float outsideIor, float filmIor, float cosTheta1, float thicknessNm) {
    return pbr_thin_film(outsideIor, filmIor, cosTheta1, thicknessNm);
}

vec3 test_thin_film_fields(float outsideIor, float filmIor, float cosTheta1, float thicknessNm) {
    pbr_ThinFilm f = pbr_thin_film(outsideIor, filmIor, cosTheta1, thicknessNm);
    return vec3(f.n1, f.n2, f.c1) + 2.0 * vec3(f.cos2Sq, f.c2, f.R12) + 3.0 * vec3(f.T121, f.thicknessNm, 0.0)
         + 5.0 * f.xyz1 + 7.0 * f.S2;
}

vec3 test_iridescent_f0_with_coat(vec3 f0, vec3 coatF0, float NdotV, pbr_Iridescence film) {
    pbr_IridescentF0 r = pbr_iridescent_f0_with_coat(f0, coatF0, NdotV, film);
    return r.f0 + 2.0 * r.coatF0;
}

vec3 test_iridescent_f0_f90_with_coat(vec3 f0, float f90, vec3 coatF0, float coatF90, float NdotV,
                                      pbr_Iridescence film) {
    pbr_IridescentF0 r = pbr_iridescent_f0_f90_with_coat(f0, f90, coatF0, coatF90, NdotV, film);
    return r.f0 + 2.0 * r.coatF0;
}

pbr_Anisotropy test_anisotropy(float strength, vec3 direction) {
    pbr_Anisotropy anisotropy;
    anisotropy.strength = strength;
    anisotropy.direction = direction;
    return anisotropy;
}

// The prepared surface (pbr_prepare_surface_dfg) as a struct argument, and its fields summed
// with distinct weights as a result (a struct is not an evaluator output).
pbr_PreparedSurface test_prepared_surface(vec3 diffuseColor, vec3 f0, vec3 coatF0, float perceptualRoughness,
                                          float occlusion, vec3 n, vec3 v, vec2 dfg) {
    return pbr_prepare_surface_dfg(diffuseColor, f0, coatF0, perceptualRoughness, occlusion, n, v, dfg);
}

vec3 test_prepared_fields(pbr_PreparedSurface s) {
    return s.n + 2.0 * s.v + 3.0 * s.f0 + vec3(s.perceptualRoughness, s.occlusion, s.specularOcclusion)
         + 5.0 * s.directDiffuseColor + 7.0 * s.indirectDiffuseColor + 11.0 * s.indirectSpecularAlbedo
         + vec3(13.0 * s.f90);
}

vec3 test_prepare_surface_dfg(vec3 diffuseColor, vec3 f0, vec3 coatF0, float perceptualRoughness,
                              float occlusion, vec3 n, vec3 v, vec2 dfg) {
    return test_prepared_fields(pbr_prepare_surface_dfg(diffuseColor, f0, coatF0, perceptualRoughness, occlusion,
                                                        n, v, dfg));
}

vec3 test_prepare_surface(vec3 diffuseColor, vec3 f0, vec3 coatF0, float perceptualRoughness, float occlusion,
                          vec3 n, vec3 v) {
    return test_prepared_fields(pbr_prepare_surface(diffuseColor, f0, coatF0, perceptualRoughness, occlusion, n, v));
}

vec3 test_prepare_surface_f90_dfg(vec3 diffuseColor, vec3 f0, float f90, vec3 coatF0, float coatF90,
                                  float perceptualRoughness, float occlusion, vec3 n, vec3 v, vec2 dfg) {
    return test_prepared_fields(pbr_prepare_surface_f90_dfg(diffuseColor, f0, f90, coatF0, coatF90,
                                                            perceptualRoughness, occlusion, n, v, dfg));
}

vec3 test_prepare_surface_f90(vec3 diffuseColor, vec3 f0, float f90, vec3 coatF0, float coatF90,
                              float perceptualRoughness, float occlusion, vec3 n, vec3 v) {
    return test_prepared_fields(pbr_prepare_surface_f90(diffuseColor, f0, f90, coatF0, coatF90, perceptualRoughness,
                                                        occlusion, n, v));
}

vec3 test_pbr_brdf_anisotropic_terms(vec3 n, vec3 v, vec3 l, vec3 a, vec3 b, float perceptualRoughness,
                                     float strength) {
    float DV;
    float LdotH;
    pbr_brdf_anisotropic_terms(n, v, l, a, b, perceptualRoughness, strength, DV, LdotH);
    return vec3(DV, LdotH, 0.0);
}

pbr_AnisotropicFrame test_anisotropic_frame_of(vec3 n, float strength, vec3 direction) {
    return pbr_anisotropic_frame(n, test_anisotropy(strength, direction));
}

vec3 test_anisotropic_frame(vec3 n, float strength, vec3 direction) {
    pbr_AnisotropicFrame frame = test_anisotropic_frame_of(n, strength, direction);
    return frame.t + 2.0 * frame.b + vec3(frame.strength);
}

pbr_PreparedTransmission test_prepared_transmission(vec3 diffuseColor, vec3 coatF0, float perceptualRoughness,
                                                    float occlusion, vec3 n, vec3 v, pbr_Transmission tr,
                                                    vec2 dfg) {
    return pbr_prepare_transmission_dfg(diffuseColor, coatF0, perceptualRoughness, occlusion, n, v, tr, dfg);
}

// Its fields one group at a time (a weighted sum of all of them rounds differently where the
// two compilers contract it differently).
vec3 test_prepare_transmission_dfg_surface(vec3 diffuseColor, vec3 coatF0, float perceptualRoughness,
                                           float occlusion, vec3 n, vec3 v, pbr_Transmission tr, vec2 dfg) {
    return test_prepared_fields(test_prepared_transmission(diffuseColor, coatF0, perceptualRoughness, occlusion,
                                                           n, v, tr, dfg).s);
}

vec3 test_prepare_transmission_dfg_rho(vec3 diffuseColor, vec3 coatF0, float perceptualRoughness,
                                       float occlusion, vec3 n, vec3 v, pbr_Transmission tr, vec2 dfg) {
    return test_prepared_transmission(diffuseColor, coatF0, perceptualRoughness, occlusion, n, v, tr, dfg).rho;
}

vec3 test_prepare_transmission_dfg_weight(vec3 diffuseColor, vec3 coatF0, float perceptualRoughness,
                                          float occlusion, vec3 n, vec3 v, pbr_Transmission tr, vec2 dfg) {
    pbr_PreparedTransmission t = test_prepared_transmission(diffuseColor, coatF0, perceptualRoughness, occlusion,
                                                            n, v, tr, dfg);
    return t.weight + vec3(0.0, 0.0, t.volume ? t.ior : -t.ior);
}

pbr_Sheen test_sheen(vec3 color, float perceptualRoughness) {
    pbr_Sheen sheen;
    sheen.color = color;
    sheen.perceptualRoughness = perceptualRoughness;
    return sheen;
}

pbr_GI test_gi(vec3 lightColor, vec3 lightDir, vec3 indirectDiffuse, vec3 indirectSpecular) {
    pbr_GI gi;
    gi.light.color = lightColor;
    gi.light.dir = lightDir;
    gi.indirect.diffuse = indirectDiffuse;
    gi.indirect.specular = indirectSpecular;
    return gi;
}

SurfaceOutputStandard test_surface(vec3 albedo, vec3 normal, vec3 emission, float metallic,
                                   float smoothness, float occlusion, float alpha) {
    SurfaceOutputStandard s;
    s.Albedo = albedo;
    s.Normal = normal;
    s.Emission = emission;
    s.Metallic = metallic;
    s.Smoothness = smoothness;
    s.Occlusion = occlusion;
    s.Alpha = alpha;
    return s;
}

SurfaceOutputStandardSpecular test_surface_specular(vec3 albedo, vec3 specular, vec3 normal,
                                                    vec3 emission, float smoothness,
                                                    float occlusion, float alpha) {
    SurfaceOutputStandardSpecular s;
    s.Albedo = albedo;
    s.Specular = specular;
    s.Normal = normal;
    s.Emission = emission;
    s.Smoothness = smoothness;
    s.Occlusion = occlusion;
    s.Alpha = alpha;
    return s;
}

// Nine coefficients from two colours (every slot different, signs mixed).
vec3 test_sh9_irradiance(vec3 a, vec3 b, vec3 n) {
    vec3 sh[9];
    sh[0] = a;
    sh[1] = b - a;
    sh[2] = a * b;
    sh[3] = 0.5 * b;
    sh[4] = a.zxy;
    sh[5] = -b.yzx;
    sh[6] = a - b;
    sh[7] = 0.25 * (a + b);
    sh[8] = a.yxz * b.zyx;
    return pbr_sh9_irradiance(sh, n);
}

vec4 test_DiffuseAndSpecularFromMetallic(vec3 albedo, float metallic) {
    vec3 specColor;
    float oneMinusReflectivity;
    vec3 diffuse = DiffuseAndSpecularFromMetallic(albedo, metallic, specColor, oneMinusReflectivity);
    return vec4(diffuse, oneMinusReflectivity);
}

vec3 test_DiffuseAndSpecularFromMetallic_specColor(vec3 albedo, float metallic) {
    vec3 specColor;
    float oneMinusReflectivity;
    vec3 diffuse = DiffuseAndSpecularFromMetallic(albedo, metallic, specColor, oneMinusReflectivity);
    return specColor;
}

vec4 test_EnergyConservationBetweenDiffuseAndSpecular(vec3 albedo, vec3 specColor) {
    float oneMinusReflectivity;
    vec3 diffuse = EnergyConservationBetweenDiffuseAndSpecular(albedo, specColor, oneMinusReflectivity);
    return vec4(diffuse, oneMinusReflectivity);
}

vec4 test_PreMultiplyAlpha(vec3 diffColor, float alpha, float oneMinusReflectivity) {
    float outModifiedAlpha;
    vec3 c = PreMultiplyAlpha(diffColor, alpha, oneMinusReflectivity, outModifiedAlpha);
    return vec4(c, outModifiedAlpha);
}

SurfaceOutput test_surface_legacy(vec3 albedo, vec3 normal, vec3 emission, float specular,
                                  float gloss, float alpha) {
    SurfaceOutput s;
    s.Albedo = albedo;
    s.Normal = normal;
    s.Emission = emission;
    s.Specular = specular;
    s.Gloss = gloss;
    s.Alpha = alpha;
    return s;
}

UnityGIInput test_gi_input(vec3 lightColor, vec3 lightDir, vec3 worldPos, vec3 viewDir, float atten,
                           vec3 ambient) {
    UnityGIInput data;
    data.light.color = lightColor;
    data.light.dir = lightDir;
    data.worldPos = worldPos;
    data.worldViewDir = viewDir;
    data.atten = atten;
    data.ambient = ambient;
    return data;
}

Unity_GlossyEnvironmentData test_glossy_environment(float roughness, vec3 dir) {
    Unity_GlossyEnvironmentData g;
    g.roughness = roughness;
    g.reflUVW = dir;
    return g;
}

vec4 test_UnityGlossyEnvironmentSetup(float smoothness, vec3 viewDir, vec3 normal, vec3 fresnel0) {
    Unity_GlossyEnvironmentData g = UnityGlossyEnvironmentSetup(smoothness, viewDir, normal, fresnel0);
    return vec4(g.reflUVW, g.roughness);
}

vec4 test_gi_light(UnityGI gi) {
    return vec4(gi.light.color, gi.light.dir.x + gi.light.dir.y + gi.light.dir.z);
}

vec4 test_gi_indirect(UnityGI gi) {
    return vec4(gi.indirect.diffuse, gi.indirect.specular.x + gi.indirect.specular.y + gi.indirect.specular.z);
}

vec4 test_UnityGlobalIllumination(UnityGIInput data, float occlusion, vec3 normal) {
    return test_gi_light(UnityGlobalIllumination(data, occlusion, normal));
}

vec4 test_UnityGlobalIllumination_indirect(UnityGIInput data, float occlusion, vec3 normal) {
    return test_gi_indirect(UnityGlobalIllumination(data, occlusion, normal));
}

vec4 test_UnityGlobalIllumination_gloss(UnityGIInput data, float occlusion, vec3 normal,
                                        Unity_GlossyEnvironmentData glossIn) {
    return test_gi_indirect(UnityGlobalIllumination(data, occlusion, normal, glossIn));
}

vec4 test_LightingStandard_GI(SurfaceOutputStandard s, UnityGIInput data) {
    UnityGI gi = test_gi(vec3(1.0, 1.0, 1.0), vec3(0.0, 0.0, 1.0), vec3(1.0, 1.0, 1.0), vec3(1.0, 1.0, 1.0));
    LightingStandard_GI(s, data, gi);
    return test_gi_light(gi) + test_gi_indirect(gi);
}

vec4 test_LightingStandardSpecular_GI(SurfaceOutputStandardSpecular s, UnityGIInput data) {
    UnityGI gi = test_gi(vec3(1.0, 1.0, 1.0), vec3(0.0, 0.0, 1.0), vec3(1.0, 1.0, 1.0), vec3(1.0, 1.0, 1.0));
    LightingStandardSpecular_GI(s, data, gi);
    return test_gi_light(gi) + test_gi_indirect(gi);
}

vec4 test_LightingLambert_GI(SurfaceOutput s, UnityGIInput data) {
    UnityGI gi = test_gi(vec3(1.0, 1.0, 1.0), vec3(0.0, 0.0, 1.0), vec3(1.0, 1.0, 1.0), vec3(1.0, 1.0, 1.0));
    LightingLambert_GI(s, data, gi);
    return test_gi_light(gi) + test_gi_indirect(gi);
}

vec4 test_LightingBlinnPhong_GI(SurfaceOutput s, UnityGIInput data) {
    UnityGI gi = test_gi(vec3(1.0, 1.0, 1.0), vec3(0.0, 0.0, 1.0), vec3(1.0, 1.0, 1.0), vec3(1.0, 1.0, 1.0));
    LightingBlinnPhong_GI(s, data, gi);
    return test_gi_light(gi) + test_gi_indirect(gi);
}

// The transmission prepared with an explicit F90 (pbr_prepare_transmission_f90_dfg) and from a
// prepared surface (pbr_prepare_transmission_from_surface), their fields a group at a time.
vec3 test_prepare_transmission_f90_dfg_surface(vec3 diffuseColor, vec3 coatF0, float coatF90,
                                               float perceptualRoughness, float occlusion, vec3 n, vec3 v,
                                               pbr_Transmission tr, vec2 dfg) {
    return test_prepared_fields(pbr_prepare_transmission_f90_dfg(diffuseColor, coatF0, coatF90, perceptualRoughness,
                                                                 occlusion, n, v, tr, dfg).s);
}

vec3 test_prepare_transmission_f90_dfg_rho(vec3 diffuseColor, vec3 coatF0, float coatF90, float perceptualRoughness,
                                           float occlusion, vec3 n, vec3 v, pbr_Transmission tr, vec2 dfg) {
    return pbr_prepare_transmission_f90_dfg(diffuseColor, coatF0, coatF90, perceptualRoughness, occlusion, n, v, tr,
                                            dfg).rho;
}

vec3 test_prepare_transmission_f90_dfg_weight(vec3 diffuseColor, vec3 coatF0, float coatF90,
                                              float perceptualRoughness, float occlusion, vec3 n, vec3 v,
                                              pbr_Transmission tr, vec2 dfg) {
    pbr_PreparedTransmission t = pbr_prepare_transmission_f90_dfg(diffuseColor, coatF0, coatF90, perceptualRoughness,
                                                                  occlusion, n, v, tr, dfg);
    return t.weight + vec3(0.0, 0.0, t.volume ? t.ior : -t.ior);
}

vec3 test_prepare_transmission_from_surface_rho(pbr_PreparedSurface s, vec3 diffuseColor, vec3 coatF0,
                                                pbr_Transmission tr) {
    return pbr_prepare_transmission_from_surface(s, diffuseColor, coatF0, tr).rho;
}

vec3 test_prepare_transmission_from_surface_weight(pbr_PreparedSurface s, vec3 diffuseColor, vec3 coatF0,
                                                   pbr_Transmission tr) {
    pbr_PreparedTransmission t = pbr_prepare_transmission_from_surface(s, diffuseColor, coatF0, tr);
    return t.weight + vec3(0.0, 0.0, t.volume ? t.ior : -t.ior);
}

#endif // PBRLAB_TEST_WRAPPERS_GLSL
