#version 330 core
// A rasterised mesh shaded through a Unity-style surface function (default_surface.inc or
// the material's own file). The work is in the shared surface_pixel.inc; mesh.hlsl is the
// HLSL twin of this entry point.
//@DEFINES
#include "scene_shading.glsl"
//@SURFACE
#include "surface_pixel.inc"

in vec3 v_position;
in vec3 v_normal;
in vec2 v_uv;
in vec2 v_uv1;
in vec4 v_color;
in vec4 v_tangent;
out vec4 out_radiance;

void main() {
    vec3 normal = v_normal;
    vec4 tangent = pbrlab_facing_tangent(gl_FrontFacing, normal, v_tangent);
    out_radiance = pbrlab_surface_pixel(pbrlab_mesh_input(v_position, normal, v_uv, v_uv1, v_color), tangent);
}
