#version 330 core
in vec3 in_position;
in vec3 in_normal;
in vec2 in_uv;
in vec4 in_tangent;  // xyz tangent, w handedness of the bitangent
in vec2 in_uv1;      // second UV set (glTF TEXCOORD_1; the first set where a mesh has one)
in vec4 in_color;    // vertex colour (glTF COLOR_0; white where a mesh has none)
uniform mat4 u_model;
uniform mat3 u_normal_matrix;
uniform mat4 u_view_proj;
out vec3 v_position;
out vec3 v_normal;
out vec2 v_uv;
out vec4 v_tangent;
out vec2 v_uv1;
out vec4 v_color;
void main() {
    vec4 world = u_model * vec4(in_position, 1.0);
    v_position = world.xyz;
    v_normal = u_normal_matrix * in_normal;
    v_tangent = vec4(mat3(u_model) * in_tangent.xyz, in_tangent.w);
    v_uv = in_uv;
    v_uv1 = in_uv1;
    v_color = in_color;
    gl_Position = u_view_proj * world;
}
