// pbrlab_tables.hlsl: sample pbrlab's DFG and sheen albedo tables (`pbrlab tables --out DIR`)
// exactly as the library does, in an engine that does not include the library.
//
// Provides: float2 pbr_table_dfg_uv(float NdotV, float perceptualRoughness)
//           float2 pbr_table_sample_dfg(Texture2D dfgTable, SamplerState s, float NdotV, float perceptualRoughness)
//           float2 pbr_table_sheen_albedo_uv(float NdotV, float sheenPerceptualRoughness)
//           float pbr_table_sample_sheen_albedo(Texture2D sheenTable, SamplerState s, float NdotV,
//                                               float sheenPerceptualRoughness)
// Include:  "pbrlab_tables.glsl" (copy it beside your shaders; it needs nothing else)
// Config macros read: PBR_TABLE_SHEEN_ALBEDO_SCALE (default 1.0: the float EXR; 4.0 for the
//           16-bit PNG, which holds E / 4).
//
// The tables (docs/tables.md): pbrlab_dfg.exr / .png, R = A (F0's weight), G = B (F90's
// weight) of the split sum (Karis 2013, "Real Shading in Unreal Engine 4", eq. 8), 256 x 256;
// pbrlab_sheen_albedo.exr / .png, R = E, the directional albedo of the white sheen lobe
// (Estevez & Kulla 2017, section 4), 128 x 128. Upload them linear (not sRGB), with the
// image's top row first, as Direct3D and Vulkan do (v = 0 at the top row): the sample
// functions read at (u, 1 - v) of the library's coordinates, which put the bottom row at
// v = 0 as OpenGL does. A SamplerState with bilinear filtering (MIN_MAG_LINEAR_MIP_POINT),
// clamp addressing, no mips.
// The texture coordinates are the library's pbr_dfg_lut_uv (pbr/ibl/environment_brdf.hlsl)
// and pbr_sheen_lut_uv (pbr/shading/sheen.hlsl); their constants are repeated here and
// tested equal (tests/library/test_engine_tables.py). With the library itself, hand it the
// tables through its hooks instead:
//   #define PBR_DFG_LUT_LOOKUP(NdotV, r) pbr_table_sample_dfg(g_dfg, g_linearClamp, NdotV, r)
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_TABLES_HLSL
#define PBR_TABLES_HLSL

#ifndef PBR_TABLE_SHEEN_ALBEDO_SCALE
#define PBR_TABLE_SHEEN_ALBEDO_SCALE 1.0
#endif

// The DFG table's warped axes (pbr/ibl/environment_brdf.hlsl): texel (i, j) holds (A, B) at
//   x = log2(1 + NdotV / 0.003) / log2(1 + 1 / 0.003),
//   y = log2((alpha + 0.003) / (0.045² + 0.003)) / log2((1 + 0.003) / (0.045² + 0.003)),
// x = i / 255, y = j / 255, alpha = perceptual roughness²; read at texel centres.
#define PBR_TABLE_DFG_SIZE float2(256.0, 256.0)
#define PBR_TABLE_DFG_NDOTV_INV_SCALE 333.333333
#define PBR_TABLE_DFG_NDOTV_LOG_NORM 0.119258545
#define PBR_TABLE_DFG_ALPHA_OFFSET 0.003
#define PBR_TABLE_DFG_ALPHA_MIN_INV 199.004975
#define PBR_TABLE_DFG_ALPHA_LOG_NORM 0.130873226

float2 pbr_table_dfg_uv(float NdotV, float perceptualRoughness) {
    float alpha = perceptualRoughness * perceptualRoughness;
    float x = log2(1.0 + clamp(NdotV, 0.0, 1.0) * PBR_TABLE_DFG_NDOTV_INV_SCALE) * PBR_TABLE_DFG_NDOTV_LOG_NORM;
    float y = log2((clamp(alpha, 0.0, 1.0) + PBR_TABLE_DFG_ALPHA_OFFSET) * PBR_TABLE_DFG_ALPHA_MIN_INV)
            * PBR_TABLE_DFG_ALPHA_LOG_NORM;
    return (clamp(float2(x, y), 0.0, 1.0) * (PBR_TABLE_DFG_SIZE - 1.0) + 0.5) / PBR_TABLE_DFG_SIZE;
}

float2 pbr_table_sample_dfg(Texture2D dfgTable, SamplerState s, float NdotV, float perceptualRoughness) {
    float2 uv = pbr_table_dfg_uv(NdotV, perceptualRoughness);
    return dfgTable.Sample(s, float2(uv.x, 1.0 - uv.y)).rg;
}

// The sheen albedo table's axes (pbr/shading/sheen.hlsl): texel (i, j) holds E at
//   x = log2(max(NdotV, 1e-4) / 1e-4) / log2(1e4),  y = log2(max(r, 0.07) / 0.07) / log2(1 / 0.07),
// x = i / 127, y = j / 127 (1e-4: PBR_MIN_NDOTV; 0.07: PBR_SHEEN_MIN_PERCEPTUAL_ROUGHNESS).
#define PBR_TABLE_SHEEN_SIZE float2(128.0, 128.0)
#define PBR_TABLE_SHEEN_MIN_NDOTV 1e-4
#define PBR_TABLE_SHEEN_MIN_ROUGHNESS 0.07
#define PBR_TABLE_SHEEN_NDOTV_LOG_NORM 0.0752574989
#define PBR_TABLE_SHEEN_ROUGHNESS_LOG_NORM 0.260654156

float2 pbr_table_sheen_albedo_uv(float NdotV, float sheenPerceptualRoughness) {
    float x = log2(clamp(NdotV, PBR_TABLE_SHEEN_MIN_NDOTV, 1.0)) * PBR_TABLE_SHEEN_NDOTV_LOG_NORM + 1.0;
    float y = log2(clamp(sheenPerceptualRoughness, PBR_TABLE_SHEEN_MIN_ROUGHNESS, 1.0))
            * PBR_TABLE_SHEEN_ROUGHNESS_LOG_NORM + 1.0;
    return (clamp(float2(x, y), 0.0, 1.0) * (PBR_TABLE_SHEEN_SIZE - 1.0) + 0.5) / PBR_TABLE_SHEEN_SIZE;
}

float pbr_table_sample_sheen_albedo(Texture2D sheenTable, SamplerState s, float NdotV, float sheenPerceptualRoughness) {
    float2 uv = pbr_table_sheen_albedo_uv(NdotV, sheenPerceptualRoughness);
    return sheenTable.Sample(s, float2(uv.x, 1.0 - uv.y)).r
         * PBR_TABLE_SHEEN_ALBEDO_SCALE;
}

#endif
