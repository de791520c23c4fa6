#version 330 core
//@EXTENSIONS
// pbrlab evaluator: one expression per fragment. Inputs are fetched bit-exactly from
// float textures with texelFetch (no filtering, no interpolation, nothing the compiler
// can fold); the result is written to an RGBA32F target and read back as float32.
//@DEFINES
//@INCLUDES

//@UNIFORMS
out vec4 pbrlab_result;

vec4 pbrlab_to_vec4(float x) { return vec4(x, 0.0, 0.0, 0.0); }
vec4 pbrlab_to_vec4(vec2 x)  { return vec4(x, 0.0, 0.0); }
vec4 pbrlab_to_vec4(vec3 x)  { return vec4(x, 0.0); }
vec4 pbrlab_to_vec4(vec4 x)  { return x; }
vec4 pbrlab_to_vec4(int x)   { return vec4(float(x), 0.0, 0.0, 0.0); }
vec4 pbrlab_to_vec4(bool x)  { return vec4(x ? 1.0 : 0.0, 0.0, 0.0, 0.0); }
int pbrlab_width(float x) { return 1; }
int pbrlab_width(vec2 x)  { return 2; }
int pbrlab_width(vec3 x)  { return 3; }
int pbrlab_width(vec4 x)  { return 4; }
int pbrlab_width(int x)   { return 1; }
int pbrlab_width(bool x)  { return 1; }

void main() {
    ivec2 pbrlab_texel = ivec2(gl_FragCoord.xy);
//@FETCHES
#ifdef PBRLAB_PROBE_WIDTH
    pbrlab_result = vec4(float(pbrlab_width(//@EXPRESSION
    )));
#else
    pbrlab_result = pbrlab_to_vec4(//@EXPRESSION
    );
#endif
}
