#version 330 core
// One analytic sphere, ray-traced per pixel (exact normals), shaded through a Unity-style
// surface function (default_surface.inc or the material's own file). The work is in the
// shared surface_pixel.inc; sphere.hlsl is the HLSL twin of this entry point. Antialiased
// (PBRLAB_SAMPLES), it writes the sphere's own coverage of the samples (ARB_sample_shading's
// gl_SampleMask, core in GLSL 400).
//@DEFINES
#ifdef PBRLAB_SAMPLES
#extension GL_ARB_sample_shading : require
#endif
#include "scene_shading.glsl"
//@SURFACE
#include "surface_pixel.inc"

uniform mat4 u_view_proj;
out vec4 out_radiance;

void main() {
    vec2 at = gl_FragCoord.xy;  // where the pixel is shaded: its centre, unless antialiased
#ifdef PBRLAB_SAMPLES
    gl_SampleMask[0] = pbrlab_sphere_coverage(gl_FragCoord.xy, at);  // scene_geometry.inc
#endif
    Input IN = pbrlab_sphere_input(at);
    out_radiance = pbrlab_surface_pixel(IN, pbrlab_sphere_tangent(IN.uv));
    vec4 clip = u_view_proj * vec4(IN.worldPos, 1.0);
    gl_FragDepth = clamp(clip.z / clip.w * 0.5 + 0.5, 0.0, 1.0);
}
