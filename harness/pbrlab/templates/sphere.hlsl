// One analytic sphere, ray-traced per pixel, shaded through a Unity-style surface function:
// the HLSL twin of sphere.frag (the work is in the shared surface_pixel.inc). Compiled by
// glslang's HLSL front end and spirv-cross (harness/pbrlab/gpu/programs.py); SV_Position
// arrives as GL's gl_FragCoord (lower-left origin), so the camera ray is the GLSL one.
//@DEFINES
#include "scene_shading.hlsl"
//@SURFACE
#include "surface_pixel.inc"

uniform float4x4 u_view_proj;

// The pixel's radiance and depth, the sphere shaded through the window position `at`.
void pbrlab_sphere_pixel(float2 at, out float4 radiance, out float depth) {
    Input IN = pbrlab_sphere_input(at);
    radiance = pbrlab_surface_pixel(IN, pbrlab_sphere_tangent(IN.uv));
    float4 clip = mul(u_view_proj, float4(IN.worldPos, 1.0));
    depth = clamp(clip.z / clip.w * 0.5 + 0.5, 0.0, 1.0);
}

#ifdef PBRLAB_SAMPLES
// Antialiased: also the sphere's own coverage of the samples (scene_geometry.inc), as
// SV_Coverage (spirv-cross's gl_SampleMask: programs.cross_version).
void main(float4 position : SV_Position, out float4 radiance : SV_Target0, out float depth : SV_Depth,
          out uint coverage : SV_Coverage) {
    float2 at;
    coverage = uint(pbrlab_sphere_coverage(position.xy, at));
    pbrlab_sphere_pixel(at, radiance, depth);
}
#else
void main(float4 position : SV_Position, out float4 radiance : SV_Target0, out float depth : SV_Depth) {
    pbrlab_sphere_pixel(position.xy, radiance, depth);
}
#endif
