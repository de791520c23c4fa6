// unity_compat/shader_variables.glsl: the built-in globals a Unity surface shader reads
// (UnityShaderVariables.cginc, UnityLightingCommon.cginc), and the UnityCG.cginc helpers
// that read them.
//
// THIS FILE DECLARES UNIFORMS, as Unity's UnityShaderVariables.cginc does: it is the one
// file that does (the caller sets them; the pbrlab harness sets every one), and it lives
// outside pbr/ (whose files declare no resources) in unity_compat/, the opt-in Unity room.
//
// Provides: uniforms _Time (t/20, t, 2t, 3t), _SinTime (sin t/8, t/4, t/2, t), _CosTime,
//           unity_DeltaTime, _WorldSpaceCameraPos, _ProjectionParams (1, near, far, 1/far),
//           _ScreenParams (w, h, 1 + 1/w, 1 + 1/h), unity_ObjectToWorld, unity_WorldToObject,
//           unity_MatrixVP, _SpecColor (Lighting.cginc's BlinnPhong specular colour),
//           unity_SpecCube0_HDR (DecodeHDR instructions of the environment);
//           per-light globals _LightColor0 and _WorldSpaceLightPos0 (NOT uniforms: plain
//           globals the caller's light loop sets before each Lighting<Name> call, since one
//           program here shades every light; w = 0 directional, 1 positional);
//           UNITY_MATRIX_M, UNITY_MATRIX_VP, UNITY_MATRIX_MVP, TRANSFORM_TEX(tex, name);
//           vec4 UnityObjectToClipPos(vec3 pos) / (vec4 pos), vec3 UnityObjectToWorldNormal(vec3),
//           vec3 UnityObjectToWorldDir(vec3), vec3 UnityWorldSpaceViewDir(vec3 worldPos),
//           vec3 UnityWorldSpaceLightDir(vec3 worldPos), vec3 WorldSpaceViewDir(vec4 localPos),
//           vec4 ComputeScreenPos(vec4 clipPos);
//           instancing macros as no-ops (UNITY_INSTANCING_BUFFER_START/END,
//           UNITY_DEFINE_INSTANCED_PROP declares a plain uniform, UNITY_ACCESS_INSTANCED_PROP,
//           UNITY_SETUP_INSTANCE_ID, UNITY_TRANSFER_INSTANCE_ID, UNITY_VERTEX_INPUT_INSTANCE_ID,
//           UNITY_VERTEX_OUTPUT_STEREO); UNITY_INITIALIZE_OUTPUT(type, name) (a no-op in
//           GLSL, as Unity defines it for its GLSL targets).
// Include:  "unity_compat/shader_variables.glsl" (path relative to glsl/). Its HLSL twin
//           hlsl_ports/unity_compat/shader_variables.hlsl is hand-written (matrices: GLSL M * v
//           is HLSL mul(M, v)); HLSL's instancing macro declares `type var;`.
// Config macros read: none.
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_UNITY_COMPAT_SHADER_VARIABLES_GLSL
#define PBR_UNITY_COMPAT_SHADER_VARIABLES_GLSL

uniform vec4 _Time;
uniform vec4 _SinTime;
uniform vec4 _CosTime;
uniform vec4 unity_DeltaTime;
uniform vec3 _WorldSpaceCameraPos;
uniform vec4 _ProjectionParams;
uniform vec4 _ScreenParams;
uniform mat4 unity_ObjectToWorld;
uniform mat4 unity_WorldToObject;
uniform mat4 unity_MatrixVP;
uniform vec4 _SpecColor;
uniform vec4 unity_SpecCube0_HDR;
// pbr/unity/lighting_legacy reads the BlinnPhong specular colour through this hook.
#define PBR_UNITY_SPEC_COLOR _SpecColor
vec4 _LightColor0;
vec4 _WorldSpaceLightPos0;

#define UNITY_MATRIX_M unity_ObjectToWorld
#define UNITY_MATRIX_VP unity_MatrixVP
#define UNITY_MATRIX_MVP (unity_MatrixVP * unity_ObjectToWorld)
#define TRANSFORM_TEX(tex, name) ((tex).xy * name##_ST.xy + name##_ST.zw)

#define UNITY_INSTANCING_BUFFER_START(name)
#define UNITY_INSTANCING_BUFFER_END(name)
#define UNITY_DEFINE_INSTANCED_PROP(type, var) uniform type var;
#define UNITY_ACCESS_INSTANCED_PROP(arr, var) var
#define UNITY_SETUP_INSTANCE_ID(v)
#define UNITY_TRANSFER_INSTANCE_ID(v, o)
#define UNITY_VERTEX_INPUT_INSTANCE_ID
#define UNITY_VERTEX_OUTPUT_STEREO
#define UNITY_INITIALIZE_OUTPUT(type, name)

vec4 UnityObjectToClipPos(vec3 pos) {
    return unity_MatrixVP * (unity_ObjectToWorld * vec4(pos, 1.0));
}

vec4 UnityObjectToClipPos(vec4 pos) {
    return UnityObjectToClipPos(pos.xyz);
}

// Normals transform with the inverse transpose: n^T M^-1 (Unity: mul(norm, (float3x3)unity_WorldToObject)).
vec3 UnityObjectToWorldNormal(vec3 norm) {
    return normalize(norm * mat3(unity_WorldToObject));
}

vec3 UnityObjectToWorldDir(vec3 dir) {
    return normalize(mat3(unity_ObjectToWorld) * dir);
}

vec3 UnityWorldSpaceViewDir(vec3 worldPos) {
    return _WorldSpaceCameraPos - worldPos;
}

vec3 UnityWorldSpaceLightDir(vec3 worldPos) {
    return _WorldSpaceLightPos0.xyz - worldPos * _WorldSpaceLightPos0.w;
}

vec3 WorldSpaceViewDir(vec4 localPos) {
    return UnityWorldSpaceViewDir((unity_ObjectToWorld * localPos).xyz);
}

// Unity's ComputeNonStereoScreenPos with _ProjectionParams.x = 1 (no flip on GL): xy in
// [0, w] from the bottom-left, zw the clip zw; divide by w for [0, 1].
vec4 ComputeScreenPos(vec4 pos) {
    vec4 o = pos * 0.5;
    o.xy = vec2(o.x, o.y * _ProjectionParams.x) + o.w;
    o.zw = pos.zw;
    return o;
}
#endif
