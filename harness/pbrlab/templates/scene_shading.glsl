// pbrlab harness: scene-level shading shared by the sphere and mesh programs.
// Declares the harness's uniforms (the library itself declares none) and lights one
// surface point with the library's pbr_shade_punctual. Compile-time configuration:
//   PBRLAB_LIGHT_COUNT   number of punctual lights (0..)
//   PBRLAB_ENV_SH        defined when the scene has an environment (SH9 irradiance)
#include "pbr/pbr.glsl"

#define PBRLAB_LIGHT_DIRECTIONAL 0
#define PBRLAB_LIGHT_POINT 1
#define PBRLAB_LIGHT_SPOT 2

// Lights: xyz = position (point, spot) or the way light travels (directional); w = type.
#if PBRLAB_LIGHT_COUNT > 0
uniform vec4 u_light_position_type[PBRLAB_LIGHT_COUNT];
uniform vec3 u_light_direction[PBRLAB_LIGHT_COUNT];   // the way light travels (spot)
uniform vec3 u_light_radiance[PBRLAB_LIGHT_COUNT];    // color * intensity
uniform vec3 u_light_range_cones[PBRLAB_LIGHT_COUNT]; // range, cos(outer), 1/(cos(inner)-cos(outer))
#endif
#ifdef PBRLAB_ENV_SH
uniform vec3 u_env_sh[9];  // order-2 SH of the environment radiance (harness/pbrlab/environment.py)
#endif

struct PbrlabSurface {
    vec3 diffuseColor;
    vec3 f0;
    float perceptualRoughness;
    vec3 emission;
    float occlusion;
};

// Smooth range window: (1 - (d/range)^4)^2 clamped, Karis 2013, "Real Shading in Unreal
// Engine 4", eq. 9 (without its +1 in the denominator: pbrlab keeps the inverse square).
float pbrlab_range_window(float distance2, float range) {
    float x = distance2 * distance2 / (range * range * range * range);
    float w = clamp(1.0 - x, 0.0, 1.0);
    return w * w;
}

// Spot cone: smoothstep-free square of a linear ramp in cos(angle) between the outer
// and inner cones (Filament, "Physically Based Rendering in Filament", 5.2.2.2).
float pbrlab_spot_cone(vec3 l, vec3 spotDirection, float cosOuter, float invCosRange) {
    float t = clamp((dot(-l, spotDirection) - cosOuter) * invCosRange, 0.0, 1.0);
    return t * t;
}

// Irradiance E(n) from 9 SH coefficients of radiance: Ramamoorthi & Hanrahan 2001, "An
// Efficient Representation for Irradiance Environment Maps", eq. 13.
#ifdef PBRLAB_ENV_SH
vec3 pbrlab_sh_irradiance(vec3 n) {
    const float c1 = 0.429043, c2 = 0.511664, c3 = 0.743125, c4 = 0.886227, c5 = 0.247708;
    return c1 * u_env_sh[8] * (n.x * n.x - n.y * n.y) + c3 * u_env_sh[6] * n.z * n.z
         + c4 * u_env_sh[0] - c5 * u_env_sh[6]
         + 2.0 * c1 * (u_env_sh[4] * n.x * n.y + u_env_sh[7] * n.x * n.z + u_env_sh[5] * n.y * n.z)
         + 2.0 * c2 * (u_env_sh[3] * n.x + u_env_sh[1] * n.y + u_env_sh[2] * n.z);
}
#endif

vec3 pbrlab_shade(vec3 p, vec3 n, vec3 v, PbrlabSurface s) {
    vec3 color = s.emission;
#if PBRLAB_LIGHT_COUNT > 0
    for (int i = 0; i < PBRLAB_LIGHT_COUNT; ++i) {
        vec3 radiance = u_light_radiance[i];
        vec3 l;
        if (u_light_position_type[i].w == float(PBRLAB_LIGHT_DIRECTIONAL)) {
            l = -u_light_position_type[i].xyz;
        } else {
            vec3 toLight = u_light_position_type[i].xyz - p;
            float d2 = max(dot(toLight, toLight), 1e-8);
            l = toLight * inversesqrt(d2);
            radiance *= pbrlab_range_window(d2, u_light_range_cones[i].x) / d2;
            if (u_light_position_type[i].w == float(PBRLAB_LIGHT_SPOT)) {
                radiance *= pbrlab_spot_cone(l, u_light_direction[i],
                                             u_light_range_cones[i].y, u_light_range_cones[i].z);
            }
        }
        color += pbr_shade_punctual(n, v, l, radiance, s.diffuseColor, s.f0, s.perceptualRoughness);
    }
#endif
#ifdef PBRLAB_ENV_SH
    // Lambert under the environment: diffuseColor/pi * E(n). Specular image-based light
    // arrives with the surface API (issue 4).
    color += s.diffuseColor * PBR_INV_PI * max(pbrlab_sh_irradiance(n), vec3(0.0)) * s.occlusion;
#endif
    return color;
}

// Material uniforms -> surface, for both workflows (Unity's metallic and specular setups).
uniform vec3 u_albedo;
uniform vec3 u_specular;
uniform float u_metallic;
uniform float u_smoothness;
uniform vec3 u_emission;
uniform float u_occlusion;
uniform float u_alpha;
uniform int u_workflow;  // 0 metallic, 1 specular

PbrlabSurface pbrlab_surface(vec3 albedo, float metallic, float smoothness) {
    PbrlabSurface s;
    if (u_workflow == 0) {
        s.diffuseColor = pbr_diffuse_from_metallic(albedo, metallic);
        s.f0 = pbr_f0_from_metallic(albedo, metallic);
    } else {
        s.diffuseColor = pbr_diffuse_from_specular(albedo, u_specular);
        s.f0 = u_specular;
    }
    s.perceptualRoughness = pbr_perceptual_roughness_from_smoothness(smoothness);
    s.emission = u_emission;
    s.occlusion = u_occlusion;
    return s;
}
