// pbr/color/luminance.hlsl: relative luminance of a linear Rec. 709 / sRGB colour.
//
// Provides: pbr_luminance(vec3 linear), PBR_LUMINANCE_REC709.
// Include:  "pbr/color/luminance.hlsl" (path relative to hlsl_ports/)
// Config macros read: none.
//
// Y = 0.2126 R + 0.7152 G + 0.0722 B: ITU-R BT.709-6 (2015), item 3.2 (derivation of
// luminance signal), the Y row of the RGB -> XYZ matrix for Rec. 709 primaries and D65,
// which sRGB shares (IEC 61966-2-1 §5.2). The weights sum to 1, so white maps to 1.
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_COLOR_LUMINANCE_HLSL
#define PBR_COLOR_LUMINANCE_HLSL
#include "pbr/common/shim.hlsl"  // generated from glsl/pbr/color/luminance.glsl by harness/pbrlab/gpu/port_hlsl.py: edit the GLSL, then regenerate

#define PBR_LUMINANCE_REC709 float3(0.2126, 0.7152, 0.0722)

float pbr_luminance(float3 linearColor) { return dot(linearColor, PBR_LUMINANCE_REC709); }

#endif // PBR_COLOR_LUMINANCE_HLSL
