// pbrlab harness: the camera ray through a pixel centre, the same formula as the
// float64 CPU renderer (harness/pbrlab/cpu_render.py, camera_rays).
#ifndef PBRLAB_CAMERA_RAY_GLSL
#define PBRLAB_CAMERA_RAY_GLSL
uniform vec3 u_camera_position;
uniform vec3 u_camera_forward;  // unit
uniform vec3 u_camera_right;    // unit right * tan(fov_y / 2) * aspect
uniform vec3 u_camera_up;       // unit up * tan(fov_y / 2)
uniform vec2 u_viewport_size;
uniform mat4 u_view_proj;

vec3 pbrlab_camera_ray(vec2 fragCoord) {
    vec2 ndc = fragCoord / u_viewport_size * 2.0 - 1.0;
    return normalize(u_camera_forward + ndc.x * u_camera_right + ndc.y * u_camera_up);
}
#endif
