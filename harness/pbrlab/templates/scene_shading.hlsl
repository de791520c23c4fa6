// pbrlab harness, HLSL side: the twin of scene_shading.glsl. What the scene programs need
// that HLSL spells differently from GLSL (textures, a basis change, the library's include
// paths); the shading itself is scene_lighting.inc, shared word for word with the GLSL
// programs and made valid HLSL by the few GLSL spellings defined below (the harness's own:
// the library's HLSL defines no GLSL names). Compile-time
// configuration: see scene_lighting.inc. Globals are HLSL uniforms ($Global cbuffer).

// Textures, as the shared files spell them (GLSL: sampler2D, texture/textureLod).
#define PBRLAB_DECLARE_TEX2D(name) Texture2D name; SamplerState sampler_##name
#define PBRLAB_SAMPLE_TEX2D(name, uv) name.Sample(sampler_##name, uv)
#define PBRLAB_SAMPLE_TEX2D_LOD(name, uv, lod) name.SampleLevel(sampler_##name, uv, lod)
// Cube maps (the prefiltered environment, harness/pbrlab/gpu/ibl.py), read along a direction.
#define PBRLAB_DECLARE_TEXCUBE(name) TextureCube name; SamplerState sampler_##name
#define PBRLAB_SAMPLE_TEXCUBE_LOD(name, dir, lod) name.SampleLevel(sampler_##name, dir, lod)
// The columns t, b, n times v: a tangent-space vector in the world (rows of float3x3).
#define PBRLAB_FROM_BASIS(t, b, n, v) mul(v, float3x3(t, b, n))
// A point of the world through a 4x4 matrix, uploaded as the GLSL programs' (sphere.hlsl's
// depth): homogeneous clip coordinates.
#define PBRLAB_TRANSFORM_POINT(m, p) mul(m, float4(p, 1.0))
// Unity's names for the same (HLSLSupport.cginc, Direct3D 11 path), so a ported surface
// function keeps them; inside Unity its own definitions stand.
#ifndef UNITY_DECLARE_TEX2D
#define UNITY_DECLARE_TEX2D(name) PBRLAB_DECLARE_TEX2D(name)
#endif
#ifndef UNITY_SAMPLE_TEX2D
#define UNITY_SAMPLE_TEX2D(name, uv) PBRLAB_SAMPLE_TEX2D(name, uv)
#endif

// The DFG table (harness/pbrlab/gpu/ibl.py dfg_lut: (A, B) on the warped axes of
// pbr_dfg_lut_uv): the environment's split sum and, for every light, the diffuse-specular
// coupling read it, so it is declared whenever the scene has light (a transmissive material
// sees the scene's transmission copy, light of its own: transmission_scene.inc).
#if defined(PBRLAB_ENV) || defined(PBRLAB_TRANSMISSION) || PBRLAB_DIRECTIONAL_COUNT + PBRLAB_POINT_COUNT + PBRLAB_SPOT_COUNT > 0
PBRLAB_DECLARE_TEX2D(u_dfg_lut);
// The library samples no textures itself: this hook hands it the DFG table, read at the
// texel-centre coordinates of the library's layout (pbr/ibl/environment_brdf.glsl).
#define PBR_DFG_LUT_LOOKUP(NdotV, perceptualRoughness) PBRLAB_SAMPLE_TEX2D(u_dfg_lut, pbr_dfg_lut_uv(NdotV, perceptualRoughness)).rg
#endif

// The sheen albedo table (harness/pbrlab/gpu/sheen_table.py: E on the warped axes of
// pbr_sheen_lut_uv), declared only where the material has a sheen; the layers the
// material lacks are left out of LightingStandardLayers (pbr/unity/surface_layers.glsl).
#ifdef PBRLAB_SHEEN
PBRLAB_DECLARE_TEX2D(u_sheen_lut);
#define PBR_SHEEN_LUT_LOOKUP(NdotV, sheenPerceptualRoughness) PBRLAB_SAMPLE_TEX2D(u_sheen_lut, pbr_sheen_lut_uv(NdotV, sheenPerceptualRoughness)).r
#define PBR_LAYERS_SHEEN 1
#else
#define PBR_LAYERS_SHEEN 0
#endif
#ifdef PBRLAB_CLEARCOAT
#define PBR_LAYERS_CLEARCOAT 1
#else
#define PBR_LAYERS_CLEARCOAT 0
#endif
#ifdef PBRLAB_ANISOTROPY
#define PBR_LAYERS_ANISOTROPY 1
#else
#define PBR_LAYERS_ANISOTROPY 0
#endif
#ifdef PBRLAB_IRIDESCENCE
#define PBR_LAYERS_IRIDESCENCE 1
#else
#define PBR_LAYERS_IRIDESCENCE 0
#endif
#ifdef PBRLAB_TRANSMISSION
#define PBR_LAYERS_TRANSMISSION 1
#else
#define PBR_LAYERS_TRANSMISSION 0
#endif
#ifdef PBRLAB_SPECULAR_F90
#define PBR_LAYERS_SPECULAR_F90 1
#endif
#ifdef PBRLAB_DIELECTRIC_SPECULAR
#define PBR_LAYERS_DIELECTRIC_SPECULAR 1
#endif

// Every normal the scene programs hand the lighting is unit already (surface_pixel.inc builds
// it with pbrlab_tangent_to_world_normal, which normalises): the Unity-named lighting
// functions skip their own normalisation (pbr/unity/surface_standard.glsl).
#define PBR_UNITY_NORMAL_IS_UNIT 1

#include "pbr/pbr.hlsl"
#include "pbr/lighting/attenuation.hlsl"
#include "pbr/lighting/sh9.hlsl"
#include "pbr/ibl/equirect.hlsl"
#include "pbr/ibl/importance_sampling.hlsl"
#include "pbr/unity/surface_standard.hlsl"
#include "pbr/unity/surface_layers.hlsl"

// The GLSL spellings the shared .inc files use, for the harness's programs only.
#define vec2 float2
#define vec3 float3
#define vec4 float4
#define mat4 float4x4
#define inversesqrt rsqrt

#include "scene_lighting.inc"
