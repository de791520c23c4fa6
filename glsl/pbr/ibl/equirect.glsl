// pbr/ibl/equirect.glsl: direction <-> texture coordinates of an equirectangular map.
//
// Provides: vec2 pbr_equirect_uv(vec3 dir)
//           vec3 pbr_equirect_direction(vec2 uv)
// Include:  "pbr/ibl/equirect.glsl" (path relative to glsl/)
// Config macros read: none.
//
// Convention (the harness's, harness/pbrlab/scene/environment.py): +Y up; the image's top row
// looks at +Y; azimuth phi = 2 pi u is measured from -Z towards +X, so the image centre
// looks at +Z. Texture coordinate t = 1 is the image's top row (images are uploaded
// top row last, as OpenGL expects).
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_IBL_EQUIRECT_GLSL
#define PBR_IBL_EQUIRECT_GLSL
#include "pbr/common/constants.glsl"

vec2 pbr_equirect_uv(vec3 dir) {
    float u = fract(atan(dir.x, -dir.z) * (0.5 * PBR_INV_PI));
    float t = 1.0 - acos(clamp(dir.y, -1.0, 1.0)) * PBR_INV_PI;
    return vec2(u, t);
}

vec3 pbr_equirect_direction(vec2 uv) {
    float phi = 2.0 * PBR_PI * uv.x;
    float theta = (1.0 - uv.y) * PBR_PI;
    return vec3(sin(theta) * sin(phi), cos(theta), -sin(theta) * cos(phi));
}
#endif
