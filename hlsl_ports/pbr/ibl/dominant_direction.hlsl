// pbr/ibl/dominant_direction.hlsl: the direction to read a prefiltered environment along for
// a rough lobe.
//
// Provides: vec3 pbr_specular_dominant_direction(vec3 n, vec3 r, float alpha)
// Include:  "pbr/ibl/dominant_direction.hlsl" (path relative to hlsl_ports/)
// Config macros read: none.
//
// The split sum prefilters the environment with the lobe as it is at n = v = r (Karis 2013,
// "Real Shading in Unreal Engine 4"); away from normal incidence the real lobe,
// f_spec (n.l) with its masking-shadowing, leans from the mirror direction r towards the
// normal n, the more the rougher: at alpha 1 its centroid is n itself (D is constant). Reading
// the prefiltered environment along r then fetches light from the wrong part of the sky,
// most visibly as a bright or dark rim on rough metals (the fidelity benchmark's
// MetalRoughSpheres against Cycles). The dominant direction of Lagarde & de Rousiers 2014
// ("Moving Frostbite to PBR", section 4.9.3), as Filament simplifies it (section 5.3.4.7,
// getSpecularDominantDirection): mix(r, n, alpha), alpha the GGX roughness (normalised).
// Against the float64 centroid of the lobe (D, height-correlated G2, n.l;
// harness/pbrlab/maths/reference/dominant_direction.py) over alpha 0.05..1 and n.v
// 0.1..0.9, it is at most 19 deg from the centroid where r is up to 84 deg from it, closer
// than r wherever the lobe leans more than 5 deg, and a third of r's error on average; near
// normal incidence, where the lobe barely leans, it overshoots by up to 3.1 deg
// (tests/library/test_dominant_direction.py). Exactly r at alpha 0 and n at alpha 1. Read
// this way, the split sum of a real environment with a sun (Blender's sunrise) errs by a
// median 18 / 15 / 8.6 % at perceptual roughness 0.5 / 0.7 / 1 where the mirror direction
// errs by 26 / 36 / 50 % (tests/render/test_specular_environment_direction.py).
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_IBL_DOMINANT_DIRECTION_HLSL
#define PBR_IBL_DOMINANT_DIRECTION_HLSL
#include "pbr/common/shim.hlsl"  // generated from glsl/pbr/ibl/dominant_direction.glsl by harness/pbrlab/gpu/port_hlsl.py: edit the GLSL, then regenerate

// The lerp vanishes only for r = -n at alpha 1/2 (a view straight behind a normal-mapped n):
// n is returned there, as at alpha 1.
#define PBR_DOMINANT_MIN_LENGTH_SQUARED 1e-12
float3 pbr_specular_dominant_direction(float3 n, float3 r, float alpha) {
    float3 d = lerp(r, n, alpha);
    float len2 = dot(d, d);
    return len2 > PBR_DOMINANT_MIN_LENGTH_SQUARED ? d * rsqrt(len2) : n;
}

#endif // PBR_IBL_DOMINANT_DIRECTION_HLSL
