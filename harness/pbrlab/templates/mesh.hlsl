// A rasterised mesh shaded through a Unity-style surface function: the HLSL twin of
// mesh.frag (the work is in the shared surface_pixel.inc). The inputs keep mesh.vert's
// output names, which spirv-cross keeps, so the GLSL vertex stage links to this one.
//@DEFINES
#include "scene_shading.hlsl"
//@SURFACE
#include "surface_pixel.inc"

float4 main(float4 position : SV_Position, float3 v_position : TEXCOORD0, float3 v_normal : TEXCOORD1,
            float2 v_uv : TEXCOORD2, float4 v_tangent : TEXCOORD3, float2 v_uv1 : TEXCOORD4,
            float4 v_color : TEXCOORD5, bool front : SV_IsFrontFace) : SV_Target0 {
    float3 normal = v_normal;
    float4 tangent = pbrlab_facing_tangent(front, normal, v_tangent);
    return pbrlab_surface_pixel(pbrlab_mesh_input(v_position, normal, v_uv, v_uv1, v_color), tangent);
}
