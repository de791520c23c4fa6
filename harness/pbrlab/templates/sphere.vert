#version 330 core
// Proxy geometry for one ray-traced sphere: the back faces of its bounding cube, which
// cover the sphere's projection; or, when the camera is inside that cube, a fullscreen
// triangle (u_fullscreen) so no pixel is lost to near-plane clipping.
in vec3 in_position;  // unit cube corners in [-1, 1]^3
uniform mat4 u_view_proj;
uniform vec4 u_sphere;  // xyz centre, w radius
uniform bool u_fullscreen;
void main() {
    if (u_fullscreen) {
        vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
        gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
    } else {
        gl_Position = u_view_proj * vec4(u_sphere.xyz + in_position * u_sphere.w, 1.0);
    }
}
