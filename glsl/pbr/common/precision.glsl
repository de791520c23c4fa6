// pbr/common/precision.glsl: the half-precision type of the LOW tier's specular lobe.
//
// Provides: PBR_HALF, the scalar type, also its constructor: PBR_HALF x = PBR_HALF(y);
//           PBR_HALF_ARITHMETIC: 1 where floats may be 16-bit (PBR_FLOAT16, or GLSL ES,
//           whose mediump is fp16 on most mobile GPUs), else 0; PBR_HALF_MIN_NORMAL (2^-14)
// Include:  "pbr/common/precision.glsl" (path relative to glsl/)
// Config macros read: PBR_FLOAT16
//
// Without PBR_FLOAT16, PBR_HALF is float: the code is float32 on desktop GL, and mediump
// where the shader's default float precision is mediump (GLSL ES: real fp16 on most mobile
// GPUs). Desktop and Vulkan drivers ignore mediump / RelaxedPrecision (Mesa's RADV 22.3
// compiles it as float32: measured, docs/bench), so with PBR_FLOAT16 defined PBR_HALF is
// float16_t, which reaches a GPU's 16-bit ALUs. That needs
// GL_EXT_shader_explicit_arithmetic_types_float16, enabled by the including shader before
// this file (the extension directive with require; Vulkan: the shaderFloat16 feature), or it is an error
// here. Where PBR_HALF_ARITHMETIC is 1 the LOW tier evaluates its lobe in the order that
// stays inside half's range (pbr_DV_GGX_SmithCorrelatedFast_half).
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_COMMON_PRECISION_GLSL
#define PBR_COMMON_PRECISION_GLSL

#if defined(PBR_FLOAT16) || defined(GL_ES)
#define PBR_HALF_ARITHMETIC 1
#else
#define PBR_HALF_ARITHMETIC 0
#endif

// The smallest normal half, 2^-14 (below it mediump need not keep values).
#define PBR_HALF_MIN_NORMAL 6.103515625e-5

#ifdef PBR_FLOAT16
// glslang defines the extension's macro for desktop GLSL only, so the check is skipped for
// GLSL ES (there the extension directive is the shader's own responsibility).
#  if !defined(GL_ES) && !defined(GL_EXT_shader_explicit_arithmetic_types_float16)
#    error PBR_FLOAT16 needs #extension GL_EXT_shader_explicit_arithmetic_types_float16 : require before the pbrlab includes
#  endif
#  define PBR_HALF float16_t
#else
#  define PBR_HALF float
#endif

#endif // PBR_COMMON_PRECISION_GLSL
