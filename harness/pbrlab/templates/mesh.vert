#version 330 core
//@DEFINES
in vec3 in_position;
in vec3 in_normal;
in vec2 in_uv;
in vec4 in_tangent;  // xyz tangent, w handedness of the bitangent
in vec2 in_uv1;      // second UV set (glTF TEXCOORD_1; the first set where a mesh has one)
in vec4 in_color;    // vertex colour (glTF COLOR_0; white where a mesh has none)
#ifdef PBRLAB_INSTANCED  // one instanced draw (instanced_draws.py): the matrices per instance
in mat4 in_model;
in mat3 in_normal_matrix;
#define PBRLAB_MODEL in_model
#define PBRLAB_NORMAL_MATRIX in_normal_matrix
#else
uniform mat4 u_model;
uniform mat3 u_normal_matrix;
#define PBRLAB_MODEL u_model
#define PBRLAB_NORMAL_MATRIX u_normal_matrix
#endif
uniform mat4 u_view_proj;
out vec3 v_position;
out vec3 v_normal;
out vec2 v_uv;
out vec4 v_tangent;
out vec2 v_uv1;
out vec4 v_color;
void main() {
    vec4 world = PBRLAB_MODEL * vec4(in_position, 1.0);
    v_position = world.xyz;
    v_normal = PBRLAB_NORMAL_MATRIX * in_normal;
    v_tangent = vec4(mat3(PBRLAB_MODEL) * in_tangent.xyz, in_tangent.w);
    v_uv = in_uv;
    v_uv1 = in_uv1;
    v_color = in_color;
    gl_Position = u_view_proj * world;
}
