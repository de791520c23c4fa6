// pbrlab test shader (written for pbrlab, session 47): a program that compares one depth texture
// and reads another shadow-declared texture plainly. Red: Core RP's SAMPLE_TEXTURE2D_SHADOW of
// _Depths (TEXTURE2D_SHADOW, SAMPLER_CMP) against _Reference at the pixel's screen uv; green: the
// red channel of _Plain, declared TEXTURE2D_SHADOW but read only by SAMPLE_TEXTURE2D (Core RP's
// TEXTURE2D_SHADOW is a Texture2D on Direct3D 11, which a SamplerState reads as any texture);
// blue: a Direct3D 11 Texture2D _Passed compared only inside a function it is passed to.
Shader "pbrlab/test/s47 shadow split" {
    Properties {
        _Depths ("Compared depths (red)", 2D) = "white" {}
        _Plain ("Plainly read depths (red)", 2D) = "white" {}
        _Passed ("Depths compared in a function (red)", 2D) = "white" {}
        _Reference ("Compared depth", Range(0, 1)) = 0.5
    }
    SubShader {
        Tags { "RenderPipeline" = "UniversalPipeline" "RenderType" = "Opaque" }
        Pass {
            Tags { "LightMode" = "UniversalForward" }
            ZTest Always
            HLSLPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"

            TEXTURE2D_SHADOW(_Depths);
            SAMPLER_CMP(sampler_Depths);
            TEXTURE2D_SHADOW(_Plain);
            SAMPLER(sampler_Plain);
            Texture2D _Passed;
            SamplerComparisonState sampler_Passed;
            float _Reference;

            float4 vert(float4 positionOS : POSITION) : SV_POSITION { return TransformObjectToHClip(positionOS.xyz); }

            float CompareIn(Texture2D map, SamplerComparisonState s, float2 uv, float z) {
                return map.SampleCmpLevelZero(s, uv, z);
            }

            float4 frag(float4 positionCS : SV_POSITION) : SV_Target {
                float2 uv = GetNormalizedScreenSpaceUV(positionCS);
                float compared = SAMPLE_TEXTURE2D_SHADOW(_Depths, sampler_Depths, float3(uv, _Reference));
                float plain = SAMPLE_TEXTURE2D(_Plain, sampler_Plain, uv).r;
                float passed = CompareIn(_Passed, sampler_Passed, uv, _Reference);
                return float4(compared, plain, passed, 1.0);
            }
            ENDHLSL
        }
    }
}
