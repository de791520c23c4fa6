#version 330 core
// One analytic sphere, ray-traced per pixel (exact normals), shaded through a Unity-style
// surface function. UVs are the equirectangular coordinates of the normal.
//@DEFINES
#include "scene_shading.glsl"
#include "camera_ray.glsl"
//@SURFACE

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
    Input IN;
    IN.uv = pbr_equirect_uv(n);
    IN.worldPos = p;
    IN.worldNormal = n;
    IN.viewDir = -d;
    PbrlabSurfaceOutput o = pbrlab_default_output();
    surf(IN, o);
#if PBR_ALPHA_MODE == PBR_ALPHA_MODE_CUTOUT
    if (o.Alpha < u_alpha_cutoff) discard;  // PBRLAB_ALPHA is always on in cutout mode
#endif
    float phi = 2.0 * PBR_PI * IN.uv.x;  // tangent along increasing u (pbr_equirect_direction)
    o.Normal = pbrlab_tangent_to_world_normal(o.Normal, n, vec4(cos(phi), 0.0, sin(phi), 1.0));
    vec4 c = pbrlab_shade_surface(o, p, -d);
    out_radiance = vec4(pbrlab_target_radiance(c.rgb), pbrlab_output_alpha(c));
    vec4 clip = u_view_proj * vec4(p, 1.0);
    gl_FragDepth = clamp(clip.z / clip.w * 0.5 + 0.5, 0.0, 1.0);
}
