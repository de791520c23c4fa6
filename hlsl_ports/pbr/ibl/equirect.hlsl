// pbr/ibl/equirect.hlsl: direction <-> texture coordinates of an equirectangular map.
//
// Provides: vec2 pbr_equirect_uv(vec3 dir)
//           vec3 pbr_equirect_direction(vec2 uv)
// Include:  "pbr/ibl/equirect.hlsl" (path relative to hlsl_ports/)
// Config macros read: none.
//
// Convention (the harness's, harness/pbrlab/scene/environment.py): +Y up; the image's top row
// looks at +Y; azimuth phi = 2 pi u is measured from -Z towards +X, so the image centre
// looks at +Z. Texture coordinate t = 1 is the image's top row (images are uploaded
// top row last, as OpenGL expects).
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_IBL_EQUIRECT_HLSL
#define PBR_IBL_EQUIRECT_HLSL
#include "pbr/common/shim.hlsl"  // generated from glsl/pbr/ibl/equirect.glsl by harness/pbrlab/gpu/port_hlsl.py: edit the GLSL, then regenerate
#include "pbr/common/constants.hlsl"

float2 pbr_equirect_uv(float3 dir) {
    float u = frac(atan2(dir.x, -dir.z) * (0.5 * PBR_INV_PI));
    float t = 1.0 - acos(clamp(dir.y, -1.0, 1.0)) * PBR_INV_PI;
    return float2(u, t);
}

float3 pbr_equirect_direction(float2 uv) {
    float phi = 2.0 * PBR_PI * uv.x;
    float theta = (1.0 - uv.y) * PBR_PI;
    return float3(sin(theta) * sin(phi), cos(theta), -sin(theta) * cos(phi));
}
#endif
