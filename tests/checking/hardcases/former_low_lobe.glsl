// The control of test_rotated_frames.py: issue 25's LOW lobe as it was before issue 35, GGX's
// denominator in the cancelling form 1 - NdotH² (1 - alpha²) with NdotH² = (n·h)² / |h|²,
// times V = 0.5 / n·(l + v), with pbr_brdf_standard's inputs (saturated NdotL, |l + v|² +
// 2^-126, the LOW roughness floor). F = 1 and no diffuse: the lobe D · V alone.
#include "pbr/pbr.glsl"

float former_low_lobe(vec3 n, vec3 v, vec3 l, float perceptualRoughness) {
    float NdotL = clamp(dot(n, l), 0.0, 1.0);
    float nDotHalfSum = NdotL + dot(n, v);
    vec3 halfSum = l + v;
    float h2 = pbr_length2_nonzero(halfSum);
    float alpha = pbr_alpha_from_perceptual_roughness(
        clamp(perceptualRoughness, PBR_MIN_PERCEPTUAL_ROUGHNESS_MEDIUMP, 1.0));
    float a2 = alpha * alpha;
    float cos2 = clamp(nDotHalfSum * nDotHalfSum * (1.0 / h2), 0.0, 1.0);
    float dn = 1.0 - cos2 * (1.0 - a2);
    return (a2 * (0.5 * PBR_INV_PI)) / (dn * dn * nDotHalfSum);
}
