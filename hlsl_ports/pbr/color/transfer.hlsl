// pbr/color/transfer.hlsl: the two ways of lighting in linear space, behind one selector.
//
// Provides: pbr_decode_color_texel(vec3), pbr_encode_final_color(vec3) and the selector
//           values PBR_COLOR_TRANSFER_{HARDWARE,SRGB,GAMMA22,FAST}.
// Include:  "pbr/color/transfer.hlsl" (path relative to hlsl_ports/)
// Config macros read: PBR_COLOR_TRANSFER (default PBR_COLOR_TRANSFER_HARDWARE).
//
// The lecture ("DIY linear space" vs "Let the GPU magically handle it"):
//   HARDWARE  colour textures are sRGB formats (GL_SRGB8_ALPHA8, D3D SRGBTEXTURE) and the
//             target is an sRGB framebuffer (GL_FRAMEBUFFER_SRGB): the GPU decodes on
//             fetch and encodes on write, so both functions are the identity. Preferred:
//             exact, free, and filtering happens in linear space.
//   SRGB      DIY with the exact IEC 61966-2-1 curves: decode each colour texel after
//             the fetch, encode in the final-colour hook (Unity's finalcolor:finalgamma)
//             when the target is a UNORM (non-sRGB) framebuffer.
//   GAMMA22   DIY with the lecture's DeGamma/ReGamma, pow 2.2.
//   FAST      DIY with c·c / sqrt(c).
// Only colour data takes this path; normal maps, roughness, metallic and other data
// textures are linear already ("When to bypass sRGB sampling").
// Guard: pbr_encode_final_color returns a value in [0, 1] on every path (HARDWARE included:
// pbr_sanitize(c, 1.0), which a UNORM/sRGB8 target would apply anyway, but with NaN
// defined as 0 instead of left to the hardware); bit-identical on [0, 1].
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_COLOR_TRANSFER_HLSL
#define PBR_COLOR_TRANSFER_HLSL
#include "pbr/common/shim.hlsl"  // generated from glsl/pbr/color/transfer.glsl by harness/pbrlab/gpu/port_hlsl.py: edit the GLSL, then regenerate

#include "pbr/color/srgb.hlsl"
#include "pbr/color/gamma.hlsl"
#include "pbr/common/guards.hlsl"

#define PBR_COLOR_TRANSFER_HARDWARE 1
#define PBR_COLOR_TRANSFER_SRGB 2
#define PBR_COLOR_TRANSFER_GAMMA22 3
#define PBR_COLOR_TRANSFER_FAST 4

#ifndef PBR_COLOR_TRANSFER
// PBR_COLOR_TRANSFER_HARDWARE as a number (glsl/README.md, one-level preprocessors)
#define PBR_COLOR_TRANSFER 1
#endif

// A colour texel as fetched -> linear colour.
float3 pbr_decode_color_texel(float3 texel) {
#if PBR_COLOR_TRANSFER == PBR_COLOR_TRANSFER_HARDWARE
    return texel;
#elif PBR_COLOR_TRANSFER == PBR_COLOR_TRANSFER_SRGB
    return pbr_srgb_to_linear(texel);
#elif PBR_COLOR_TRANSFER == PBR_COLOR_TRANSFER_GAMMA22
    return pbr_degamma(texel);
#elif PBR_COLOR_TRANSFER == PBR_COLOR_TRANSFER_FAST
    return pbr_degamma_fast(texel);
#else
#error "PBR_COLOR_TRANSFER: unknown value"
#endif
}

// The final linear colour -> the value written to the colour attachment.
float3 pbr_encode_final_color(float3 linearColor) {
#if PBR_COLOR_TRANSFER == PBR_COLOR_TRANSFER_HARDWARE
    return pbr_sanitize(linearColor, 1.0);
#elif PBR_COLOR_TRANSFER == PBR_COLOR_TRANSFER_SRGB
    return pbr_linear_to_srgb(linearColor);
#elif PBR_COLOR_TRANSFER == PBR_COLOR_TRANSFER_GAMMA22
    return pbr_regamma(linearColor);
#elif PBR_COLOR_TRANSFER == PBR_COLOR_TRANSFER_FAST
    return pbr_regamma_fast(linearColor);
#else
#error "PBR_COLOR_TRANSFER: unknown value"
#endif
}

#endif // PBR_COLOR_TRANSFER_HLSL
