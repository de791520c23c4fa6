// pbr/common/conventions.glsl: the conventions every pbrlab file follows, written once.
//
// Provides: PBR_LIGHT_UNIT_SCALE (and, through its includes, PBR_PI and the math helpers).
// Include:  "pbr/common/conventions.glsl" (path relative to glsl/)
// Config macros read: none.
//
// 1. Directions. n (normal), v (to the viewer), l (to the light) and h = normalize(l + v)
//    are unit vectors pointing AWAY from the shaded point, all in the same space (any
//    orthonormal frame, handedness irrelevant: only dot products are used). Cosines are
//    named NdotL, NdotV, NdotH, LdotH, VdotH; for the half vector LdotH == VdotH.
// 2. Colours are linear (scene-referred, Rec. 709 primaries) unless the name says sRGB.
// 3. Roughness vocabulary; every parameter name says which one it takes:
//      smoothness            Unity's "Smoothness"/gloss g, 0 = rough .. 1 = smooth
//      perceptualRoughness   = 1 - smoothness (Burley 2012's "roughness", Disney/Unreal slider)
//      alpha                 = perceptualRoughness^2 (the microfacet width of D and V)
//      specPower             Blinn-Phong exponent s
//    Converters: pbr/material/remap.glsl.
// 4. BRDF terms. D_ is a microfacet distribution (1/sr, normalised so that
//    ∫ D(h) (n·h) dω_h = 1); G_ is the masking-shadowing function G itself (unitless, <= 1);
//    V_ is the visibility V = G / (4 · NdotL · NdotV), so that the Cook-Torrance specular
//    lobe is D · V · F; F_ is Fresnel reflectance; Fd_ is a diffuse BRDF. Every BRDF
//    INCLUDES its 1/π (pbr_Fd_Lambert() == 1/π), so it is a true BRDF in 1/sr.
// 5. Light units: "lights are π times too bright" (Lanterman's lecture, after McAuley 2011
//    and Driscoll 2009). A punctual light of intensity C_light contributes
//        C_final = C_light ⊗ PBR_LIGHT_UNIT_SCALE · BRDF · max(0, NdotL),
//    with PBR_LIGHT_UNIT_SCALE = π, so a white Lambert surface (BRDF = 1/π) lit by an
//    intensity-1 light along its normal returns exactly 1. Global illumination code that
//    integrates radiance must NOT apply this factor (the lecture's "be careful!").
// 6. Energy: a colour in [0, 1] is a reflectance; diffuse + specular reflectance <= 1 is
//    the practical energy-conservation rule (pbr/material/workflow.glsl).
// 7. Prefixes: public functions pbr_, macros PBR_, include guards PBR_<PATH>_GLSL. No file
//    declares uniforms, varyings, samplers or in/out globals: the caller owns resources.
// 8. Variants: each alternative is its own function; a numbered macro selects it
//    (e.g. PBR_SPECULAR_D = PBR_SPECULAR_D_GGX) and one dispatch function per term holds
//    the only conditional chain (pbr/shading/dispatch.glsl).
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_COMMON_CONVENTIONS_GLSL
#define PBR_COMMON_CONVENTIONS_GLSL

#include "pbr/common/constants.glsl"
#include "pbr/common/math.glsl"

// The light-unit factor of convention 5 (see above). Shared with
// harness/pbrlab/maths/reference/constants.py LIGHT_UNIT_SCALE.
#define PBR_LIGHT_UNIT_SCALE PBR_PI

#endif // PBR_COMMON_CONVENTIONS_GLSL
