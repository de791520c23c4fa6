// pbr/tonemap/reinhard.glsl: Reinhard's global operator.
//
// Provides: vec3 pbr_tonemap_reinhard(vec3 color)
//           vec3 pbr_tonemap_reinhard_extended(vec3 color, float whitePoint)
// Include:  "pbr/tonemap/reinhard.glsl" (path relative to glsl/)
// Config macros read: none.
//
// Reinhard, Stark, Shirley, Ferwerda 2002, "Photographic Tone Reproduction for Digital
// Images", ACM ToG 21(3): eq. 3, L_d = L / (1 + L), and eq. 4 (with the smallest value
// mapped to white, L_white): L_d = L (1 + L / L_white²) / (1 + L). The paper applies them
// to luminance; as is common in games they are applied here per channel to linear RGB
// (simpler, desaturates highlights towards white). Input: non-negative linear HDR colour
// (after exposure); output linear in [0, 1) (eq. 3) or [0, 1] up to whitePoint (eq. 4).
#ifndef PBR_TONEMAP_REINHARD_GLSL
#define PBR_TONEMAP_REINHARD_GLSL

vec3 pbr_tonemap_reinhard(vec3 color) { return color / (vec3(1.0) + color); }

vec3 pbr_tonemap_reinhard_extended(vec3 color, float whitePoint) {
    return color * (vec3(1.0) + color / (whitePoint * whitePoint)) / (vec3(1.0) + color);
}

#endif // PBR_TONEMAP_REINHARD_GLSL
