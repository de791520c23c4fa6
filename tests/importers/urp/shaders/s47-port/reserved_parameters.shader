// s47-port: URP's common spelling `half4 frag(Varyings input) : SV_Target` (input, output and a varying sample are
// GLSL reserved words, HLSL's own names), with a helper taking `Varyings input` and a default
// argument, for which the GLSL port writes a shorter overload of its own.
Shader "s47port/ReservedParameters" {
    SubShader {
        Tags { "RenderPipeline" = "UniversalPipeline" "RenderType" = "Opaque" }
        Pass {
            Tags { "LightMode" = "UniversalForward" }
            HLSLPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
            struct Attributes { float4 positionOS : POSITION; float2 uv : TEXCOORD0; };
            struct Varyings { float4 positionCS : SV_POSITION; float2 uv : TEXCOORD0; half3 sample : TEXCOORD1; };
            Varyings vert(Attributes input) {
                Varyings output = (Varyings)0;
                output.positionCS = TransformObjectToHClip(input.positionOS.xyz);
                output.uv = input.uv;
                output.sample = half3(0.25, 0.5, 0.75);
                return output;
            }
            half3 Shade(Varyings input, half filter = 0.5, half common = 0.125) {
                return input.sample * filter + common;
            }
            half4 frag(Varyings input) : SV_Target {
                return half4(Shade(input), 1.0);
            }
            ENDHLSL
        }
    }
}
