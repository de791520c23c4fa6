// pbr/unity/global_illumination.glsl: Unity's global-illumination inputs and the _GI half of
// its lighting models (UnityGlobalIllumination.cginc, UnityPBSLighting.cginc, Lighting.cginc).
//
// Provides: struct UnityGIInput { light, worldPos, worldViewDir, atten, ambient, probeHDR[2] };
//           struct Unity_GlossyEnvironmentData { roughness (perceptual), reflUVW };
//           Unity_GlossyEnvironmentData UnityGlossyEnvironmentSetup(float smoothness,
//               vec3 worldViewDir, vec3 normal, vec3 fresnel0)
//           vec3 ShadeSH9(vec4 normal)                       ambient irradiance / pi
//           vec3 Unity_GlossyEnvironment(Unity_GlossyEnvironmentData glossIn)
//           UnityGI UnityGlobalIllumination(UnityGIInput data, float occlusion, vec3 normalWorld)
//           UnityGI UnityGlobalIllumination(UnityGIInput data, float occlusion, vec3 normalWorld,
//                                           Unity_GlossyEnvironmentData glossIn)
//           void LightingStandard_GI(SurfaceOutputStandard s, UnityGIInput data, inout UnityGI gi)
//           void LightingStandardSpecular_GI(SurfaceOutputStandardSpecular s, UnityGIInput data,
//                                            inout UnityGI gi)
//           void LightingLambert_GI(SurfaceOutput s, UnityGIInput data, inout UnityGI gi)
//           void LightingBlinnPhong_GI(SurfaceOutput s, UnityGIInput data, inout UnityGI gi)
// Include:  "pbr/unity/global_illumination.glsl" (path relative to glsl/).
// Config macros read: PBR_UNITY_SH_IRRADIANCE(n) (the caller's ambient lookup: irradiance / pi
//           around world normal n, what ShadeSH9 returns; default black) and
//           PBR_UNITY_GLOSSY_ENVIRONMENT(dir, perceptualRoughness) (the caller's prefiltered
//           environment radiance along dir; default black): the library samples no
//           textures, as with PBR_DFG_LUT_LOOKUP.
//
// Differences from Unity, stated: no lightmaps, light probes' box projection or second
// reflection probe (UnityGIInput keeps the fields a surface shader reads); the environment
// is sampled at the caller's roughness-to-mip mapping (the harness uses
// pbr_unity_environment_lod: Unity's perceptualRoughness * (1.7 - 0.7 * perceptualRoughness)
// under PBR_BRDF_MODEL_UNITY, pbrlab's otherwise); and LightingStandard*_GI pass
// pbr_unity_gi_occlusion(s.Occlusion): s.Occlusion under the unity model, as Unity, and 1
// under pbrlab's, whose LightingStandard applies s.Occlusion itself (README, "Unity surface
// API"). Lambert and BlinnPhong apply occlusion 1, as Unity.
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_UNITY_GLOBAL_ILLUMINATION_GLSL
#define PBR_UNITY_GLOBAL_ILLUMINATION_GLSL
#include "pbr/unity/surface_standard.glsl"
#include "pbr/unity/lighting_legacy.glsl"

#ifndef PBR_UNITY_SH_IRRADIANCE
#define PBR_UNITY_SH_IRRADIANCE(n) vec3(0.0, 0.0, 0.0)
#endif
#ifndef PBR_UNITY_GLOSSY_ENVIRONMENT
#define PBR_UNITY_GLOSSY_ENVIRONMENT(dir, perceptualRoughness) vec3(0.0, 0.0, 0.0)
#endif

struct UnityGIInput {
    UnityLight light;   // the pass's light, colour without atten
    vec3 worldPos;
    vec3 worldViewDir;  // unit, towards the camera
    float atten;        // the light's shadow and falloff factor
    vec3 ambient;       // vertex ambient (added to ShadeSH9)
    vec4 probeHDR[2];   // the reflection probes' HDR decode (unity_SpecCube0_HDR, ..1_HDR):
                        // UnityGlobalIllumination.cginc's member, which shaders fill; unread
                        // here (the environment is the caller's PBR_UNITY_GLOSSY_ENVIRONMENT)
};

struct Unity_GlossyEnvironmentData {
    float roughness;    // perceptual roughness, as in Unity
    vec3 reflUVW;
};

Unity_GlossyEnvironmentData UnityGlossyEnvironmentSetup(float smoothness, vec3 worldViewDir,
                                                        vec3 normal, vec3 fresnel0) {
    Unity_GlossyEnvironmentData g;
    g.roughness = SmoothnessToPerceptualRoughness(smoothness);
    g.reflUVW = reflect(-worldViewDir, normal);
    return g;
}

vec3 ShadeSH9(vec4 normal) {
    return PBR_UNITY_SH_IRRADIANCE(normal.xyz);
}

vec3 Unity_GlossyEnvironment(Unity_GlossyEnvironmentData glossIn) {
    return PBR_UNITY_GLOSSY_ENVIRONMENT(glossIn.reflUVW, glossIn.roughness);
}

UnityGI UnityGlobalIllumination(UnityGIInput data, float occlusion, vec3 normalWorld) {
    UnityGI gi;
    gi.light = data.light;
    gi.light.color *= data.atten;
    gi.indirect.diffuse = (data.ambient + ShadeSH9(vec4(normalWorld, 1.0))) * occlusion;
    gi.indirect.specular = vec3(0.0, 0.0, 0.0);
    return gi;
}

UnityGI UnityGlobalIllumination(UnityGIInput data, float occlusion, vec3 normalWorld,
                                Unity_GlossyEnvironmentData glossIn) {
    UnityGI gi = UnityGlobalIllumination(data, occlusion, normalWorld);
    gi.indirect.specular = Unity_GlossyEnvironment(glossIn) * occlusion;
    return gi;
}

void LightingStandard_GI(SurfaceOutputStandard s, UnityGIInput data, inout UnityGI gi) {
    Unity_GlossyEnvironmentData g = UnityGlossyEnvironmentSetup(s.Smoothness, data.worldViewDir,
                                                                s.Normal, vec3(0.0, 0.0, 0.0));
    gi = UnityGlobalIllumination(data, pbr_unity_gi_occlusion(s.Occlusion), s.Normal, g);
}

void LightingStandardSpecular_GI(SurfaceOutputStandardSpecular s, UnityGIInput data, inout UnityGI gi) {
    Unity_GlossyEnvironmentData g = UnityGlossyEnvironmentSetup(s.Smoothness, data.worldViewDir,
                                                                s.Normal, s.Specular);
    gi = UnityGlobalIllumination(data, pbr_unity_gi_occlusion(s.Occlusion), s.Normal, g);
}

void LightingLambert_GI(SurfaceOutput s, UnityGIInput data, inout UnityGI gi) {
    gi = UnityGlobalIllumination(data, 1.0, s.Normal);
}

void LightingBlinnPhong_GI(SurfaceOutput s, UnityGIInput data, inout UnityGI gi) {
    gi = UnityGlobalIllumination(data, 1.0, s.Normal);
}
#endif
