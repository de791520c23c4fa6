// pbrlab's part of Core RP's Common.hlsl that URP programs reach through URP's Core.hlsl: the
// float classification tests (IsNaN, IsInf, IsFinite and their Any / Sanitize forms), the powers
// of a base known to be positive (PositivePow, SafePositivePow) and SafeDiv's vector forms.
// Written for pbrlab from the names' documented meaning (Core RP 14.0.9 Common.hlsl; Unity's
// own file is under the Unity Companion License and is not copied). Core writes these with its
// TEMPLATE_*_REAL macros (one overload per float width); they are spelled out here, and a vector
// base with a scalar exponent gets its own overload: HLSL splats the scalar to pick the vector
// one, GLSL (the port) has no implicit splat.
#ifndef PBRLAB_CORE_RP_COMMON_MATH_HLSL
#define PBRLAB_CORE_RP_COMMON_MATH_HLSL

// IEEE 754 single: exponent bits all set (0x7F800000) with a zero mantissa is an infinity, with
// any other mantissa a NaN; the sign bit (0x80000000) aside. Tested on the bits, as Core does,
// because FXC folds isnan() away without /Gic.
bool IsNaN(float x) { return (asuint(x) & 0x7FFFFFFFu) > 0x7F800000u; }
bool AnyIsNaN(float2 v) { return IsNaN(v.x) || IsNaN(v.y); }
bool AnyIsNaN(float3 v) { return IsNaN(v.x) || IsNaN(v.y) || IsNaN(v.z); }
bool AnyIsNaN(float4 v) { return IsNaN(v.x) || IsNaN(v.y) || IsNaN(v.z) || IsNaN(v.w); }
bool IsInf(float x) { return (asuint(x) & 0x7FFFFFFFu) == 0x7F800000u; }
bool AnyIsInf(float2 v) { return IsInf(v.x) || IsInf(v.y); }
bool AnyIsInf(float3 v) { return IsInf(v.x) || IsInf(v.y) || IsInf(v.z); }
bool AnyIsInf(float4 v) { return IsInf(v.x) || IsInf(v.y) || IsInf(v.z) || IsInf(v.w); }
// finite: the exponent bits not all set (neither NaN nor infinity)
bool IsFinite(float x) { return (asuint(x) & 0x7F800000u) != 0x7F800000u; }
float SanitizeFinite(float x) { return IsFinite(x) ? x : 0.0; }
// positive and finite, +0 included: the bits below those of +infinity (a set sign bit is above)
bool IsPositiveFinite(float x) { return asuint(x) < 0x7F800000u; }
float SanitizePositiveFinite(float x) { return IsPositiveFinite(x) ? x : 0.0; }

// pow of |base|: the base's sign dropped, for a base the caller knows is >= 0 (pow(0, p > 0) = 0).
float PositivePow(float base, float power) { return pow(abs(base), power); }
float2 PositivePow(float2 base, float2 power) { return pow(abs(base), power); }
float3 PositivePow(float3 base, float3 power) { return pow(abs(base), power); }
float4 PositivePow(float4 base, float4 power) { return pow(abs(base), power); }
float2 PositivePow(float2 base, float power) { return pow(abs(base), float2(power, power)); }
float3 PositivePow(float3 base, float power) { return pow(abs(base), float3(power, power, power)); }
float4 PositivePow(float4 base, float power) { return pow(abs(base), float4(power, power, power, power)); }

// pow of |base| held at least at epsilon, so that a zero base with a zero or negative power is
// finite: FLT_EPS (2^-24) for the float forms (SafePositivePow, SafePositivePow_float), HALF_EPS
// (2^-11, 4.8828125e-4) for the half form.
#define PBRLAB_SAFE_POW_FLT_EPS 5.960464478e-8
#define PBRLAB_SAFE_POW_HALF_EPS 4.8828125e-4
float SafePositivePow(float base, float power) { return pow(max(abs(base), PBRLAB_SAFE_POW_FLT_EPS), power); }
float2 SafePositivePow(float2 base, float2 power) { return pow(max(abs(base), PBRLAB_SAFE_POW_FLT_EPS), power); }
float3 SafePositivePow(float3 base, float3 power) { return pow(max(abs(base), PBRLAB_SAFE_POW_FLT_EPS), power); }
float4 SafePositivePow(float4 base, float4 power) { return pow(max(abs(base), PBRLAB_SAFE_POW_FLT_EPS), power); }
float2 SafePositivePow(float2 base, float power) { return SafePositivePow(base, float2(power, power)); }
float3 SafePositivePow(float3 base, float power) { return SafePositivePow(base, float3(power, power, power)); }
float4 SafePositivePow(float4 base, float power) { return SafePositivePow(base, float4(power, power, power, power)); }
float SafePositivePow_float(float base, float power) { return SafePositivePow(base, power); }
float2 SafePositivePow_float(float2 base, float2 power) { return SafePositivePow(base, power); }
float3 SafePositivePow_float(float3 base, float3 power) { return SafePositivePow(base, power); }
float4 SafePositivePow_float(float4 base, float4 power) { return SafePositivePow(base, power); }
float SafePositivePow_half(float base, float power) { return pow(max(abs(base), PBRLAB_SAFE_POW_HALF_EPS), power); }
float2 SafePositivePow_half(float2 base, float2 power) { return pow(max(abs(base), PBRLAB_SAFE_POW_HALF_EPS), power); }
float3 SafePositivePow_half(float3 base, float3 power) { return pow(max(abs(base), PBRLAB_SAFE_POW_HALF_EPS), power); }
float4 SafePositivePow_half(float4 base, float4 power) { return pow(max(abs(base), PBRLAB_SAFE_POW_HALF_EPS), power); }

// SafeDiv per component (the float form is Core.hlsl's: 1 where numerator equals denominator).
float2 SafeDiv(float2 numer, float2 denom) { return float2(SafeDiv(numer.x, denom.x), SafeDiv(numer.y, denom.y)); }
float3 SafeDiv(float3 numer, float3 denom) {
    return float3(SafeDiv(numer.x, denom.x), SafeDiv(numer.y, denom.y), SafeDiv(numer.z, denom.z));
}
float4 SafeDiv(float4 numer, float4 denom) {
    return float4(SafeDiv(numer.x, denom.x), SafeDiv(numer.y, denom.y), SafeDiv(numer.z, denom.z), SafeDiv(numer.w, denom.w));
}

#endif
