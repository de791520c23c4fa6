// The bounding mesh of an analytic sphere: its world position, from which sphere.frag.glsl
// casts the pixel's camera ray. (three.js's ShaderMaterial supplies modelMatrix, viewMatrix,
// projectionMatrix and position.)
out vec3 v_world;

void main() {
    vec4 world = modelMatrix * vec4(position, 1.0);
    v_world = world.xyz;
    gl_Position = projectionMatrix * viewMatrix * world;
}
