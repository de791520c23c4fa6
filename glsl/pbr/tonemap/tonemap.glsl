// pbr/tonemap/tonemap.glsl: tonemapper selection.
//
// Provides: vec3 pbr_tonemap(vec3 color) and the selector values PBR_TONEMAP_*.
// Include:  "pbr/tonemap/tonemap.glsl" (path relative to glsl/)
// Config macros read: PBR_TONEMAP (default PBR_TONEMAP_KHRONOS_NEUTRAL).
//
// One dispatcher over the tonemappers of this folder (the library's one variant
// mechanism, pbr/common/conventions.glsl §8). PBR_TONEMAP_NONE is pbr_sanitize(c, 1.0):
// saturate with NaN -> 0 defined (every tonemapper sanitises its input the same way).
// Khronos PBR Neutral is the default because it keeps base colours (albedo under a white
// light) nearly unchanged, which is what material charts want.
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_TONEMAP_TONEMAP_GLSL
#define PBR_TONEMAP_TONEMAP_GLSL

#include "pbr/common/math.glsl"
#include "pbr/common/guards.glsl"
#include "pbr/tonemap/reinhard.glsl"
#include "pbr/tonemap/hable.glsl"
#include "pbr/tonemap/aces.glsl"
#include "pbr/tonemap/khronos_neutral.glsl"

#define PBR_TONEMAP_NONE 1
#define PBR_TONEMAP_REINHARD 2
#define PBR_TONEMAP_HABLE 3
#define PBR_TONEMAP_ACES_FITTED 4
#define PBR_TONEMAP_ACES_NARKOWICZ 5
#define PBR_TONEMAP_KHRONOS_NEUTRAL 6

#ifndef PBR_TONEMAP
// PBR_TONEMAP_KHRONOS_NEUTRAL as a number (glsl/README.md, one-level preprocessors)
#define PBR_TONEMAP 6
#endif

vec3 pbr_tonemap(vec3 color) {
#if PBR_TONEMAP == PBR_TONEMAP_NONE
    return pbr_sanitize(color, 1.0);
#elif PBR_TONEMAP == PBR_TONEMAP_REINHARD
    return pbr_tonemap_reinhard(color);
#elif PBR_TONEMAP == PBR_TONEMAP_HABLE
    return pbr_tonemap_hable(color);
#elif PBR_TONEMAP == PBR_TONEMAP_ACES_FITTED
    return pbr_tonemap_aces_fitted(color);
#elif PBR_TONEMAP == PBR_TONEMAP_ACES_NARKOWICZ
    return pbr_tonemap_aces_narkowicz(color);
#elif PBR_TONEMAP == PBR_TONEMAP_KHRONOS_NEUTRAL
    return pbr_tonemap_khronos_neutral(color);
#else
#error PBR_TONEMAP: unknown value
#endif
}

#endif // PBR_TONEMAP_TONEMAP_GLSL
