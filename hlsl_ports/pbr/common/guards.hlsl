// pbr/common/guards.hlsl: the numeric guards of the library, each a named constant with its
// derivation and its accuracy cost, and the helpers that apply them.
//
// Provides: PBR_FLT_MIN, PBR_HALF_MAX, PBR_MIN_ALPHA, PBR_MIN_NDOTV, PBR_MIN_VDOTH,
//           PBR_MIN_HALF_VECTOR_LENGTH_SQUARED, PBR_MIN_NDOT_HALF_SUM, PBR_SAFE_NORMALIZE_HUGE,
//           pbr_pow_safe(float, float), pbr_sanitize(float|vec3, float hi),
//           pbr_safe_normalize(vec3), pbr_one_minus_dot2(vec3, vec3),
//           pbr_length2_nonzero(vec3).
// Include:  "pbr/common/guards.hlsl" (path relative to hlsl_ports/)
// Config macros read: none.
//
// Rule (tested by tests/checking/hardcases/): a guard changes a result only where the maths has no
// finite value or float32 cannot represent it; inside the domain of the maths results are
// bit-identical to the unguarded formula unless the comment says otherwise. Where the maths
// has no value the library decides one, written next to the guard and tested exactly.
// NaN: GLSL leaves min/max/clamp/isnan on NaN implementation-defined (isnan may be compiled
// away under fast maths), so NaN is removed only by an ordered comparison, false for NaN in
// IEEE 754 and in SPIR-V OpFOrdGreaterThan, used as a select (pbr_sanitize).
// Every constant is shared with harness/pbrlab/maths/reference/guards.py (tested equal).
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_COMMON_GUARDS_HLSL
#define PBR_COMMON_GUARDS_HLSL
#include "pbr/common/shim.hlsl"  // generated from glsl/pbr/common/guards.glsl by harness/pbrlab/gpu/port_hlsl.py: edit the GLSL, then regenerate

#include "pbr/common/math.hlsl"

// Smallest normal float32, 2^-126. A divisor or pow base floored here stays a normal
// number, so GPUs that flush denormals to zero never see 0 (log2(0) = -Inf, x/0).
#define PBR_FLT_MIN 1.17549435e-38

// Largest finite IEEE binary16 (half), (2 - 2^-10) · 2^15. RGBA16F render targets cannot
// hold more, so it is the largest HDR value the tonemappers take (+Inf is clamped to it)
// and the largest value a mediump (half) tier may produce.
#define PBR_HALF_MAX 65504.0

// Smallest alpha the raw D, G and V terms accept (larger alpha passes bit-identically).
// A float32 unit vector resolves directions to ~2^-24 ≈ 6e-8 rad, so a lobe narrower than
// 1e-7 is a Dirac for every float32 caller; at alpha = 0 the maths has no value (D_GGX(1, 0)
// is 0/0). Keeps alpha² = 1e-14 a normal float and D's peak 1/(π alpha²) = 3.2e13 finite,
// with room for V (<= 2.5e7) and light (<= PBR_HALF_MAX) in the product. Cost: none for
// alpha >= 1e-7; below it the value is that of alpha = 1e-7 (the shading model never goes
// below PBR_MIN_PERCEPTUAL_ROUGHNESS² = 2e-3).
#define PBR_MIN_ALPHA 1e-7

// Lower clamp of the cosines every V term divides by (NdotL and NdotV): Filament's
// MIN_N_DOT_V (shading_model_standard.fs, clampNoV). V ~ 1/(NdotL NdotV) at grazing; with
// both cosines >= 1e-4 every V stays below 0.25/(1e-4)² = 2.5e7, and the lit result
// V · NdotL · NdotV -> 0 continuously as a cosine -> 0. Cost: V changes only for a cosine
// below 1e-4 (within 0.006° of the horizon), where the light it scales is multiplied by
// NdotL <= 1e-4 anyway. Back-facing views (normal maps) clamp to it rather than go negative.
#define PBR_MIN_NDOTV 1e-4

