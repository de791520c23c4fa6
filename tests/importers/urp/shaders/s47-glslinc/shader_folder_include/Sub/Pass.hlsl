// s47-glslinc: the pass's functions; Common/ is not beside this file but beside the shader.
#ifndef S47_GLSLINC_PASS_INCLUDED
#define S47_GLSLINC_PASS_INCLUDED
#include "Common/Tone.hlsl"

struct Attributes { float4 positionOS : POSITION; };
struct Varyings { float4 positionCS : SV_POSITION; };

Varyings vert(Attributes input)
{
    Varyings output;
    output.positionCS = TransformObjectToHClip(input.positionOS.xyz);
    return output;
}

half4 frag(Varyings input) : SV_Target
{
    SurfaceData surface = ToneSurface(_Base.rgb);
    return half4(surface.albedo, surface.alpha);
}
#endif
