#version 330 core
// A rasterised mesh shaded through a Unity-style surface function (default_surface.glsl
// or the material's own file, included as PBRLAB_SURFACE).
//@DEFINES
#include "scene_shading.glsl"
#include "camera_ray.glsl"
//@SURFACE

in vec3 v_position;
in vec3 v_normal;
in vec2 v_uv;
in vec4 v_tangent;
out vec4 out_radiance;

void main() {
    vec3 n = normalize(v_normal);
    Input IN;
    IN.uv = v_uv;
    IN.worldPos = v_position;
    IN.worldNormal = n;
    IN.viewDir = normalize(u_camera_position - v_position);
    PbrlabSurfaceOutput o = pbrlab_default_output();
    surf(IN, o);
#if PBR_ALPHA_MODE == PBR_ALPHA_MODE_CUTOUT
    if (o.Alpha < u_alpha_cutoff) discard;  // PBRLAB_ALPHA is always on in cutout mode
#endif
    o.Normal = pbrlab_tangent_to_world_normal(o.Normal, n, v_tangent);
    vec4 c = pbrlab_shade_surface(o, v_position, IN.viewDir);
    out_radiance = vec4(pbrlab_target_radiance(c.rgb), pbrlab_output_alpha(c));
}
