// s47-glslinc: a global texture declared through the program's own macro that wraps Core RP's
// TEXTURE2D_FLOAT (as URP 14's Shaders/Utils/CopyDepthPass.hlsl declares _CameraDepthAttachment
// under _DEPTH_NO_MSAA), beside a direct TEXTURE2D_FLOAT; both read the properties' defaults.
// Here the macro is defined in an include (DepthMacros.hlsl), its use in the program.
Shader "s47glslinc/DepthTextureMacroIncluded" {
    Properties {
        _Depth ("Depth", 2D) = "gray" {}
        _Direct ("Direct", 2D) = "white" {}
    }
    SubShader {
        Tags { "RenderPipeline" = "UniversalPipeline" "RenderType" = "Opaque" }
        Pass {
            Tags { "LightMode" = "UniversalForward" }
            HLSLPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma multi_compile _DEPTH_NO_MSAA _DEPTH_MSAA_2
            #include "DepthMacros.hlsl"
            #ifdef _DEPTH_NO_MSAA
                DEPTH_TEXTURE(_Depth);
                SAMPLER(sampler_Depth);
            #endif
            TEXTURE2D_FLOAT(_Direct); SAMPLER(sampler_Direct);
            struct Attributes { float4 positionOS : POSITION; float2 uv : TEXCOORD0; };
            struct Varyings { float4 positionCS : SV_POSITION; float2 uv : TEXCOORD0; };
            Varyings vert(Attributes input) {
                Varyings output;
                output.positionCS = TransformObjectToHClip(input.positionOS.xyz);
                output.uv = input.uv;
                return output;
            }
            float4 frag(Varyings input) : SV_Target {
                float d = SAMPLE_DEPTH_TEXTURE(_Depth, sampler_Depth, input.uv);
                float w = SAMPLE_TEXTURE2D(_Direct, sampler_Direct, input.uv).g;
                return float4(d * 0.5, w * 0.25, d * w, 1.0);
            }
            ENDHLSL
        }
    }
}
