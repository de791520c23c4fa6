#version 330 core
// HDR resolve: scene radiance * 2^exposure -> the library's tonemapper (selected by
// PBR_TONEMAP, pbr/tonemap/tonemap.glsl) -> display value -> pbr_encode_final_color
// (PBR_COLOR_TRANSFER, pbr/color/transfer.glsl): identity on the hardware path, where an
// sRGB framebuffer encodes; the shader's own encode on the DIY paths (plain RGBA8).
//@DEFINES
#include "pbr/pbr.glsl"
uniform sampler2D u_hdr;
uniform float u_exposure_ev;
out vec4 out_color;
void main() {
    vec4 hdr = texelFetch(u_hdr, ivec2(gl_FragCoord.xy), 0);
    vec3 c = pbr_tonemap(pbr_apply_exposure(hdr.rgb, u_exposure_ev));
    // The display image is opaque: coverage alpha stays in the float render (EXR).
    out_color = vec4(pbr_encode_final_color(clamp(c, 0.0, 1.0)), 1.0);
}
