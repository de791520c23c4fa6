#version 330 core
// The pyrender cross-check of glTF files (harness/pbrlab/checking/pyrender/check.py): a mesh's
// material read by pbrlab's default surface (the one glTF mapping, default_surface.inc)
// and lit as pyrender 0.1.45's mesh.frag lights it (templates/pyrender_brdf.inc; point
// lights I / d^2 with no range window, l. 377-389; spot lights the squared linear ramp
// in cos, l. 392-406, pbr_spot_attenuation's form), emission as pyrender adds it
// (emissive texture x factor, times the factor again: l. 436-440), then pyrender's
// display encode clamp(pow(c, 1/2.2)) (l. 446) before blending, as pyrender blends its
// 8-bit target. The caller decodes with pow 2.2. Not covered: occlusion maps (pyrender
// scales direct light by them) and normal scale (pyrender ignores it).
//@DEFINES
#include "scene_shading.glsl"
// pyrender uploads colour textures as plain RGBA8 and decodes sRGB after filtering, with
// the exact piecewise curve (mesh.frag l. 150-162); the caller uploads them linear.
#define PBRLAB_SAMPLE_COLOR_TEX2D(name, uv) pyr_srgb_to_linear(PBRLAB_SAMPLE_TEX2D(name, uv))
vec4 pyr_srgb_to_linear(vec4 encoded) {
    return vec4(pbr_srgb_to_linear(encoded.rgb), encoded.a);
}
//@SURFACE
#include "surface_pixel.inc"
#include "pyrender_brdf.inc"

in vec3 v_position;
in vec3 v_normal;
in vec2 v_uv;
in vec2 v_uv1;
in vec4 v_color;
in vec4 v_tangent;
out vec4 out_radiance;

#define PYR_GAMMA 2.2  // mesh.frag l. 446

void main() {
    Input IN = pbrlab_mesh_input(v_position, v_normal, v_uv, v_uv1, v_color);
    PbrlabSurfaceOutput o = pbrlab_default_output();
    surf(IN, o);
#if PBR_ALPHA_MODE == PBR_ALPHA_MODE_CUTOUT
    if (o.Alpha < u_alpha_cutoff) discard;
#endif
    vec3 n = pbrlab_tangent_to_world_normal(o.Normal, IN.worldNormal, v_tangent);
    vec3 v = IN.viewDir;
    float roughness = 1.0 - o.Smoothness;
    vec3 c = vec3(0.0);
#if PBRLAB_DIRECTIONAL_COUNT > 0
    for (int i = 0; i < PBRLAB_DIRECTIONAL_COUNT; ++i)
        c += pyr_direct(n, v, -u_directional_direction[i], u_directional_radiance[i], o.Albedo, o.Metallic, roughness);
#endif
#if PBRLAB_POINT_COUNT > 0
    for (int i = 0; i < PBRLAB_POINT_COUNT; ++i) {
        vec3 toLight = u_point_position[i] - IN.worldPos;
        float d2 = dot(toLight, toLight);
        c += pyr_direct(n, v, normalize(toLight), u_point_radiance[i] / d2, o.Albedo, o.Metallic, roughness);
    }
#endif
#if PBRLAB_SPOT_COUNT > 0
    for (int i = 0; i < PBRLAB_SPOT_COUNT; ++i) {
        vec3 toLight = u_spot_position[i] - IN.worldPos;
        float d2 = dot(toLight, toLight);
        vec3 l = normalize(toLight);
        float cone = pbr_spot_attenuation(l, u_spot_direction[i], u_spot_cone[i].x, u_spot_cone[i].y);
        c += pyr_direct(n, v, l, u_spot_radiance[i] * cone / d2, o.Albedo, o.Metallic, roughness);
    }
#endif
#ifdef PBRLAB_EMISSION
    c += o.Emission * u_emission;
#endif
    float alpha = 1.0;
#if PBR_ALPHA_MODE == PBR_ALPHA_MODE_FADE
    alpha = o.Alpha;
#endif
    out_radiance = clamp(vec4(pow(max(c, vec3(0.0)), vec3(1.0 / PYR_GAMMA)), alpha), 0.0, 1.0);
}
