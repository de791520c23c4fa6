// unity_compat/cg_compat.glsl: the Cg/HLSL intrinsics a Unity shader calls, spelled for GLSL.
//
// Provides: saturate (float, vec2-4), lerp (= mix), frac (= fract), rsqrt (= inversesqrt),
//           fmod (C's truncating remainder: x - y * trunc(x / y), NOT GLSL's mod), atan2(y, x),
//           sincos(x, s, c), lit(NdotL, NdotH, m) (HLSL's lighting coefficients), pbr_unity_select(bvecN c, vecN a, vecN b) (HLSL's componentwise
//           c ? a : b, written by port-unity), pbr_unity_set_row(inout M, i, v) (HLSL's row write M[i] = v), ddx / ddy (= dFdx / dFdy; 0 in a vertex stage, which has no derivatives), fwidth (GLSL's; 0 in a vertex stage: a fragment function the vertex stage compiles but never calls), mul(M, v) / mul(v, M) / mul(M, N) for mat2, mat3 and mat4,
//           clip(x) (discards when any component < 0; a no-op in a vertex stage, where GLSL
//           has no discard: define PBR_UNITY_VERTEX_STAGE there), PBR_UNITY_DISCARD (a
//           program's own `discard`, as port-unity writes it: the same rule), tex2D, tex3D, tex2Dlod (uv.w is
//           the LOD), tex2Dbias, tex2Dproj, tex2Dgrad (and tex2D's form with derivatives), texCUBE,
//           texCUBElod, texCUBEbias, texCUBEgrad (each coordinate through
//           pbr_unity_finite_coordinate: finite_texture_coordinate.glsl; tex2Dproj divides first, as HLSL's), pbr_unity_load (Texture2D.Load), asuint / asint / asfloat, rcp, mad, log10, and the type names
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
#include "unity_compat/finite_texture_coordinate.glsl"  // the tex* lookups' coordinates, as Direct3D addresses them

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
#define samplerCUBE_float samplerCube
#define samplerCUBE_half samplerCube
#define sampler3D_float sampler3D
#define sampler3D_half sampler3D
// HLSLSupport.cginc's constant-buffer brackets, which Unity includes in every CGPROGRAM: on GL
// a named buffer is plain globals (CBUFFER_START(UnitySceneViewColor) ... CBUFFER_END in a
// program that includes nothing)
#ifndef CBUFFER_START
#define CBUFFER_START(name)
#define CBUFFER_END
#endif
// HLSLSupport.cginc's type of a fragment input with the VPOS semantic, float4 (x, y the pixel's
// window position, as SV_POSITION in a fragment) on every target but Direct3D 9's float2; a
// program that includes nothing declares ``UNITY_VPOS_TYPE screenPos : VPOS``.
#ifndef UNITY_VPOS_TYPE
#define UNITY_VPOS_TYPE vec4
#endif

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

// HLSL's row write M[i] = v (HLSL indexes a matrix by rows, GLSL by columns): the type pass of
// port-unity writes pbr_unity_set_row(M, i, v), which returns v as the assignment does. GLSL's
// matCxR is HLSL's floatRxC: a row has C components.
vec2 pbr_unity_set_row(inout mat2 m, int i, vec2 v) { m[0][i] = v.x; m[1][i] = v.y; return v; }
vec3 pbr_unity_set_row(inout mat3 m, int i, vec3 v) { m[0][i] = v.x; m[1][i] = v.y; m[2][i] = v.z; return v; }
vec4 pbr_unity_set_row(inout mat4 m, int i, vec4 v) { m[0][i] = v.x; m[1][i] = v.y; m[2][i] = v.z; m[3][i] = v.w; return v; }
vec3 pbr_unity_set_row(inout mat3x4 m, int i, vec3 v) { m[0][i] = v.x; m[1][i] = v.y; m[2][i] = v.z; return v; }
vec4 pbr_unity_set_row(inout mat4x3 m, int i, vec4 v) { m[0][i] = v.x; m[1][i] = v.y; m[2][i] = v.z; m[3][i] = v.w; return v; }

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

