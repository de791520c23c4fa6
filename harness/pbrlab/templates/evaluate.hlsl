// pbrlab evaluator, HLSL side: one expression per pixel, the twin of evaluate.frag.
// Compiled by glslang's HLSL front end to SPIR-V and by spirv-cross to GLSL 330
// (harness/pbrlab/gpu/hlsl.py), then run by the same evaluator: each input is a Texture2D read
// with Load (texelFetch after the cross-compile: bit-exact, no filtering), bound by name
// (pbrlab_in_<name>, register t<k>) like the GLSL template's samplers; the result goes to
// SV_Target0, the RGBA32F target read back as float32. The pixel position arrives as
// SV_Position; spirv-cross maps it to gl_FragCoord with GL's lower-left origin, so texel
// (x, y) holds element y * width + x in both languages (tests/gpu/hlsl/test_hlsl_evaluator.py).
// Depends on nothing from the library (no shim): it spells float4, not vec4.
//@DEFINES
//@INCLUDES

//@TEXTURES

float4 pbrlab_to_vec4(float x)  { return float4(x, 0.0, 0.0, 0.0); }
float4 pbrlab_to_vec4(float2 x) { return float4(x, 0.0, 0.0); }
float4 pbrlab_to_vec4(float3 x) { return float4(x, 0.0); }
float4 pbrlab_to_vec4(float4 x) { return x; }
float4 pbrlab_to_vec4(int x)    { return float4(float(x), 0.0, 0.0, 0.0); }
float4 pbrlab_to_vec4(uint x)   { return float4(float(x), 0.0, 0.0, 0.0); }
float4 pbrlab_to_vec4(bool x)   { return float4(x ? 1.0 : 0.0, 0.0, 0.0, 0.0); }
int pbrlab_width(float x)  { return 1; }
int pbrlab_width(float2 x) { return 2; }
int pbrlab_width(float3 x) { return 3; }
int pbrlab_width(float4 x) { return 4; }
int pbrlab_width(int x)    { return 1; }
int pbrlab_width(uint x)   { return 1; }
int pbrlab_width(bool x)   { return 1; }

float4 main(float4 pbrlab_position : SV_Position) : SV_Target0 {
    int3 pbrlab_texel = int3(int2(pbrlab_position.xy), 0);
//@FETCHES
#ifdef PBRLAB_PROBE_WIDTH
    return float4(float(pbrlab_width(//@EXPRESSION
    )), 0.0, 0.0, 0.0);
#else
    return pbrlab_to_vec4(//@EXPRESSION
    );
#endif
}
