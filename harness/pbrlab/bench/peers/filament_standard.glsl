// bench/peers/filament_standard.glsl: a peer engine's per-light standard lobe, for the bench's
// cost comparison only (not part of the library; no pbrlab shader includes it).
//
// Provides: vec3 peer_filament_brdf(vec3 n, vec3 v, vec3 l, vec3 diffuseColor, vec3 f0,
//                                   float perceptualRoughness)
//
// The formulas and clamps of Filament's desktop standard model, restated from its
// documentation (Guy & Agopian, "Physically Based Rendering in Filament": §4.4.1 GGX D in
// the 1 - NdotH² form, §4.4.2 height-correlated Smith V, §4.4.3 Schlick F with
// f90 = saturate(50 · 0.33 · dot(f0, 1)) (§4.8.3.2), §4.4.4 Lambert; §4.8.3.3 the minimum
// perceptual roughness 0.045; MIN_N_DOT_V = 1e-4; NoL, NoH and LoH saturated), written for
// this bench: h normalised, no branch, no guard for l = -v. Returns the BRDF without the
// cosine (Filament multiplies (Fd + Fr) by NoL afterwards; pbr_brdf_standard leaves that to
// its caller too), so the two do the same work per light.
#ifndef PBRLAB_BENCH_PEER_FILAMENT_STANDARD_GLSL
#define PBRLAB_BENCH_PEER_FILAMENT_STANDARD_GLSL

float peer_filament_D_GGX(float roughness, float NoH) {
    float oneMinusNoHSquared = 1.0 - NoH * NoH;
    float a = NoH * roughness;
    float k = roughness / (oneMinusNoHSquared + a * a);
    return k * k * (1.0 / 3.14159265358979);
}

float peer_filament_V_SmithGGXCorrelated(float roughness, float NoV, float NoL) {
    float a2 = roughness * roughness;
    float lambdaV = NoL * sqrt((NoV - a2 * NoV) * NoV + a2);
    float lambdaL = NoV * sqrt((NoL - a2 * NoL) * NoL + a2);
    return 0.5 / (lambdaV + lambdaL);
}

vec3 peer_filament_F_Schlick(vec3 f0, float f90, float VoH) {
    float x = 1.0 - VoH;
    float x2 = x * x;
    return f0 + (f90 - f0) * (x2 * x2 * x);
}

vec3 peer_filament_brdf(vec3 n, vec3 v, vec3 l, vec3 diffuseColor, vec3 f0, float perceptualRoughness) {
    float roughness = clamp(perceptualRoughness, 0.045, 1.0);
    roughness *= roughness;
    vec3 h = normalize(v + l);
    float NoV = max(dot(n, v), 1e-4);
    float NoL = clamp(dot(n, l), 0.0, 1.0);
    float NoH = clamp(dot(n, h), 0.0, 1.0);
    float LoH = clamp(dot(l, h), 0.0, 1.0);
    float f90 = clamp(dot(f0, vec3(50.0 * 0.33)), 0.0, 1.0);
    vec3 Fr = (peer_filament_D_GGX(roughness, NoH) * peer_filament_V_SmithGGXCorrelated(roughness, NoV, NoL))
            * peer_filament_F_Schlick(f0, f90, LoH);
    return diffuseColor * (1.0 / 3.14159265358979) + Fr;
}

#endif // PBRLAB_BENCH_PEER_FILAMENT_STANDARD_GLSL
