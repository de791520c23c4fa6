// s47-include: a URP pass of a project that embeds URP's package (Packages/ beside Assets/)
Shader "s47-include/vendored brdf" {
    SubShader {
        Tags { "RenderPipeline" = "UniversalPipeline" }
        Pass {
            Tags { "LightMode" = "UniversalForward" }
            HLSLPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
            #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/BRDF.hlsl"
            struct Attributes { float4 positionOS : POSITION; };
            struct Varyings { float4 positionCS : SV_POSITION; };
            Varyings vert(Attributes IN) {
                Varyings OUT;
                OUT.positionCS = TransformObjectToHClip(IN.positionOS.xyz);
                return OUT;
            }
            float4 frag(Varyings IN) : SV_Target {
                return float4(Max3(0.25, 0.5, 0.125), Min3(0.25, 0.5, 0.125), 0.75, 1.0);
            }
            ENDHLSL
        }
    }
}
