// pbrlab stand-in for URP's Shaders/2D/Include/SpriteMaskShared.hlsl (the 2D renderer's Sprite
// Mask pass): the mask's texture _MainTex and alpha cutoff _Cutoff, its Attributes (object position,
// texture coordinate) and Varyings, MaskRenderingVertex (the object's position to clip space, the
// coordinate passed on) and MaskRenderingFragment (discards a pixel whose texel's alpha is below
// _Cutoff, so the mask's stencil is not marked there; writes 0). Written for pbrlab from the names
// and behaviour of URP 12's file (Unity's own file is under the Unity Companion License and is not
// copied). Like URP's, it has no include guard and includes nothing: the program includes Core.hlsl
// first.
float _Cutoff;

TEXTURE2D(_MainTex);
SAMPLER(sampler_MainTex);

struct Attributes {
    float4 positionOS : POSITION;
    float2 texcoord : TEXCOORD0;
};

struct Varyings {
    float4 positionCS : SV_POSITION;
    float2 uv : TEXCOORD0;
};

Varyings MaskRenderingVertex(Attributes input) {
    Varyings output;
    output.positionCS = TransformObjectToHClip(input.positionOS.xyz);
    output.uv = input.texcoord;
    return output;
}

float4 MaskRenderingFragment(Varyings input) : SV_Target {
    float4 c = SAMPLE_TEXTURE2D(_MainTex, sampler_MainTex, input.uv);
    clip(c.a - _Cutoff);
    return float4(0.0, 0.0, 0.0, 0.0);
}
