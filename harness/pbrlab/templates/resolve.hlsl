// HDR resolve, the HLSL twin of resolve.frag: scene radiance * 2^exposure -> the library's
// tonemapper (PBR_TONEMAP) -> display value -> pbr_encode_final_color (PBR_COLOR_TRANSFER).
//@DEFINES
#include "pbr/pbr.hlsl"
Texture2D u_hdr;
uniform float u_exposure_ev;

float4 main(float4 position : SV_Position) : SV_Target0 {
    float4 hdr = u_hdr.Load(int3(int2(position.xy), 0));
    float3 c = pbr_tonemap(pbr_apply_exposure(hdr.rgb, u_exposure_ev));
    // The display image is opaque: coverage alpha stays in the float render (EXR).
    return float4(pbr_encode_final_color(clamp(c, 0.0, 1.0)), 1.0);
}
