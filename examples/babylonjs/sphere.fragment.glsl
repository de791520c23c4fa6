// An analytic sphere shaded with pbrlab's LightingStandard (the amalgamated library, which
// main.mjs places above this file, after the DFG hook's declaration). Linear radiance out, as
// pbrlab render's EXR: the environment once (constant radiance u_environment: SH irradiance / pi
// and prefiltered radiance are both that constant), then each directional light, as pbrlab's
// scene programs do (harness/pbrlab/templates/scene_lighting.inc, pbrlab_shade_surface). Where
// u_display is 1 (the page's on-screen view) the radiance is tone mapped and sRGB encoded by
// the library (pbr_tonemap, pbr_linear_to_srgb) for the 8-bit canvas.
#define MAX_LIGHTS 4
uniform vec3 u_camera;                          // the camera's world position
uniform vec4 u_sphere;                          // xyz centre, w radius
uniform vec3 u_albedo;
uniform float u_metallic;
uniform float u_smoothness;
uniform vec3 u_environment;                     // constant radiance (colour x intensity)
uniform int u_light_count;
uniform vec3 u_light_direction[MAX_LIGHTS];     // the way light travels, unit
uniform vec3 u_light_radiance[MAX_LIGHTS];      // colour x intensity
uniform int u_display;
varying vec3 v_world;

// The library's DFG hook (declared above the library by main.mjs): the exported table,
// read at the library's own texture coordinates (docs/tables.md).
vec2 example_dfg_lookup(float NdotV, float perceptualRoughness) {
    return texture(u_dfg, pbr_dfg_lut_uv(NdotV, perceptualRoughness)).rg;
}

void main() {
    // The ray through this pixel and its nearest hit, in pbrlab's cancellation-free form
    // (Haines et al. 2019, Ray Tracing Gems ch. 7, eq. 5, harness/pbrlab/templates/scene_geometry.inc).
    vec3 D = v_world - u_camera;
    float DD = dot(D, D);
    vec3 d = D * inversesqrt(DD);
    vec3 oc = u_camera - u_sphere.xyz;
    vec3 w = cross(oc, D);
    float disc = u_sphere.w * u_sphere.w - dot(w, w) / DD;
    if (disc < 0.0) discard;
    float h = sqrt(disc);
    vec3 n = normalize(cross(D, w) / DD - h * d);

    SurfaceOutputStandard o;
    o.Albedo = u_albedo;
    o.Normal = n;
    o.Emission = vec3(0.0);
    o.Metallic = u_metallic;
    o.Smoothness = u_smoothness;
    o.Occlusion = 1.0;
    o.Alpha = 1.0;
    vec3 v = -d;

    UnityGI gi;
    gi.indirect.diffuse = u_environment;
    gi.indirect.specular = u_environment;
    gi.light.color = vec3(0.0);
    gi.light.dir = n;
    vec4 c = LightingStandard(o, v, gi);
    gi.indirect.diffuse = vec3(0.0);
    gi.indirect.specular = vec3(0.0);
    for (int i = 0; i < MAX_LIGHTS; ++i) {
        if (i >= u_light_count) break;
        gi.light.dir = -u_light_direction[i];
        gi.light.color = u_light_radiance[i];
        c.rgb += LightingStandard(o, v, gi).rgb;
    }
    gl_FragColor = vec4(u_display == 1 ? pbr_linear_to_srgb(pbr_tonemap(c.rgb)) : c.rgb, 1.0);
}
