// The bounding mesh of an analytic sphere: its world position, from which sphere.fragment.glsl
// casts the pixel's camera ray. Babylon.js's dialect (attribute, varying), which its WebGL2
// shader processor turns into GLSL ES 3.00; the ShaderMaterial binds world and viewProjection.
precision highp float;
attribute vec3 position;
uniform mat4 world;
uniform mat4 viewProjection;
varying vec3 v_world;

void main() {
    vec4 w = world * vec4(position, 1.0);
    v_world = w.xyz;
    gl_Position = viewProjection * w;
}
