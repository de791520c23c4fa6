// s47-stages: a struct holding a texture, its sampler and its tiling, filled from the globals in
// a local and passed to a function that samples it (GLSL forbids opaque types in a struct).
Shader "s47-stages/urp_texture_struct" {
    Properties { _MainTex ("Texture", 2D) = "white" {} }
    SubShader { Tags { "RenderPipeline" = "UniversalPipeline" } Pass {
        Tags { "LightMode" = "UniversalForward" }
        Cull Off
        HLSLPROGRAM
        #pragma vertex vert
        #pragma fragment frag
        #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
        TEXTURE2D(_MainTex); SAMPLER(sampler_MainTex);
        float4 _MainTex_ST;
        struct TextureInfo { TEXTURE2D(tex); SAMPLER(sampler_tex); float4 st; };
        struct Attributes { float4 positionOS : POSITION; float2 uv : TEXCOORD0; };
        struct Varyings { float4 positionCS : SV_POSITION; float2 uv : TEXCOORD0; };
        float4 SampleInfo(TextureInfo info, float2 uv) {
            return SAMPLE_TEXTURE2D(info.tex, info.sampler_tex, uv * info.st.xy + info.st.zw);
        }
        Varyings vert(Attributes v) {
            Varyings o;
            o.positionCS = float4(v.positionOS.x / 0.3, -v.positionOS.z / 0.3, 0.0, 1.0);
            o.uv = v.uv;
            return o;
        }
        half4 frag(Varyings i) : SV_Target {
            TextureInfo info;
            info.tex = _MainTex;
            info.sampler_tex = sampler_MainTex;
            info.st = _MainTex_ST;
            float2 uv = (floor(i.uv * 8) + 0.5) / 8;  // (a texel centre after the tiling: one texel read)
            return SampleInfo(info, uv);
        }
        ENDHLSL
    } }
}
