// pbr/material/f0_tables.hlsl: the lecture's F0 tables (linear reflectance at normal incidence).
//
// Provides: PBR_F0_<DIELECTRIC> (float) and PBR_F0_<METAL> (vec3, linear RGB).
// Include:  "pbr/material/f0_tables.hlsl" (path relative to hlsl_ports/)
// Config macros read: none.
//
// Source: Lagarde 2011, "Feeding a physically based shading model" (seblagarde.wordpress.com,
// 2011-08-17), as reproduced in the lecture's slides "F0 for dielectrics (linear)" and
// "F0 for metals (linear)". Dielectric F0 is grey (use vec3(PBR_F0_WATER)); metal F0 is
// coloured. Copied digit for digit; shared with reference/material.py F0_DIELECTRICS and
// F0_METALS and tested equal (tests/library/test_material.py).
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_MATERIAL_F0_TABLES_HLSL
#define PBR_MATERIAL_F0_TABLES_HLSL
#include "pbr/common/shim.hlsl"  // generated from glsl/pbr/material/f0_tables.glsl by harness/pbrlab/gpu/port_hlsl.py: edit the GLSL, then regenerate

// Dielectrics
#define PBR_F0_QUARTZ   0.045593921
#define PBR_F0_ICE      0.017908907
#define PBR_F0_WATER    0.020373188
#define PBR_F0_ALCOHOL  0.01995505
#define PBR_F0_GLASS    0.04
#define PBR_F0_MILK     0.022181983
#define PBR_F0_RUBY     0.077271957
#define PBR_F0_CRYSTAL  0.111111111
#define PBR_F0_DIAMOND  0.171968833
#define PBR_F0_SKIN     0.028

// Metals (R, G, B)
#define PBR_F0_SILVER    float3(0.971519, 0.959915, 0.915324)
#define PBR_F0_ALUMINIUM float3(0.913183, 0.921494, 0.924524)
#define PBR_F0_GOLD      float3(1.0,      0.765557, 0.336057)
#define PBR_F0_COPPER    float3(0.955008, 0.637427, 0.538163)
#define PBR_F0_CHROMIUM  float3(0.549585, 0.556114, 0.554256)
#define PBR_F0_NICKEL    float3(0.659777, 0.608679, 0.525649)
#define PBR_F0_TITANIUM  float3(0.541931, 0.496791, 0.449419)
#define PBR_F0_COBALT    float3(0.662124, 0.654864, 0.633732)
#define PBR_F0_PLATINUM  float3(0.672411, 0.637331, 0.585456)

#endif // PBR_MATERIAL_F0_TABLES_HLSL
