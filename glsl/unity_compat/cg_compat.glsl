// unity_compat/cg_compat.glsl: the Cg/HLSL intrinsics a Unity shader calls, spelled for GLSL.
//
// Provides: saturate (float, vec2-4), lerp (= mix), frac (= fract), rsqrt (= inversesqrt),
//           fmod (C's truncating remainder: x - y * trunc(x / y), NOT GLSL's mod), atan2(y, x),
//           sincos(x, s, c), lit(NdotL, NdotH, m) (HLSL's lighting coefficients), pbr_unity_select(bvecN c, vecN a, vecN b) (HLSL's componentwise
//           c ? a : b, written by port-unity), ddx / ddy (= dFdx / dFdy; 0 in a vertex stage, which has no derivatives), fwidth (GLSL's; 0 in a vertex stage: a fragment function the vertex stage compiles but never calls), mul(M, v) / mul(v, M) / mul(M, N) for mat2, mat3 and mat4,
//           clip(x) (discards when any component < 0; a no-op in a vertex stage, where GLSL
//           has no discard: define PBR_UNITY_VERTEX_STAGE there), PBR_UNITY_DISCARD (a
//           program's own `discard`, as port-unity writes it: the same rule), tex2D, tex2Dlod (uv.w is
//           the LOD), tex2Dbias, tex2Dproj, texCUBE, texCUBElod, and the type names
//           samplerCUBE (= samplerCube); pbr_unity_pow (pow with HLSL's scalar promotion:
//           port-unity renames pow to it), fmod(vecN, float).
// Include:  "unity_compat/cg_compat.glsl" (path relative to glsl/), GLSL ONLY: HLSL has every
//           one of these names itself, so this file has no HLSL twin
//           (harness/pbrlab/gpu/port_hlsl.py ports pbr/ only). Never included by the pbr_ core;
//           `pbrlab port-unity` output includes it. Type renames (float3 -> vec3, ...) are
//           not macros here: port-unity rewrites them, so an engine's own vec3 stays intact.
// Config macros read: PBR_UNITY_VERTEX_STAGE (define it when compiling a vertex stage).
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_UNITY_COMPAT_CG_COMPAT_GLSL
#define PBR_UNITY_COMPAT_CG_COMPAT_GLSL

float saturate(float x) { return clamp(x, 0.0, 1.0); }
vec2 saturate(vec2 x) { return clamp(x, 0.0, 1.0); }
vec3 saturate(vec3 x) { return clamp(x, 0.0, 1.0); }
vec4 saturate(vec4 x) { return clamp(x, 0.0, 1.0); }

#define lerp mix
#define frac fract
#define rsqrt inversesqrt
#ifdef PBR_UNITY_VERTEX_STAGE
#define ddx(x) ((x) * 0.0)
#define ddy(x) ((x) * 0.0)
#define fwidth(x) ((x) * 0.0)
#else
#define ddx dFdx
#define ddy dFdy
#endif
#define samplerCUBE samplerCube
#define sampler2D_float sampler2D
#define sampler2D_half sampler2D

float fmod(float x, float y) { return x - y * trunc(x / y); }
vec2 fmod(vec2 x, vec2 y) { return x - y * trunc(x / y); }
vec3 fmod(vec3 x, vec3 y) { return x - y * trunc(x / y); }
vec4 fmod(vec4 x, vec4 y) { return x - y * trunc(x / y); }

// HLSL promotes a scalar exponent (pow(float3, 2.2)); GLSL has no such overload and forbids
// overloading its built-ins, so port-unity renames pow to pbr_unity_pow.
float pbr_unity_pow(float x, float y) { return pow(x, y); }
vec2 pbr_unity_pow(vec2 x, vec2 y) { return pow(x, y); }
vec3 pbr_unity_pow(vec3 x, vec3 y) { return pow(x, y); }
vec4 pbr_unity_pow(vec4 x, vec4 y) { return pow(x, y); }
vec2 pbr_unity_pow(vec2 x, float y) { return pow(x, vec2(y)); }
vec3 pbr_unity_pow(vec3 x, float y) { return pow(x, vec3(y)); }
vec4 pbr_unity_pow(vec4 x, float y) { return pow(x, vec4(y)); }
vec2 fmod(vec2 x, float y) { return fmod(x, vec2(y)); }
vec3 fmod(vec3 x, float y) { return fmod(x, vec3(y)); }
vec4 fmod(vec4 x, float y) { return fmod(x, vec4(y)); }

