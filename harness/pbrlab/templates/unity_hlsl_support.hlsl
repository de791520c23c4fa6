// pbrlab harness, HLSL only: Unity's Direct3D 9-style sampler names (HLSLSupport.cginc) for
// glslang's HLSL front end, included before a surface shader's CGPROGRAM. A `sampler2D`,
// `sampler3D` or `samplerCUBE` is a texture object; tex2D/texCUBE sample it with one shared sampler state,
// which glslang's --auto-sampled-textures combines into each texture (the GL texture's own
// filtering applies). Inside Unity its own definitions stand.
#ifndef PBRLAB_UNITY_HLSL_SUPPORT
#define PBRLAB_UNITY_HLSL_SUPPORT
SamplerState pbrlab_unity_sampler;
// An argument that expands to nothing: a one-parameter macro called with empty parentheses
// (``TRANSFER_SHADOW()``, one empty argument in C and for FXC) is given it for glslang, which
// counts no argument there (importers/unity/empty_arguments.py).
#define PBRLAB_EMPTY_ARGUMENT
#define sampler2D Texture2D
#define samplerCUBE TextureCube
#define tex2D(t, uv) (t).Sample(pbrlab_unity_sampler, (uv))
#define tex2Dlod(t, uv) (t).SampleLevel(pbrlab_unity_sampler, (uv).xy, (uv).w)
#define tex2Dbias(t, uv) (t).SampleBias(pbrlab_unity_sampler, (uv).xy, (uv).w)
#define tex2Dproj(t, uv) (t).Sample(pbrlab_unity_sampler, (uv).xy / (uv).w)
#define tex2Dgrad(t, uv, dx, dy) (t).SampleGrad(pbrlab_unity_sampler, (uv), (dx), (dy))
#define texCUBE(t, d) (t).Sample(pbrlab_unity_sampler, (d))
#define texCUBElod(t, d) (t).SampleLevel(pbrlab_unity_sampler, (d).xyz, (d).w)
#define sampler3D Texture3D
#define tex3D(t, uvw) (t).Sample(pbrlab_unity_sampler, (uvw))
#define tex3Dlod(t, uvw) (t).SampleLevel(pbrlab_unity_sampler, (uvw).xyz, (uvw).w)
// HLSL's fmod truncates (x - y trunc(x / y), the sign of x: Direct3D's definition); glslang
// 11.x lowers it to GLSL's floored mod, so -5.5 fmod 2 gave 0.5 instead of -1.5. The Cg
// programs call this one instead (float `%` keeps glslang's lowering: a known difference).
float pbrlab_fmod(float x, float y) { return x - y * trunc(x / y); }
float2 pbrlab_fmod(float2 x, float2 y) { return x - y * trunc(x / y); }
float3 pbrlab_fmod(float3 x, float3 y) { return x - y * trunc(x / y); }
float4 pbrlab_fmod(float4 x, float4 y) { return x - y * trunc(x / y); }
#define fmod pbrlab_fmod
// HLSL's lit(n.l, n.h, m) is (1, max(n.l, 0), (n.l < 0 || n.h < 0) ? 0 : pow(n.h, m), 1)
// (Microsoft's HLSL reference); glslang 11.x lowers its specular term to n.h * m, so the Cg
// programs call this one instead (GLSL: unity_compat/cg_compat.glsl's lit).
float4 pbrlab_lit(float n_dot_l, float n_dot_h, float m) {
    return float4(1.0, max(n_dot_l, 0.0), (n_dot_l < 0.0 || n_dot_h < 0.0) ? 0.0 : pow(n_dot_h, m), 1.0);
}
#define lit pbrlab_lit
// HLSL's `*` of two matrices multiplies component by component (Microsoft's HLSL reference,
// "Per-component math"); glslang 11.x lowers it to the linear-algebra product, so the type pass
// (cg_types.fxc_conversions) writes a matrix `a * b` as this call, one per size.
#define PBRLAB_MATRIX_COMP_MULT(R, C) \
    float##R##x##C pbrlab_matrix_comp_mult(float##R##x##C a, float##R##x##C b) { \
        float##R##x##C m; [unroll] for (int i = 0; i < R; i++) { m[i] = a[i] * b[i]; } return m; }
PBRLAB_MATRIX_COMP_MULT(2, 2) PBRLAB_MATRIX_COMP_MULT(2, 3) PBRLAB_MATRIX_COMP_MULT(2, 4)
PBRLAB_MATRIX_COMP_MULT(3, 2) PBRLAB_MATRIX_COMP_MULT(3, 3) PBRLAB_MATRIX_COMP_MULT(3, 4)
PBRLAB_MATRIX_COMP_MULT(4, 2) PBRLAB_MATRIX_COMP_MULT(4, 3) PBRLAB_MATRIX_COMP_MULT(4, 4)
#define sampler2D_float Texture2D
#define sampler2D_half Texture2D
#define samplerCUBE_float TextureCube
#define samplerCUBE_half TextureCube
#define sampler3D_float Texture3D
#define sampler3D_half Texture3D
// HLSLSupport.cginc's constant-buffer brackets, which Unity includes in every CGPROGRAM: on GL
// a named buffer is plain globals (CBUFFER_START(UnitySceneViewColor) ... CBUFFER_END in a
// program that includes nothing)
#ifndef CBUFFER_START
#define CBUFFER_START(name)
#define CBUFFER_END
#endif
// HLSLSupport.cginc's type of a fragment input with the VPOS semantic, float4 (x, y the pixel's
// window position, as SV_POSITION in a fragment) on every target but Direct3D 9's float2; a
// program that includes nothing declares ``UNITY_VPOS_TYPE screenPos : VPOS``.
#ifndef UNITY_VPOS_TYPE
#define UNITY_VPOS_TYPE float4
#endif
// A surface shader's Input member `float face : VFACE`: the harness fills it (generate.py,
// from the fragment's facing); glslang would take the semantic as its own built-in and drop
// the member from the struct, so the semantic is renamed to a plain one.
#define VFACE PBRLAB_VFACE
// unity_SpecCube0 as texCUBE / texCUBElod / UNITY_SAMPLE_TEXCUBE(_LOD) read it: an object whose
// Sample and SampleLevel are unity_surface.inc's pbrlab_unity_reflection_probe (the URP
// stand-in's Lighting.hlsl, included after this, keeps this one).
#define PBRLAB_UNITY_SPECCUBE0
struct PbrlabUnityReflectionProbe {
    float unused;
    float4 Sample(SamplerState s, float3 direction) { return pbrlab_unity_reflection_probe(direction, 0.0); }
    float4 SampleLevel(SamplerState s, float3 direction, float mip) { return pbrlab_unity_reflection_probe(direction, mip); }
};
static PbrlabUnityReflectionProbe unity_SpecCube0;
SamplerState samplerunity_SpecCube0;
// The second probe reads the same sky (Unity with one probe: weight 1 toward probe 0,
// unity_compat/shader_variables's unity_SpecCube0_BoxMin.w).
static PbrlabUnityReflectionProbe unity_SpecCube1;
#endif
