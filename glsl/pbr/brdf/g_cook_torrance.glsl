// pbr/brdf/g_cook_torrance.glsl: the original Cook-Torrance geometric attenuation.
//
// Provides: float pbr_G_CookTorrance(float NdotL, float NdotV, float NdotH, float VdotH)
//           float pbr_V_CookTorrance(float NdotL, float NdotV, float NdotH, float VdotH)
// Include:  "pbr/brdf/g_cook_torrance.glsl" (path relative to glsl/)
// Config macros read: none.
//
// Blinn 1977 (V-groove derivation); Cook & Torrance 1982, "A Reflectance Model for
// Computer Graphics", ACM ToG 1(1), the geometrical attenuation factor G:
//   G_CT = min(1, 2 NdotH NdotV / VdotH, 2 NdotH NdotL / LdotH),  LdotH == VdotH.
// V_CookTorrance = G_CT / (4 NdotL NdotV) (the visibility convention). Domain: cosines in
// (0, 1]; VdotH = 0 cannot occur for a half vector of two directions above the surface.
#ifndef PBR_BRDF_G_COOK_TORRANCE_GLSL
#define PBR_BRDF_G_COOK_TORRANCE_GLSL

float pbr_G_CookTorrance(float NdotL, float NdotV, float NdotH, float VdotH) {
    return min(1.0, 2.0 * NdotH * min(NdotV, NdotL) / VdotH);
}

float pbr_V_CookTorrance(float NdotL, float NdotV, float NdotH, float VdotH) {
    return pbr_G_CookTorrance(NdotL, NdotV, NdotH, VdotH) / (4.0 * NdotL * NdotV);
}

#endif // PBR_BRDF_G_COOK_TORRANCE_GLSL