// HLSL's componentwise c ? a : b on a vector condition (GLSL's ?: takes one bool): the type
// pass of port-unity writes pbr_unity_select(c, a, b), both branches at the condition's size.
vec2 pbr_unity_select(bvec2 c, vec2 a, vec2 b) { return mix(b, a, c); }
vec3 pbr_unity_select(bvec3 c, vec3 a, vec3 b) { return mix(b, a, c); }
vec4 pbr_unity_select(bvec4 c, vec4 a, vec4 b) { return mix(b, a, c); }

// HLSL's sincos(x, out s, out c): both at once.
#define sincos(x, s, c) { s = sin(x); c = cos(x); }

// HLSL's lit(n.l, n.h, m) (Microsoft's HLSL reference, "lit"): (ambient 1, diffuse n.l where
// n.l >= 0 else 0, specular (n.h)^m unless n.l < 0 or n.h < 0, then 0, 1).
vec4 lit(float NdotL, float NdotH, float m) {
    float specular = (NdotL < 0.0 || NdotH < 0.0) ? 0.0 : pow(NdotH, m);
    return vec4(1.0, max(NdotL, 0.0), specular, 1.0);
}

float atan2(float y, float x) { return atan(y, x); }
vec2 atan2(vec2 y, vec2 x) { return atan(y, x); }
vec3 atan2(vec3 y, vec3 x) { return atan(y, x); }

vec4 mul(mat4 m, vec4 v) { return m * v; }
vec4 mul(vec4 v, mat4 m) { return v * m; }
vec3 mul(mat3 m, vec3 v) { return m * v; }
vec3 mul(vec3 v, mat3 m) { return v * m; }
// HLSL multiplies a float4x4 by a float3 with the matrix cut to its first three columns (rows
// for v * M): the four-component result, whose .xyz is mat3(M) * v.
vec4 mul(mat4 m, vec3 v) { return m * vec4(v, 0.0); }
vec4 mul(vec3 v, mat4 m) { return vec4(v, 0.0) * m; }
vec2 mul(mat2 m, vec2 v) { return m * v; }
vec2 mul(vec2 v, mat2 m) { return v * m; }
mat4 mul(mat4 a, mat4 b) { return a * b; }
mat2 mul(mat2 a, mat2 b) { return a * b; }
mat3 mul(mat3 a, mat3 b) { return a * b; }

bool pbr_unity_clip_below_zero(float x) { return x < 0.0; }
bool pbr_unity_clip_below_zero(vec2 x) { return any(lessThan(x, vec2(0.0))); }
bool pbr_unity_clip_below_zero(vec3 x) { return any(lessThan(x, vec3(0.0))); }
bool pbr_unity_clip_below_zero(vec4 x) { return any(lessThan(x, vec4(0.0))); }
#ifdef PBR_UNITY_VERTEX_STAGE
#define clip(x)
#define PBR_UNITY_DISCARD
#else
#define clip(x) if (pbr_unity_clip_below_zero(x)) discard
#define PBR_UNITY_DISCARD discard
#endif

vec4 tex2D(sampler2D s, vec2 uv) { return texture(s, uv); }
vec4 tex2Dlod(sampler2D s, vec4 uv) { return textureLod(s, uv.xy, uv.w); }
#ifdef PBR_UNITY_VERTEX_STAGE
vec4 tex2Dbias(sampler2D s, vec4 uv) { return textureLod(s, uv.xy, 0.0); }  // no LOD to bias
#else
vec4 tex2Dbias(sampler2D s, vec4 uv) { return texture(s, uv.xy, uv.w); }
#endif
vec4 tex2Dproj(sampler2D s, vec4 uv) { return textureProj(s, uv); }
vec4 texCUBE(samplerCube s, vec3 dir) { return texture(s, dir); }
vec4 texCUBElod(samplerCube s, vec4 dir) { return textureLod(s, dir.xyz, dir.w); }
#endif
