#version 330 core
// One analytic sphere, ray-traced per pixel: exact normals, no tessellation.
//@DEFINES
#include "scene_shading.glsl"
#include "camera_ray.glsl"

uniform vec4 u_sphere;  // xyz centre, w radius
out vec4 out_radiance;

void main() {
    vec3 d = pbrlab_camera_ray(gl_FragCoord.xy);
    // Ray-sphere intersection in the form that avoids cancellation for distant spheres:
    // the discriminant is r^2 - |oc - (oc.d) d|^2 (Haines et al. 2019, "Precision
    // Improvements for Ray/Sphere Intersection", Ray Tracing Gems ch. 7, eq. 5).
    vec3 oc = u_camera_position - u_sphere.xyz;
    float b = dot(oc, d);
    vec3 q = oc - b * d;
    float disc = u_sphere.w * u_sphere.w - dot(q, q);
    if (disc < 0.0) discard;
    float h = sqrt(disc);
    float t = -b - h;
    if (t <= 0.0) t = -b + h;  // camera inside the sphere: its inner surface
    if (t <= 0.0) discard;
    vec3 p = u_camera_position + t * d;
    vec3 n = normalize(p - u_sphere.xyz);
    PbrlabSurface s = pbrlab_surface(u_albedo, u_metallic, u_smoothness);
    out_radiance = vec4(pbrlab_shade(p, n, -d, s), u_alpha);
    vec4 clip = u_view_proj * vec4(p, 1.0);
    gl_FragDepth = clamp(clip.z / clip.w * 0.5 + 0.5, 0.0, 1.0);
}
