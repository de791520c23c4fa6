// pbr/unity/lighting_legacy.hlsl: Unity's legacy surface output and its two built-in
// lighting models, Lambert and BlinnPhong (Lighting.cginc), by Unity's names.
//
// Provides: struct SurfaceOutput { Albedo, Normal, Emission, Specular, Gloss, Alpha };
//           vec4 UnityLambertLight(SurfaceOutput s, UnityLight light)
//           vec4 LightingLambert(SurfaceOutput s, UnityGI gi)
//           vec4 UnityBlinnPhongLight(SurfaceOutput s, vec3 viewDir, UnityLight light)
//           vec4 LightingBlinnPhong(SurfaceOutput s, vec3 viewDir, UnityGI gi)
//           (their _GI functions are in pbr/unity/global_illumination.hlsl)
// Include:  "pbr/unity/lighting_legacy.hlsl" (path relative to hlsl_ports/).
// Config macros read: UNITY_LIGHT_FUNCTION_APPLY_INDIRECT (Unity's: defined when the pass
//           samples ambient light; then the lighting function adds Albedo * indirect diffuse);
//           PBR_UNITY_SPEC_COLOR (BlinnPhong's specular colour, Unity's _SpecColor global:
//           unity_compat/shader_variables.hlsl, included first, defines it as _SpecColor;
//           default Unity's legacy Properties default (0.5, 0.5, 0.5, 1)).
//
// Formulas are Unity's (Lighting.cginc, Unity 5-2019), with Unity's light units: no 1/pi in
// the diffuse, light.color the light's colour times intensity. That equals pbrlab's
// convention (lights "pi times too bright", README): a white Lambert surface under an
// intensity-1 light along its normal gives 1 in both. The specular is not energy-normalised:
// pow(NdotH, Specular * 128) * Gloss * _SpecColor, as Unity. Float64 references written from
// Lighting.cginc: harness/pbrlab/maths/reference/unity_lighting.py.
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_UNITY_LIGHTING_LEGACY_HLSL
#define PBR_UNITY_LIGHTING_LEGACY_HLSL
#include "pbr/common/shim.hlsl"  // generated from glsl/pbr/unity/lighting_legacy.glsl by harness/pbrlab/gpu/port_hlsl.py: edit the GLSL, then regenerate
#include "pbr/unity/surface_standard.hlsl"

#ifndef PBR_UNITY_SPEC_COLOR
#define PBR_UNITY_SPEC_COLOR float4(0.5, 0.5, 0.5, 1.0)
#endif

// Unity's BlinnPhong exponent scale: Specular in [0, 1] maps to a power in [0, 128].
#define PBR_UNITY_BLINN_PHONG_POWER_SCALE 128.0

struct SurfaceOutput {
    float3 Albedo;
    float3 Normal;     // tangent space when written by a surface function, world space here
    float3 Emission;
    float Specular;  // exponent / 128
    float Gloss;     // specular intensity
    float Alpha;
};

float4 UnityLambertLight(SurfaceOutput s, UnityLight light) {
    float diff = max(0.0, dot(s.Normal, light.dir));
    float4 c;
    c.rgb = s.Albedo * light.color * diff;
    c.a = s.Alpha;
    return c;
}

float4 LightingLambert(SurfaceOutput s, UnityGI gi) {
    float4 c = UnityLambertLight(s, gi.light);
#ifdef UNITY_LIGHT_FUNCTION_APPLY_INDIRECT
    c.rgb += s.Albedo * gi.indirect.diffuse;
#endif
    return c;
}

float4 UnityBlinnPhongLight(SurfaceOutput s, float3 viewDir, UnityLight light) {
    float3 h = normalize(light.dir + viewDir);
    float diff = max(0.0, dot(s.Normal, light.dir));
    float nh = max(0.0, dot(s.Normal, h));
    float spec = pow(nh, s.Specular * PBR_UNITY_BLINN_PHONG_POWER_SCALE) * s.Gloss;
    float4 c;
    c.rgb = s.Albedo * light.color * diff + light.color * PBR_UNITY_SPEC_COLOR.rgb * spec;
    c.a = s.Alpha;
    return c;
}

float4 LightingBlinnPhong(SurfaceOutput s, float3 viewDir, UnityGI gi) {
    float4 c = UnityBlinnPhongLight(s, viewDir, gi.light);
#ifdef UNITY_LIGHT_FUNCTION_APPLY_INDIRECT
    c.rgb += s.Albedo * gi.indirect.diffuse;
#endif
    return c;
}
#endif
