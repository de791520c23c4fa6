// pbrlab test shader (written for pbrlab, CC0): a varying declared only under URP's pipeline
// keyword _ADDITIONAL_LIGHTS (as URP's Lit-derived passes declare positionWS), which URP's
// renderer enables; it draws the world position it carries (x, y, z) + 0.5.
Shader "pbrlab tests/URP keyword varying" {
    SubShader {
        Tags { "RenderPipeline" = "UniversalPipeline" }
        Pass {
            Tags { "LightMode" = "UniversalForward" }
            HLSLPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma multi_compile _ _ADDITIONAL_LIGHTS_VERTEX _ADDITIONAL_LIGHTS
            #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"

            struct Attributes {
                float4 positionOS : POSITION;
            };
            struct Varyings {
                float4 positionCS : SV_POSITION;
            #ifdef _ADDITIONAL_LIGHTS
                float3 positionWS : TEXCOORD2;
            #endif
            };

            Varyings vert(Attributes IN) {
                Varyings OUT = (Varyings)0;
                float3 positionWS = TransformObjectToWorld(IN.positionOS.xyz);
                OUT.positionCS = TransformWorldToHClip(positionWS);
            #ifdef _ADDITIONAL_LIGHTS
                OUT.positionWS = positionWS;
            #endif
                return OUT;
            }

            float4 frag(Varyings IN) : SV_Target {
            #ifdef _ADDITIONAL_LIGHTS
                return float4(IN.positionWS + 0.5, 1.0);
            #else
                return float4(1.0, 0.0, 1.0, 1.0);
            #endif
            }
            ENDHLSL
        }
    }
}