// |l + v|² below which l and v are treated as opposite (no half vector): |l + v| < 1e-5,
// i.e. l and -v within 1e-5 rad, a few times float32's direction resolution (2^-24 ≈ 6e-8
// per component, amplified by normalisation). The fused D · V quotients take h = l + v
// unnormalised: their denominator d² (lambdaV + lambdaL) >= (h2 alpha²)² · NdotV alpha
// (dv_ggx_smith_correlated.hlsl) stays a normal float32 (>= 1.2e-38) for h2 >= 1e-10 at
// the smallest alpha, where 1e-12 would let it become a denormal that GPUs flush to 0.
#define PBR_MIN_HALF_VECTOR_LENGTH_SQUARED 1e-10

// Smallest n·(l + v) at which pbr_brdf_standard keeps the specular lobe: 2^-50 ≈ 8.9e-16,
// the one test for "l + v has a direction above the surface". For a lit light (n·l > 0;
// below the horizon pbr_brdf_standard takes n·l as 0 and only needs a finite value, which
// pbr_length2_nonzero gives) it implies |l + v|² >=
// (n·(l + v))² >= 2^-100 ≈ 7.9e-31, a normal float32 whose reciprocal (1.3e30) is finite, so
// the fused D · V quotients, which normalise by 1 / |l + v|² (dv_ggx_smith_correlated.hlsl),
// see 1 - NdotH² and NdotH² of a unit h in [0, 1] however short l + v is. A grazing mirror
// (l + v = 2c·n at NdotL = NdotV = c) keeps its lobe down to c = 4.4e-16; the threshold on
// |l + v|² it replaces dropped the lobe below c = 5e-6 (1e-10) and, in the LOW tier (2^-14),
// below c = 3.9e-3, where the lobe is thousands of 1/sr (issue 25). l = -v gives n·(l + v) =
// NdotL + (-NdotL) = 0 exactly, and any l + v below the surface gives a value <= 0: no lobe.
#define PBR_MIN_NDOT_HALF_SUM 8.8817842e-16

// Smallest VdotH (= LdotH) the Kelemen and Cook-Torrance terms divide by: the smallest
// VdotH = |l + v| / 2 the shading model can produce, ½·sqrt(PBR_MIN_HALF_VECTOR_LENGTH_SQUARED)
// = 5e-6. Bounds V_Kelemen by 0.25/VdotH² = 1e10. Cost: none above 5e-6.
#define PBR_MIN_VDOTH 5e-6

// x^s for x >= 0, s >= 0 with a value everywhere (GLSL 4.60 §8.2: pow is undefined for
// x < 0, and for x = 0 with s <= 0). Decided: 0^s = 0 for s > 0 (the limit), 0^0 = 1 (the
// usual convention, so a Blinn-Phong lobe of power 0 is uniform); x <= 0 or NaN counts as
// 0. The base is floored at PBR_FLT_MIN so a denormal x flushed to 0 never reaches log2.
// Cost: none for x >= 2^-126 (bit-identical pow); x in (0, 2^-126) is raised as 2^-126.
// s < 0 counts as 0 (a negative power would exceed 1 and reach +Inf at x = 0).
float pbr_pow_safe(float x, float s) {
    s = max(s, 0.0);
    float p = pow(max(x, PBR_FLT_MIN), s);
    return x > 0.0 ? p : (s > 0.0 ? 0.0 : 1.0);
}

// NaN and negatives -> 0, +Inf and values above hi -> hi, by an ordered comparison used as a
// select (see the header: never min/max on a NaN). Decided: NaN is black (a failed sample;
// black neither blooms nor spreads through temporal filters), +Inf is hi (an infinitely
// bright light is as bright as the output can be). Bit-identical on [0, hi].
float pbr_sanitize(float x, float hi) {
    return min(x > 0.0 ? x : 0.0, hi);
}

