// s47-stages: a struct-typed member inside URP's Varyings (a varying that is a struct), its
// members carrying their own semantics; the plane's uv reaches the fragment through
// Varyings.inner.uv and a constant through Varyings.inner.tint.
Shader "s47-stages/urp_struct_varying" {
    SubShader { Tags { "RenderPipeline" = "UniversalPipeline" } Pass {
        Tags { "LightMode" = "UniversalForward" }
        Cull Off
        HLSLPROGRAM
        #pragma vertex vert
        #pragma fragment frag
        #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
        struct Attributes { float4 positionOS : POSITION; float2 uv : TEXCOORD0; };
        struct Inner { float2 uv : TEXCOORD3; float tint : TEXCOORD5; };
        struct Varyings { float4 positionCS : SV_POSITION; Inner inner; float w : TEXCOORD1; };
        Varyings vert(Attributes v) {
            Varyings o;
            o.positionCS = float4(v.positionOS.x / 0.3, -v.positionOS.z / 0.3, 0.0, 1.0);
            o.inner.uv = v.uv;
            o.inner.tint = 0.25;
            o.w = 0.75;
            return o;
        }
        half4 frag(Varyings i) : SV_Target { return half4(i.inner.uv, i.inner.tint, i.w); }
        ENDHLSL
    } }
}
