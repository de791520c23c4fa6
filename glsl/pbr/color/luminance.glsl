// pbr/color/luminance.glsl: relative luminance of a linear Rec. 709 / sRGB colour.
//
// Provides: pbr_luminance(vec3 linear), PBR_LUMINANCE_REC709.
// Include:  "pbr/color/luminance.glsl" (path relative to glsl/)
// Config macros read: none.
//
// Y = 0.2126 R + 0.7152 G + 0.0722 B: ITU-R BT.709-6 (2015), item 3.2 (derivation of
// luminance signal), the Y row of the RGB -> XYZ matrix for Rec. 709 primaries and D65,
// which sRGB shares (IEC 61966-2-1 §5.2). The weights sum to 1, so white maps to 1.
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_COLOR_LUMINANCE_GLSL
#define PBR_COLOR_LUMINANCE_GLSL

#define PBR_LUMINANCE_REC709 vec3(0.2126, 0.7152, 0.0722)

float pbr_luminance(vec3 linearColor) { return dot(linearColor, PBR_LUMINANCE_REC709); }

#endif // PBR_COLOR_LUMINANCE_GLSL
