#version 330 core
// HDR resolve: scene radiance * 2^exposure -> tonemapper -> linear display value,
// written to an sRGB framebuffer that encodes in hardware.
//   PBRLAB_TONEMAP  0 none (clamp), 1 Reinhard, 2 ACES fit, 3 Hable, 4 Khronos PBR Neutral
//@DEFINES
#include "pbr/pbr.glsl"
uniform sampler2D u_hdr;
uniform float u_exposure_ev;
out vec4 out_color;
void main() {
    vec4 hdr = texelFetch(u_hdr, ivec2(gl_FragCoord.xy), 0);
    vec3 c = pbr_apply_exposure(hdr.rgb, u_exposure_ev);
#if PBRLAB_TONEMAP == 1
    c = pbr_tonemap_reinhard(c);
#elif PBRLAB_TONEMAP == 2
    c = pbr_tonemap_aces_fitted(c);
#elif PBRLAB_TONEMAP == 3
    c = pbr_tonemap_hable(c);
#elif PBRLAB_TONEMAP == 4
    c = pbr_tonemap_khronos_neutral(c);
#endif
    out_color = vec4(clamp(c, 0.0, 1.0), clamp(hdr.a, 0.0, 1.0));
}