vec4 tex2D(sampler2D s, vec2 uv) { return texture(s, pbr_unity_finite_coordinate(uv)); }
vec4 tex2Dlod(sampler2D s, vec4 uv) { return textureLod(s, pbr_unity_finite_coordinate(uv.xy), uv.w); }
#ifdef PBR_UNITY_VERTEX_STAGE
vec4 tex2Dbias(sampler2D s, vec4 uv) { return textureLod(s, pbr_unity_finite_coordinate(uv.xy), 0.0); }  // no LOD to bias
#else
vec4 tex2Dbias(sampler2D s, vec4 uv) { return texture(s, pbr_unity_finite_coordinate(uv.xy), uv.w); }
#endif
vec4 tex2Dproj(sampler2D s, vec4 uv) { return texture(s, pbr_unity_finite_coordinate(uv.xy / uv.w)); }
vec4 tex2Dproj(sampler2D s, vec3 uv) { return texture(s, pbr_unity_finite_coordinate(uv.xy / uv.z)); }
vec4 texCUBE(samplerCube s, vec3 dir) { return texture(s, pbr_unity_finite_coordinate(dir)); }
vec4 texCUBElod(samplerCube s, vec4 dir) { return textureLod(s, pbr_unity_finite_coordinate(dir.xyz), dir.w); }
// A 3D (volume) texture: Cg's tex3D, and tex3Dlod (uvw.w the mip level).
vec4 tex3D(sampler3D s, vec3 uvw) { return texture(s, pbr_unity_finite_coordinate(uvw)); }
vec4 tex3Dlod(sampler3D s, vec4 uvw) { return textureLod(s, pbr_unity_finite_coordinate(uvw.xyz), uvw.w); }
// Texture2D.Load(int3(x, y, mip)) as the GLSL port spells it (importers/unity/texture_methods.py).
vec4 pbr_unity_load(sampler2D s, ivec3 p) { return texelFetch(s, p.xy, p.z); }
// A comparison sampler's read (Texture2D.SampleCmp / SampleCmpLevelZero, Core RP's
// SAMPLE_TEXTURE2D_SHADOW and its array and cube forms, as the GLSL port spells them): the
// reference (the last component) against each texel the filter reads, by the depth texture's
// comparison (importers/unity/shadow_maps.py: LEQUAL, 1 where it passes), the results filtered;
// a depth texture's one level, so SampleCmpLevelZero's level 0 is this read in every stage.
float pbr_unity_sample_cmp(sampler2DShadow s, vec3 uv_reference) { return texture(s, uv_reference); }
float pbr_unity_sample_cmp(sampler2DArrayShadow s, vec4 uv_layer_reference) { return texture(s, uv_layer_reference); }
float pbr_unity_sample_cmp(samplerCubeShadow s, vec4 direction_reference) { return texture(s, direction_reference); }
// Explicit derivatives (Cg's tex2Dgrad, and tex2D's four-argument form: the same lookup).
vec4 tex2Dgrad(sampler2D s, vec2 uv, vec2 dx, vec2 dy) { return textureGrad(s, pbr_unity_finite_coordinate(uv), dx, dy); }
vec4 tex2D(sampler2D s, vec2 uv, vec2 dx, vec2 dy) { return textureGrad(s, pbr_unity_finite_coordinate(uv), dx, dy); }
vec4 texCUBEgrad(samplerCube s, vec3 dir, vec3 dx, vec3 dy) { return textureGrad(s, pbr_unity_finite_coordinate(dir), dx, dy); }
#ifdef PBR_UNITY_VERTEX_STAGE
vec4 texCUBEbias(samplerCube s, vec4 dir) { return textureLod(s, pbr_unity_finite_coordinate(dir.xyz), 0.0); }  // no LOD to bias
#else
vec4 texCUBEbias(samplerCube s, vec4 dir) { return texture(s, pbr_unity_finite_coordinate(dir.xyz), dir.w); }
#endif

// HLSL's bit casts (Microsoft's HLSL intrinsic reference): asuint / asint /
// asfloat reinterpret the 32 bits; an integer to an integer keeps the bits (GLSL's uint(int)).
uint asuint(float x) { return floatBitsToUint(x); }
uvec2 asuint(vec2 x) { return floatBitsToUint(x); }
uvec3 asuint(vec3 x) { return floatBitsToUint(x); }
uvec4 asuint(vec4 x) { return floatBitsToUint(x); }
uint asuint(int x) { return uint(x); }
uint asuint(uint x) { return x; }
int asint(float x) { return floatBitsToInt(x); }
ivec2 asint(vec2 x) { return floatBitsToInt(x); }
ivec3 asint(vec3 x) { return floatBitsToInt(x); }
ivec4 asint(vec4 x) { return floatBitsToInt(x); }
int asint(uint x) { return int(x); }
int asint(int x) { return x; }
float asfloat(uint x) { return uintBitsToFloat(x); }
vec2 asfloat(uvec2 x) { return uintBitsToFloat(x); }
vec3 asfloat(uvec3 x) { return uintBitsToFloat(x); }
vec4 asfloat(uvec4 x) { return uintBitsToFloat(x); }
float asfloat(int x) { return intBitsToFloat(x); }
vec2 asfloat(ivec2 x) { return intBitsToFloat(x); }
vec3 asfloat(ivec3 x) { return intBitsToFloat(x); }
vec4 asfloat(ivec4 x) { return intBitsToFloat(x); }
float asfloat(float x) { return x; }

// HLSL's rcp, mad and log10 (GLSL has none of the three names).
float rcp(float x) { return 1.0 / x; }
vec2 rcp(vec2 x) { return 1.0 / x; }
vec3 rcp(vec3 x) { return 1.0 / x; }
vec4 rcp(vec4 x) { return 1.0 / x; }
float mad(float a, float b, float c) { return a * b + c; }
vec2 mad(vec2 a, vec2 b, vec2 c) { return a * b + c; }
vec3 mad(vec3 a, vec3 b, vec3 c) { return a * b + c; }
vec4 mad(vec4 a, vec4 b, vec4 c) { return a * b + c; }
float log10(float x) { return log2(x) * 0.30102999566398120; }  // log10(2)
vec2 log10(vec2 x) { return log2(x) * 0.30102999566398120; }
vec3 log10(vec3 x) { return log2(x) * 0.30102999566398120; }
vec4 log10(vec4 x) { return log2(x) * 0.30102999566398120; }
vec4 atan2(vec4 y, vec4 x) { return atan(y, x); }
#endif
