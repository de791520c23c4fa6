// examples/wgpu: sphere.frag.glsl's HLSL twin on the library's HLSL ports (hlsl_ports/), for the
// Slang -> WGSL route (render.py --route slang: Slang compiles it with hlsl_ports/ on its include
// path). Same ray, same shading, same bindings; the comments of sphere.frag.glsl apply.

[[vk::binding(1, 0)]] Texture2D<float4> u_dfg_table;
[[vk::binding(2, 0)]] SamplerState u_dfg_sampler;
// No mips: level 0 is what GLSL's texture() reads.
#define PBR_DFG_LUT_LOOKUP(NdotV, r) u_dfg_table.SampleLevel(u_dfg_sampler, pbr_dfg_lut_uv(NdotV, r), 0.0).rg

#include "pbr/pbr.hlsl"
#include "pbr/unity/surface_standard.hlsl"

#define MAX_LIGHTS 4  // render.py's
struct SphereDraw {
    float4 camera_position;
    float4 camera_forward;
    float4 camera_right;
    float4 camera_up;
    float4 viewport_size;
    float4 sphere;
    float4 albedo;
    float4 metallic_smoothness;
    float4 environment;
    int4 light_count;
    float4 light_direction[MAX_LIGHTS];
    float4 light_radiance[MAX_LIGHTS];
};
[[vk::binding(0, 0)]] ConstantBuffer<SphereDraw> u;

struct PixelOut {
    float4 radiance : SV_Target0;
    float depth : SV_Depth;
};

[shader("pixel")]
PixelOut main(float4 fragPosition : SV_Position) {
    float2 fragCoord = float2(fragPosition.x, u.viewport_size.y - fragPosition.y);
    float2 ndc = fragCoord / u.viewport_size.xy * 2.0 - 1.0;
    float3 D = u.camera_forward.xyz + ndc.x * u.camera_right.xyz + ndc.y * u.camera_up.xyz;
    float DD = dot(D, D);
    float3 d = D * rsqrt(DD);
    float3 oc = u.camera_position.xyz - u.sphere.xyz;
    float b = dot(oc, d);
    float3 w = cross(oc, D);
    float disc = u.sphere.w * u.sphere.w - dot(w, w) / DD;
    if (disc < 0.0) discard;
    float h = sqrt(disc);
    float t = -b - h;
    if (t <= 0.0) discard;
    float3 n = normalize(cross(D, w) / DD - h * d);

    SurfaceOutputStandard o;
    o.Albedo = u.albedo.rgb;
    o.Normal = n;
    o.Emission = float3(0.0, 0.0, 0.0);
    o.Metallic = u.metallic_smoothness.x;
    o.Smoothness = u.metallic_smoothness.y;
    o.Occlusion = 1.0;
    o.Alpha = 1.0;
    float3 v = -d;

    UnityGI gi;
    gi.indirect.diffuse = u.environment.rgb;
    gi.indirect.specular = u.environment.rgb;
    gi.light.color = float3(0.0, 0.0, 0.0);
    gi.light.dir = n;
    float4 c = LightingStandard(o, v, gi);
    gi.indirect.diffuse = float3(0.0, 0.0, 0.0);
    gi.indirect.specular = float3(0.0, 0.0, 0.0);
    for (int i = 0; i < MAX_LIGHTS; ++i) {
        if (i >= u.light_count.x) break;
        gi.light.dir = -u.light_direction[i].xyz;
        gi.light.color = u.light_radiance[i].rgb;
        c.rgb += LightingStandard(o, v, gi).rgb;
    }
    PixelOut result;
    result.radiance = float4(c.rgb, 1.0);
    result.depth = t / (t + 1.0);
    return result;
}
