// pbr/shading/valid_reflection_normal.hlsl: a normal-mapped shading normal bent until the
// view's mirror reflection stays just above the geometric surface.
//
// Provides: vec3 pbr_valid_reflection_normal(vec3 n, vec3 ng, vec3 v)
// Include:  "pbr/shading/valid_reflection_normal.hlsl" (path relative to hlsl_ports/)
// Config macros read: none.
//
// A normal map can tilt the shading normal n so far from the geometric normal ng that the
// mirror reflection of the view, r = 2 (n.v) n - v, points below the geometric surface: a
// path tracer finds that light blocked by the object itself, and a steep metal bump draws a
// dark ring. Keller et al. 2017 ("The Iray Light Transport Simulation and Rendering System",
// arXiv 1705.01263, the section on bump and normal maps) replace n by the n' in the plane of
// n and ng whose reflection of v lies a small height t above the surface; Cycles does the
// same for its glossy closures (kernel/closure/bsdf_util.h, ensure_valid_specular_reflection)
// with t = min(0.9 v.ng, 0.01): a reflection may always be as shallow as the view, at most
// 0.01 above the plane. n is returned unchanged where r.ng >= t already (always where n = ng).
// In the frame with ng as z and n in the x-z plane, n' = (sqrt(1 - z^2), 0, z) solves
// 2 (n'.v) z - v.z = t; squared, a quadratic in w = z^2: 4a w^2 - 2b w + c = 0 with
// a = vx^2 + vz^2, b = 2 (a + vz t), c = (vz + t)^2, of whose roots the one solving the
// unsquared equation is (b + sqrt(b^2 - 4ac)) / 4a for vx < 0 and (b - sqrt(...)) / 4a
// otherwise. The second is written c / (b + sqrt(b^2 - 4ac)) (the product of the roots is
// c / 4a): the same value without the cancellation of b - sqrt(...) when 4ac << b^2. The
// tangent component sqrt(1 - w) is not taken from 1 - w either (at a grazing view w is
// within vz^2 of 1 and 1 - w would keep none of its digits): u = 1 - w solves
// 4a u^2 - 2B u + C = 0, B = 2 (a - vz t), C = (vz - t)^2 (the same discriminant), and is
// taken from whichever of its two forms has no cancellation.
// Float64 reference: harness/pbrlab/maths/reference/valid_reflection_normal.py (the closed
// form and a bisection on the angle); tests/library/test_valid_reflection_normal.py.
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_SHADING_VALID_REFLECTION_NORMAL_HLSL
#define PBR_SHADING_VALID_REFLECTION_NORMAL_HLSL
#include "pbr/common/shim.hlsl"  // generated from glsl/pbr/shading/valid_reflection_normal.glsl by harness/pbrlab/gpu/port_hlsl.py: edit the GLSL, then regenerate

#include "pbr/common/guards.hlsl"

// Cycles' threshold: the reflection at least 0.9 of the view's elevation above the plane
// (PBR_VALID_REFLECTION_VIEW_SCALE) and at most 0.01 (PBR_VALID_REFLECTION_MAX_HEIGHT);
// the same constants as THRESHOLD_SCALE / THRESHOLD_MAX of the Python reference (tested).
#define PBR_VALID_REFLECTION_VIEW_SCALE 0.9
#define PBR_VALID_REFLECTION_MAX_HEIGHT 0.01

// n, ng, v unit; v.ng below 0 (a view just behind an interpolated normal's plane) is taken
// as 0: the reflection is brought to the plane itself.
float3 pbr_valid_reflection_normal(float3 n, float3 ng, float3 v) {
    float vz = max(dot(v, ng), 0.0);
    float t = min(PBR_VALID_REFLECTION_VIEW_SCALE * vz, PBR_VALID_REFLECTION_MAX_HEIGHT);
    float3 r = 2.0 * dot(n, v) * n - v;
    if (dot(r, ng) >= t) {
        return n;
    }
    float3 across = pbr_safe_normalize(n - dot(n, ng) * ng);
    float3 x = dot(across, across) > 0.0 ? across : n;  // n along ng: no plane, n itself
    float vx = dot(v, x);
    float a = vx * vx + vz * vz;
    float b = 2.0 * (a + vz * t);
    float c = pbr_sq(vz + t);
    float root = sqrt(max(b * b - 4.0 * a * c, 0.0));
    // w = z^2 and u = 1 - w = x'^2, each from its own quadratic so the small one never comes
    // from a difference: u solves 4a u^2 - 2B u + C = 0, B = 2 (a - vz t) > 0,
    // C = (vz - t)^2, with the same discriminant
    float bigB = 2.0 * (a - vz * t);
    float w, u;
    if (vx < 0.0) {
        w = (b + root) / max(4.0 * a, PBR_FLT_MIN);
        u = pbr_sq(vz - t) / max(bigB + root, PBR_FLT_MIN);
    } else {
        w = c / max(b + root, PBR_FLT_MIN);
        u = (bigB + root) / max(4.0 * a, PBR_FLT_MIN);
    }
    return sqrt(clamp(u, 0.0, 1.0)) * x + sqrt(clamp(w, 0.0, 1.0)) * ng;
}

#endif // PBR_SHADING_VALID_REFLECTION_NORMAL_HLSL
