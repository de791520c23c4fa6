#version 330 core
// HDR resolve: scene radiance * 2^exposure -> the library's tonemapper (selected by
// PBR_TONEMAP, see pbr/tonemap/tonemap.glsl) -> linear display value, written to an
// sRGB framebuffer that encodes in hardware.
//@DEFINES
#include "pbr/pbr.glsl"
uniform sampler2D u_hdr;
uniform float u_exposure_ev;
out vec4 out_color;
void main() {
    vec4 hdr = texelFetch(u_hdr, ivec2(gl_FragCoord.xy), 0);
    vec3 c = pbr_tonemap(pbr_apply_exposure(hdr.rgb, u_exposure_ev));
    out_color = vec4(clamp(c, 0.0, 1.0), clamp(hdr.a, 0.0, 1.0));
}
