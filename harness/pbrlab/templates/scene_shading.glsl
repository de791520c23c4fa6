// pbrlab harness: scene-level shading shared by the sphere and mesh programs. Declares
// the harness's resources (the library declares none), builds Unity's UnityGI for each
// light and the environment, and shades a surface with the library's LightingStandard /
// LightingStandardSpecular (pbr/unity/surface_standard.glsl). Compile-time configuration:
//   PBRLAB_DIRECTIONAL_COUNT, PBRLAB_POINT_COUNT, PBRLAB_SPOT_COUNT  lights per type
//   PBRLAB_ENV                defined when the scene has an environment
//   PBRLAB_EMISSION, PBRLAB_OCCLUSION, PBRLAB_ALPHA  the material's optional effects
//   PBRLAB_FULL               the runtime-branching program (harness/pbrlab/features.py)
//   PBRLAB_WORKFLOW_SPECULAR  defined for the specular workflow (else metallic)
//   PBRLAB_HDR_HALF           defined when the float target is RGBA16F
//   PBR_QUALITY, PBR_ALPHA_MODE, PBR_SPECULAR_*, PBR_DIFFUSE: the library's selectors

#ifdef PBRLAB_ENV
uniform sampler2D u_dfg_lut;          // harness/pbrlab/ibl.py dfg_lut: (A, B)
uniform sampler2D u_env_prefiltered;  // GGX-prefiltered equirect mip chain
uniform float u_env_lod_count;
uniform vec3 u_env_sh[9];             // SH9 of the environment radiance
// The library samples no textures itself: this hook hands it the DFG table.
#define PBR_DFG_LUT_LOOKUP(NdotV, perceptualRoughness) texture(u_dfg_lut, vec2(NdotV, perceptualRoughness)).rg
#endif

#include "pbr/pbr.glsl"
#include "pbr/lighting/attenuation.glsl"
#include "pbr/lighting/sh9.glsl"
#include "pbr/ibl/equirect.glsl"
#include "pbr/ibl/importance_sampling.glsl"
#include "pbr/unity/surface_standard.glsl"

#ifdef PBRLAB_WORKFLOW_SPECULAR
#define PbrlabSurfaceOutput SurfaceOutputStandardSpecular
#define PBRLAB_LIGHTING LightingStandardSpecular
#else
#define PbrlabSurfaceOutput SurfaceOutputStandard
#define PBRLAB_LIGHTING LightingStandard
#endif

// What a surface function receives (Unity's Input, with one UV set: IN.uv).
struct Input {
    vec2 uv;
    vec3 worldPos;
    vec3 worldNormal;
    vec3 viewDir;
};

// Punctual lights, one array set per type. Specialised programs size each type to the
// scene's count (a type the scene lacks compiles to nothing); the full program
// (PBRLAB_FULL) holds PBRLAB_*_COUNT = capacity and loops to a runtime count instead.
#ifdef PBRLAB_FULL
uniform int u_directional_active;
uniform int u_point_active;
uniform int u_spot_active;
#define PBRLAB_DIRECTIONAL_ACTIVE u_directional_active
#define PBRLAB_POINT_ACTIVE u_point_active
#define PBRLAB_SPOT_ACTIVE u_spot_active
#else
#define PBRLAB_DIRECTIONAL_ACTIVE PBRLAB_DIRECTIONAL_COUNT
#define PBRLAB_POINT_ACTIVE PBRLAB_POINT_COUNT
#define PBRLAB_SPOT_ACTIVE PBRLAB_SPOT_COUNT
#endif

#if PBRLAB_DIRECTIONAL_COUNT > 0
uniform vec3 u_directional_direction[PBRLAB_DIRECTIONAL_COUNT];  // the way light travels
uniform vec3 u_directional_radiance[PBRLAB_DIRECTIONAL_COUNT];   // color * intensity
#endif
#if PBRLAB_POINT_COUNT > 0
uniform vec3 u_point_position[PBRLAB_POINT_COUNT];
uniform vec3 u_point_radiance[PBRLAB_POINT_COUNT];
uniform float u_point_range[PBRLAB_POINT_COUNT];
#endif
#if PBRLAB_SPOT_COUNT > 0
uniform vec3 u_spot_position[PBRLAB_SPOT_COUNT];
uniform vec3 u_spot_direction[PBRLAB_SPOT_COUNT];                // the way light travels
uniform vec3 u_spot_radiance[PBRLAB_SPOT_COUNT];
uniform float u_spot_range[PBRLAB_SPOT_COUNT];
uniform vec2 u_spot_cone[PBRLAB_SPOT_COUNT];                     // cos(outer), 1/(cos(inner)-cos(outer))
#endif

// A light at a position: direction from p, and radiance with inverse-square falloff.
UnityLight pbrlab_positional_light(vec3 position, vec3 radiance, float range, vec3 p) {
    UnityLight light;
    vec3 toLight = position - p;
    float d2 = dot(toLight, toLight);
    light.dir = toLight * inversesqrt(max(d2, PBR_MIN_LIGHT_DISTANCE_SQUARED));
    light.color = radiance * pbr_distance_attenuation(d2, range);
    return light;
}