// Per component, with the scalar form: the same operations, so the same bits; and portable
// to GLSL ES 1.00 / WebGL 1 (no boolean-vector mix) and to HLSL without a select helper.
float3 pbr_sanitize(float3 x, float hi) {
    return float3(pbr_sanitize(x.x, hi), pbr_sanitize(x.y, hi), pbr_sanitize(x.z, hi));
}

// normalize() that is defined everywhere: the zero vector (a point light at the shaded
// point, a degenerate tangent frame) returns the zero vector (decided: no direction, so
// no light: NdotL = 0), and so does a vector whose components are all below PBR_FLT_MIN
// (denormals: GPUs may flush them, so their direction is not portable). Tiny and huge
// vectors (1e-30, a camera 1e30 away) normalise correctly because the vector is first
// scaled by its largest component, so dot(v, v) can neither underflow nor overflow.
// Finite inputs. Cost: one extra rounding per component (<= 1 ulp more than normalize()).
// GLSL only bounds the error of a / b for |b| in [2^-126, 2^126] (GLSL 4.60 §4.7.1), and
// NVIDIA's compiler does divide as a * (1/b): for m > 2^126, 1/m is a denormal, flushed to 0,
// and s came out 0 and the result NaN (seen on an H200, driver 580). Above
// PBR_SAFE_NORMALIZE_HUGE both are first scaled by 2^-4 (exact: powers of two), which keeps
// the divisor inside the range; below it the scale is 1 and the result is unchanged.
// Branch-free (the zero vector selected at the end, not returned early): a program that
// inlines it in more than one place with the same input (the anisotropic tangent in the
// environment's and each light's lighting call) then shares one evaluation; the early return
// kept a copy per call (benchmarks/whole_program_cost.py, anisotropy with one light and an
// environment: 684 -> 638 RDNA3 instructions). The selected values are the same.
#define PBR_SAFE_NORMALIZE_HUGE 4.2535296e37  // 2^125
float3 pbr_safe_normalize(float3 v) {
    float m = pbr_max3(abs(v));
    float k = m > PBR_SAFE_NORMALIZE_HUGE ? 0.0625 : 1.0;
    float3 s = (v * k) / (m * k);  // largest component exactly ±1: 1 <= dot(s, s) <= 3
    float3 unit = s * rsqrt(dot(s, s));
    return m >= PBR_FLT_MIN ? unit : ((float3)(0.0));  // below: no direction (see above)
}

// 1 - (a·b)² for unit a, b without cancellation: |a × b|² (Lagrange's identity). Near
// a·b = 1, 1 - (a·b)² computed from a rounded cosine loses everything below the cosine's
// absolute error (~1e-7 in float32, ~5e-4 in half), while each component of a × b carries
// an error relative to |a × b| itself (Guy & Agopian, "Physically Based Rendering in
// Filament", §4.4.1, for mediump). Where a·b <= 0 it returns 1, the value for a cosine
// clamped to 0 (h below the surface: otherwise h = -n would give 0 and D_GGX 1/0).
float pbr_one_minus_dot2(float3 a, float3 b) {
    float3 c = cross(a, b);
    return dot(a, b) > 0.0 ? dot(c, c) : 1.0;
}

// |x|² + PBR_FLT_MIN: a squared length that is never 0, so 1 / |x|² <= 2^126 stays finite
// (pbr_brdf_standard: l = -v, where l + v = 0 exactly). Written as a chain of
// multiply-adds that starts from PBR_FLT_MIN, so a compiler that contracts a * b + c (GLSL
// 4.60 §4.7.1 allows it outside `precise`; RADV/ACO does) pays nothing for the floor: the
// dot product's first multiply becomes a fused multiply-add. Cost in accuracy: for
// |x|² >= 2^-100 the floor is below half an ulp of the result (2^-124), so it changes
// nothing but the order of the roundings.
float pbr_length2_nonzero(float3 x) {
    return x.x * x.x + (x.y * x.y + (x.z * x.z + PBR_FLT_MIN));
}

#endif // PBR_COMMON_GUARDS_HLSL
