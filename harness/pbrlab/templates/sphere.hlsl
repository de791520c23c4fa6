// One analytic sphere, ray-traced per pixel, shaded through a Unity-style surface function:
// the HLSL twin of sphere.frag (the work is in the shared surface_pixel.inc). Compiled by
// glslang's HLSL front end and spirv-cross (harness/pbrlab/gpu/programs.py); SV_Position
// arrives as GL's gl_FragCoord (lower-left origin), so the camera ray is the GLSL one.
//@DEFINES
#include "scene_shading.hlsl"
//@SURFACE
#include "surface_pixel.inc"

uniform float4x4 u_view_proj;

void main(float4 position : SV_Position, out float4 radiance : SV_Target0, out float depth : SV_Depth) {
    Input IN = pbrlab_sphere_input(position.xy);
    radiance = pbrlab_surface_pixel(IN, pbrlab_sphere_tangent(IN.uv));
    float4 clip = mul(u_view_proj, float4(IN.worldPos, 1.0));
    depth = clamp(clip.z / clip.w * 0.5 + 0.5, 0.0, 1.0);
}
