// pbr/common/shim.hlsl: the GLSL spellings the ported bodies use, defined for HLSL.
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
//
// Provides: the GLSL type names vec2..4, ivec2..4, uvec2..4, bvec2..4 (macros for the HLSL
//           vector types); mix (lerp, and GLSL's boolean-select form), fract (frac),
//           inversesqrt (rsqrt), mod (GLSL semantics, NOT fmod), greaterThan, lessThan,
//           greaterThanEqual, lessThanEqual (component-wise comparisons); and, for Unity
//           users, fixed, fixed2..4 (= half, as Unity's HLSLSupport.cginc defines them).
// Include:  "pbr/common/shim.hlsl" (path relative to hlsl_ports/). Every generated file
//           includes it; you do not need to.
// Config macros read: PBR_HLSL_NO_GLSL_FUNCTIONS (define it when your engine already
//           defines mix/fract/inversesqrt/mod/greaterThan/... with these signatures);
//           PBR_HLSL_NO_FIXED_TYPES (define it to keep fixed* undefined). A type name
//           that is already a macro (e.g. Unity's `#define fixed half`, a GLSL-compat
//           header's `#define vec3 float3`) is left as the engine defined it.
//
// This is the only hand-written HLSL of hlsl_ports/: everything else is generated from
// glsl/ by harness/pbrlab/port_hlsl.py (python -m pbrlab.port_hlsl), which also turns
// one-argument constructors vec3(x) into casts ((vec3)(x)) and atan(y, x) into atan2(y, x),
// and refuses matrices (GLSL m * v vs HLSL mul: the order depends on storage, so a port
// must be written by hand, never guessed). Every GLSL/HLSL difference of the library
// goes through this file:
//   GLSL                      HLSL here                   why it needs a definition
//   vecN, ivecN, uvecN, bvecN floatN, intN, uintN, boolN  spelling
//   mix(x, y, a)              lerp(x, y, a)               spelling; same formula x + (y - x) a
//   mix(x, y, bvecN a)        a ? y : x per component     GLSL select form (HLSL 2021 has
//                                                         no vector ?:, so per component)
//   fract(x)                  frac(x)                     spelling; both x - floor(x)
//   inversesqrt(x)            rsqrt(x)                    spelling
//   mod(x, y)                 x - y * floor(x / y)        fmod truncates towards 0: differs
//                                                         for x/y < 0 (GLSL 4.60 §8.3)
//   greaterThan(a, b) etc.    a > b (boolN)               spelling
// Scalars, swizzles, out/inout parameters, arrays (float3 sh[9]), structs, uint literals
// and the other built-ins the library calls (clamp, dot, cross, pow, exp2, ...) are the
// same in both languages. Measured equality of every function: tests/hlsl/.
#ifndef PBR_COMMON_SHIM_HLSL
#define PBR_COMMON_SHIM_HLSL

#ifndef vec2
#define vec2 float2
#endif
#ifndef vec3
#define vec3 float3
#endif
#ifndef vec4
#define vec4 float4
#endif
#ifndef ivec2
#define ivec2 int2
#endif
#ifndef ivec3
#define ivec3 int3
#endif
#ifndef ivec4
#define ivec4 int4
#endif
#ifndef uvec2
#define uvec2 uint2
#endif
#ifndef uvec3
#define uvec3 uint3
#endif
#ifndef uvec4
#define uvec4 uint4
#endif
#ifndef bvec2
#define bvec2 bool2
#endif
#ifndef bvec3
#define bvec3 bool3
#endif
#ifndef bvec4
#define bvec4 bool4
#endif

// Unity's HLSLSupport.cginc defines fixed* as macros for half*; half is an HLSL type
// (float below SM 6.2 or without -enable-16bit-types, float16 with it).
#if !defined(PBR_HLSL_NO_FIXED_TYPES) && !defined(fixed)
#define fixed half
#define fixed2 half2
#define fixed3 half3
#define fixed4 half4
#endif

#ifndef PBR_HLSL_NO_GLSL_FUNCTIONS

float  mix(float x,  float y,  float a)  { return lerp(x, y, a); }
float2 mix(float2 x, float2 y, float2 a) { return lerp(x, y, a); }
float3 mix(float3 x, float3 y, float3 a) { return lerp(x, y, a); }
float4 mix(float4 x, float4 y, float4 a) { return lerp(x, y, a); }
float2 mix(float2 x, float2 y, float a)  { return lerp(x, y, a); }
float3 mix(float3 x, float3 y, float a)  { return lerp(x, y, a); }
float4 mix(float4 x, float4 y, float a)  { return lerp(x, y, a); }
float  mix(float x,  float y,  bool a)   { return a ? y : x; }
float2 mix(float2 x, float2 y, bool2 a)  { return float2(a.x ? y.x : x.x, a.y ? y.y : x.y); }
float3 mix(float3 x, float3 y, bool3 a)  { return float3(a.x ? y.x : x.x, a.y ? y.y : x.y, a.z ? y.z : x.z); }
float4 mix(float4 x, float4 y, bool4 a)  { return float4(a.x ? y.x : x.x, a.y ? y.y : x.y, a.z ? y.z : x.z, a.w ? y.w : x.w); }

float  fract(float x)  { return frac(x); }
float2 fract(float2 x) { return frac(x); }
float3 fract(float3 x) { return frac(x); }
float4 fract(float4 x) { return frac(x); }

float  inversesqrt(float x)  { return rsqrt(x); }
float2 inversesqrt(float2 x) { return rsqrt(x); }
float3 inversesqrt(float3 x) { return rsqrt(x); }
float4 inversesqrt(float4 x) { return rsqrt(x); }

float  mod(float x,  float y)  { return x - y * floor(x / y); }
float2 mod(float2 x, float2 y) { return x - y * floor(x / y); }
float3 mod(float3 x, float3 y) { return x - y * floor(x / y); }
float4 mod(float4 x, float4 y) { return x - y * floor(x / y); }
float2 mod(float2 x, float y)  { return x - y * floor(x / y); }
float3 mod(float3 x, float y)  { return x - y * floor(x / y); }
float4 mod(float4 x, float y)  { return x - y * floor(x / y); }

bool2 greaterThan(float2 a, float2 b)      { return a > b; }
bool3 greaterThan(float3 a, float3 b)      { return a > b; }
bool4 greaterThan(float4 a, float4 b)      { return a > b; }
bool2 lessThan(float2 a, float2 b)         { return a < b; }
bool3 lessThan(float3 a, float3 b)         { return a < b; }
bool4 lessThan(float4 a, float4 b)         { return a < b; }
bool2 greaterThanEqual(float2 a, float2 b) { return a >= b; }
bool3 greaterThanEqual(float3 a, float3 b) { return a >= b; }
bool4 greaterThanEqual(float4 a, float4 b) { return a >= b; }
bool2 lessThanEqual(float2 a, float2 b)    { return a <= b; }
bool3 lessThanEqual(float3 a, float3 b)    { return a <= b; }
bool4 lessThanEqual(float4 a, float4 b)    { return a <= b; }

#endif // PBR_HLSL_NO_GLSL_FUNCTIONS

#endif // PBR_COMMON_SHIM_HLSL
