// pbrlab test shader (written for pbrlab, session 47): one depth texture read both through a
// comparison sampler and plainly, in Core RP's macros (Direct3D allows it: one Texture2D, two
// samplers). Red: SAMPLE_TEXTURE2D_SHADOW(_Depths, sampler_DepthsCompare, (uv, _Reference));
// green: SAMPLE_TEXTURE2D(_Depths, sampler_Depths, uv).r, the stored depth itself; blue: the
// comparison again through a function the map is passed to (TEXTURE2D_SHADOW_PARAM / _ARGS).
Shader "pbrlab/test/s47 shadow both core" {
    Properties {
        _Depths ("Depths (red)", 2D) = "white" {}
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
            SAMPLER_CMP(sampler_DepthsCompare);
            SAMPLER(sampler_Depths);
            float _Reference;

            float4 vert(float4 positionOS : POSITION) : SV_POSITION { return TransformObjectToHClip(positionOS.xyz); }

            float CompareIn(TEXTURE2D_SHADOW_PARAM(map, sampler_map), float2 uv, float z) {
                return SAMPLE_TEXTURE2D_SHADOW(map, sampler_map, float3(uv, z));
            }

            float4 frag(float4 positionCS : SV_POSITION) : SV_Target {
                float2 uv = GetNormalizedScreenSpaceUV(positionCS);
                float compared = SAMPLE_TEXTURE2D_SHADOW(_Depths, sampler_DepthsCompare, float3(uv, _Reference));
                float plain = SAMPLE_TEXTURE2D(_Depths, sampler_Depths, uv).r;
                float passed = CompareIn(TEXTURE2D_SHADOW_ARGS(_Depths, sampler_DepthsCompare), uv, _Reference);
                return float4(compared, plain, passed, 1.0);
            }
            ENDHLSL
        }
    }
}
