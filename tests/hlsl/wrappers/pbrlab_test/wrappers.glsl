// pbrlab_test/wrappers.glsl: what the evaluator (one expression over float and vector
// inputs) needs to call the library functions that take arrays, structs or out parameters.
//
// Provides: test_light, test_indirect, test_gi, test_surface, test_surface_specular (struct builders), test_sh9_irradiance,
//           test_DiffuseAndSpecularFromMetallic[_specColor],
//           test_EnergyConservationBetweenDiffuseAndSpecular, test_PreMultiplyAlpha.
// Include:  "pbrlab_test/wrappers.glsl" (path relative to tests/hlsl/wrappers/)
// Config macros read: those of the library.
//
// Test code, written once in GLSL: tests/hlsl ports it to HLSL with the library's own
// generator (pbrlab.port_hlsl), so the wrappers are as mechanical as the ports they test.
#ifndef PBRLAB_TEST_WRAPPERS_GLSL
#define PBRLAB_TEST_WRAPPERS_GLSL

#include "pbr/pbr.glsl"
#include "pbr/unity/surface_standard.glsl"

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

#endif // PBRLAB_TEST_WRAPPERS_GLSL
