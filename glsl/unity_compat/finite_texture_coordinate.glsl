// unity_compat/finite_texture_coordinate.glsl: a texture coordinate as Direct3D's sampler
// addresses it when a component is not finite.
//
// Provides: pbr_unity_finite_coordinate(x) for float, vec2, vec3, vec4: each NaN or infinite
//           component replaced by 0, the others kept.
// Why:      Direct3D converts a texture coordinate to fixed point before addressing texels
//           (Direct3D 10/11 "Data Conversion Rules", float to fixed point: NaN becomes 0), so
//           a sample of a finite texture is finite whatever the coordinate; the filter weights
//           are fixed-point fractions. Mesa's llvmpipe filters with float weights, and a NaN or
//           infinite coordinate gives a NaN colour. A Unity shader that samples at 0 / 0 (a
//           matrix or a divisor its C# script sets, 0 without it) draws the texel in Unity and
//           NaN in pbrlab without this. Which texel an infinite coordinate reads is the
//           hardware's (its fixed-point range): 0 here, the same for a texture of one colour,
//           as every default texture is.
// Include:  "unity_compat/finite_texture_coordinate.glsl"; cg_compat.glsl includes it, and
//           importers/unity/finite_texture_coordinates.py puts it into the GLSL spirv-cross
//           writes for an HLSL program. GLSL only (no HLSL twin: pbr/ is ported, not this).
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_UNITY_COMPAT_FINITE_TEXTURE_COORDINATE_GLSL
#define PBR_UNITY_COMPAT_FINITE_TEXTURE_COORDINATE_GLSL

float pbr_unity_finite_coordinate(float x) { return (isnan(x) || isinf(x)) ? 0.0 : x; }
vec2 pbr_unity_finite_coordinate(vec2 x) { return vec2(pbr_unity_finite_coordinate(x.x), pbr_unity_finite_coordinate(x.y)); }
vec3 pbr_unity_finite_coordinate(vec3 x) { return vec3(pbr_unity_finite_coordinate(x.xy), pbr_unity_finite_coordinate(x.z)); }
vec4 pbr_unity_finite_coordinate(vec4 x) { return vec4(pbr_unity_finite_coordinate(x.xy), pbr_unity_finite_coordinate(x.zw)); }

#endif
