// pbr/common/shim.hlsl: the HLSL the generated ports need beyond HLSL's own intrinsics.
//
// Provides: pbr_mod(x, y) (GLSL's mod: x - y * floor(x / y), NOT fmod) for float..float4
//           and (floatN, float); and, for Unity users, fixed, fixed2..4 and fixed2x2..4x4
//           (= half, as Unity's HLSLSupport.cginc defines them, left alone where the engine
//           already did).
// Include:  "pbr/common/shim.hlsl" (path relative to hlsl_ports/). Every generated file
//           includes it; you do not need to.
// Config macros read: PBR_HLSL_NO_FIXED_TYPES (define it to keep fixed* undefined).
//
// This is the only hand-written HLSL of hlsl_ports/: everything else is generated from
// glsl/ by harness/pbrlab/gpu/port_hlsl.py (python -m pbrlab.gpu.port_hlsl), which spells the GLSL
// in HLSL's own words instead of defining GLSL names here, so the ports compile beside an
// engine that has its own mod, mix, vec3 or PI:
//   GLSL                      generated HLSL              note
//   vecN, ivecN, uvecN, bvecN floatN, intN, uintN, boolN  spelling
//   mix(x, y, a)              lerp(x, y, a)               same formula x + (y - x) a; a
//                                                         boolean selector is refused
//   fract(x)                  frac(x)                     both x - floor(x)
//   inversesqrt(x)            rsqrt(x)                    spelling
//   mod(x, y)                 pbr_mod(x, y)               fmod truncates towards 0: differs
//                                                         for x/y < 0 (GLSL 4.60 §8.3)
//   vecN(x) (one argument)    ((floatN)(x))               HLSL has no splat constructor
//   atan(y, x)                atan2(y, x)                 HLSL's atan takes one argument
// greaterThan & co. and matrices are refused by the generator. Scalars, swizzles,
// out/inout parameters, arrays (float3 sh[9]), structs, uint literals and the other
// built-ins the library calls (clamp, dot, cross, pow, exp2, ...) are the same in both
// languages. Measured equality of every function: tests/gpu/hlsl/.
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_COMMON_SHIM_HLSL
#define PBR_COMMON_SHIM_HLSL

// Unity's HLSLSupport.cginc defines fixed* as macros for half*; half is an HLSL type
// (float below SM 6.2 or without -enable-16bit-types, float16 with it).
#if !defined(PBR_HLSL_NO_FIXED_TYPES) && !defined(fixed)
#define fixed half
#define fixed2 half2
#define fixed3 half3
#define fixed4 half4
#define fixed2x2 half2x2
#define fixed3x3 half3x3
#define fixed4x4 half4x4
#endif

float  pbr_mod(float x,  float y)  { return x - y * floor(x / y); }
float2 pbr_mod(float2 x, float2 y) { return x - y * floor(x / y); }
float3 pbr_mod(float3 x, float3 y) { return x - y * floor(x / y); }
float4 pbr_mod(float4 x, float4 y) { return x - y * floor(x / y); }
float2 pbr_mod(float2 x, float y)  { return x - y * floor(x / y); }
float3 pbr_mod(float3 x, float y)  { return x - y * floor(x / y); }
float4 pbr_mod(float4 x, float y)  { return x - y * floor(x / y); }

#endif // PBR_COMMON_SHIM_HLSL