// The environment's light: irradiance / pi from SH9, prefiltered radiance along the
// mirror direction at the mip of this roughness. Unoccluded (LightingStandard applies
// the surface's Occlusion).
UnityIndirect pbrlab_indirect(vec3 n, vec3 v, float perceptualRoughness) {
    UnityIndirect indirect;
    indirect.diffuse = vec3(0.0);
    indirect.specular = vec3(0.0);
#ifdef PBRLAB_ENV
    indirect.diffuse = max(pbr_sh9_irradiance(u_env_sh, n), vec3(0.0)) * PBR_INV_PI;
    float lod = pbr_ibl_lod_from_perceptual_roughness(
        pbr_clamp_perceptual_roughness(perceptualRoughness), u_env_lod_count);
    indirect.specular = textureLod(u_env_prefiltered, pbr_equirect_uv(reflect(-v, n)), lod).rgb;
#endif
    return indirect;
}

// The surface lit by the environment (once) and every light, type by type, plus its
// emission. The order of the sums is the same in specialised and full programs.
vec4 pbrlab_shade_surface(PbrlabSurfaceOutput o, vec3 p, vec3 v) {
    UnityGI gi;
    gi.indirect = pbrlab_indirect(o.Normal, v, SmoothnessToPerceptualRoughness(o.Smoothness));
    gi.light.color = vec3(0.0);
    gi.light.dir = o.Normal;
    vec4 c = PBRLAB_LIGHTING(o, v, gi);
    gi.indirect.diffuse = vec3(0.0);
    gi.indirect.specular = vec3(0.0);
#if PBRLAB_DIRECTIONAL_COUNT > 0
    for (int i = 0; i < PBRLAB_DIRECTIONAL_ACTIVE; ++i) {
        gi.light.dir = -u_directional_direction[i];
        gi.light.color = u_directional_radiance[i];
        c.rgb += PBRLAB_LIGHTING(o, v, gi).rgb;
    }
#endif
#if PBRLAB_POINT_COUNT > 0
    for (int i = 0; i < PBRLAB_POINT_ACTIVE; ++i) {
        gi.light = pbrlab_positional_light(u_point_position[i], u_point_radiance[i], u_point_range[i], p);
        c.rgb += PBRLAB_LIGHTING(o, v, gi).rgb;
    }
#endif
#if PBRLAB_SPOT_COUNT > 0
    for (int i = 0; i < PBRLAB_SPOT_ACTIVE; ++i) {
        gi.light = pbrlab_positional_light(u_spot_position[i], u_spot_radiance[i], u_spot_range[i], p);
        gi.light.color *= pbr_spot_attenuation(gi.light.dir, u_spot_direction[i],
                                               u_spot_cone[i].x, u_spot_cone[i].y);
        c.rgb += PBRLAB_LIGHTING(o, v, gi).rgb;
    }
#endif
#ifdef PBRLAB_EMISSION
    c.rgb += o.Emission;
#endif
    return c;
}

PbrlabSurfaceOutput pbrlab_default_output() {
    PbrlabSurfaceOutput o;
    o.Albedo = vec3(0.0);
    o.Normal = vec3(0.0, 0.0, 1.0);  // tangent space: the interpolated normal
    o.Emission = vec3(0.0);
#ifdef PBRLAB_WORKFLOW_SPECULAR
    o.Specular = vec3(0.0);
#else
    o.Metallic = 0.0;
#endif
    o.Smoothness = 0.0;
    o.Occlusion = 1.0;
    o.Alpha = 1.0;
    return o;
}

// Tangent-space normal (what a surface function writes) -> world space, Gram-Schmidt
// against the interpolated normal (Lengyel 2001; bitangent sign in tangent.w).
vec3 pbrlab_tangent_to_world_normal(vec3 tangentNormal, vec3 n, vec4 tangent) {
    vec3 t = tangent.xyz - n * dot(n, tangent.xyz);
    float tl = dot(t, t);
    t = tl > 1e-12 ? t * inversesqrt(tl) : pbr_tangent_to_world(vec3(1.0, 0.0, 0.0), n);
    vec3 b = cross(n, t) * (tangent.w < 0.0 ? -1.0 : 1.0);
    return normalize(mat3(t, b, n) * tangentNormal);
}

// What the float target stores: radiance, clamped to the largest half (PBR_HALF_MAX) when
// the target is RGBA16F (PBRLAB_HDR_HALF), where a larger value would become +Inf.
vec3 pbrlab_target_radiance(vec3 c) {
#ifdef PBRLAB_HDR_HALF
    return pbr_sanitize(c, PBR_HALF_MAX);
#else
    return c;
#endif
}

// The render target's alpha: coverage for opaque and cutout, the blend weight otherwise.
float pbrlab_output_alpha(vec4 shaded) {
#if PBR_ALPHA_MODE == PBR_ALPHA_MODE_OPAQUE || PBR_ALPHA_MODE == PBR_ALPHA_MODE_CUTOUT
    return 1.0;
#else
    return shaded.a;
#endif
}

#if PBR_ALPHA_MODE == PBR_ALPHA_MODE_CUTOUT
uniform float u_alpha_cutoff;
#endif
