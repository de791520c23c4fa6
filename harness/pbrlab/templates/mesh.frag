#version 330 core
// A rasterised mesh. Texture slots are compiled in only when the material has them:
//   PBRLAB_ALBEDO_MAP               sRGB colour texture (hardware decode), multiplies albedo
//   PBRLAB_METALLIC_SMOOTHNESS_MAP  linear data texture: R metallic, A smoothness (Unity)
//@DEFINES
#include "scene_shading.glsl"
#include "camera_ray.glsl"

in vec3 v_position;
in vec3 v_normal;
in vec2 v_uv;
in vec4 v_tangent;
#ifdef PBRLAB_ALBEDO_MAP
uniform sampler2D u_albedo_map;
#endif
#ifdef PBRLAB_METALLIC_SMOOTHNESS_MAP
uniform sampler2D u_metallic_smoothness_map;
#endif
out vec4 out_radiance;

void main() {
    vec3 n = normalize(v_normal);
    vec3 v = normalize(u_camera_position - v_position);
    vec3 albedo = u_albedo;
    float metallic = u_metallic;
    float smoothness = u_smoothness;
#ifdef PBRLAB_ALBEDO_MAP
    albedo *= texture(u_albedo_map, v_uv).rgb;
#endif
#ifdef PBRLAB_METALLIC_SMOOTHNESS_MAP
    vec4 ms = texture(u_metallic_smoothness_map, v_uv);
    metallic *= ms.r;
    smoothness *= ms.a;
#endif
    PbrlabSurface s = pbrlab_surface(albedo, metallic, smoothness);
    out_radiance = vec4(pbrlab_shade(v_position, n, v, s), u_alpha);
}
