#version 450
// examples/wgpu: an analytic sphere shaded by pbrlab's LightingStandard, in Vulkan GLSL for
// naga's GLSL front end (render.py: `pbrlab amalgamate` inlines the includes, naga translates the
// one file to WGSL, wgpu draws it). One draw per sphere over a full-screen triangle
// (fullscreen.wgsl). Linear radiance out, as pbrlab render's float image: the environment
// once (a constant radiance: SH irradiance / pi and prefiltered radiance are both that
// constant), then each directional light, as pbrlab's scene programs do
// (harness/pbrlab/templates/scene_lighting.inc) and examples/threejs/sphere.frag.glsl.

// The DFG table (`pbrlab tables`, pbrlab.gpu.engine_tables), uploaded bottom row first so that
// the library's own coordinates (pbr_dfg_lut_uv) read it; bilinear, clamped, no mips.
layout(set = 0, binding = 1) uniform texture2D u_dfg_table;
layout(set = 0, binding = 2) uniform sampler u_dfg_sampler;
#define PBR_DFG_LUT_LOOKUP(NdotV, r) texture(sampler2D(u_dfg_table, u_dfg_sampler), pbr_dfg_lut_uv(NdotV, r)).rg

#include "pbr/pbr.glsl"
#include "pbr/unity/surface_standard.glsl"

#define MAX_LIGHTS 4  // render.py's
// One sphere's draw (std140; render.py packs it): the camera basis of pbrlab.maths.camera
// (camera_frame), the sphere, its material and the scene's lights.
layout(set = 0, binding = 0, std140) uniform SphereDraw {
    vec4 camera_position;                   // xyz
    vec4 camera_forward;                    // xyz unit
    vec4 camera_right;                      // xyz: unit right * tan(fov_y / 2) * aspect
    vec4 camera_up;                         // xyz: unit up * tan(fov_y / 2)
    vec4 viewport_size;                     // xy, pixels
    vec4 sphere;                            // xyz centre, w radius
    vec4 albedo;                            // rgb
    vec4 metallic_smoothness;               // x metallic, y smoothness
    vec4 environment;                       // rgb: constant radiance (colour x intensity)
    ivec4 light_count;                      // x
    vec4 light_direction[MAX_LIGHTS];       // xyz: the way light travels, unit
    vec4 light_radiance[MAX_LIGHTS];        // rgb: colour x intensity
} u;
layout(location = 0) out vec4 radiance;

void main() {
    // WebGPU's fragment position counts rows from the top; pbrlab's from the bottom.
    vec2 fragCoord = vec2(gl_FragCoord.x, u.viewport_size.y - gl_FragCoord.y);
    // The camera ray through the pixel centre and its nearest hit, as pbrlab_sphere_hit
    // (harness/pbrlab/templates/scene_geometry.inc): the cancellation-free form of Haines et
    // al. 2019, Ray Tracing Gems ch. 7, eq. 5.
    vec2 ndc = fragCoord / u.viewport_size.xy * 2.0 - 1.0;
    vec3 D = u.camera_forward.xyz + ndc.x * u.camera_right.xyz + ndc.y * u.camera_up.xyz;
    float DD = dot(D, D);
    vec3 d = D * inversesqrt(DD);
    vec3 oc = u.camera_position.xyz - u.sphere.xyz;
    float b = dot(oc, d);
    vec3 w = cross(oc, D);
    float disc = u.sphere.w * u.sphere.w - dot(w, w) / DD;
    if (disc < 0.0) discard;
    float h = sqrt(disc);
    float t = -b - h;
    if (t <= 0.0) discard;  // this example keeps the camera outside its spheres
    vec3 n = normalize(cross(D, w) / DD - h * d);

    SurfaceOutputStandard o;
    o.Albedo = u.albedo.rgb;
    o.Normal = n;
    o.Emission = vec3(0.0);
    o.Metallic = u.metallic_smoothness.x;
    o.Smoothness = u.metallic_smoothness.y;
    o.Occlusion = 1.0;
    o.Alpha = 1.0;
    vec3 v = -d;

    UnityGI gi;
    gi.indirect.diffuse = u.environment.rgb;
    gi.indirect.specular = u.environment.rgb;
    gi.light.color = vec3(0.0);
    gi.light.dir = n;
    vec4 c = LightingStandard(o, v, gi);
    gi.indirect.diffuse = vec3(0.0);
    gi.indirect.specular = vec3(0.0);
    for (int i = 0; i < MAX_LIGHTS; ++i) {
        if (i >= u.light_count.x) break;
        gi.light.dir = -u.light_direction[i].xyz;
        gi.light.color = u.light_radiance[i].rgb;
        c.rgb += LightingStandard(o, v, gi).rgb;
    }
    radiance = vec4(c.rgb, 1.0);
    gl_FragDepth = t / (t + 1.0);  // nearer spheres in front: any increasing map of t to [0, 1)
}
