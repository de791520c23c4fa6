// pbrlab test shader (written for pbrlab, session 47): one Direct3D 11 Texture2D read both with a
// SamplerComparisonState and with a SamplerState (Microsoft's HLSL reference: a texture object
// may be sampled by any sampler). Red: _Depths.SampleCmpLevelZero at (uv, _Reference); green:
// _Depths.Sample(sampler_Depths, uv).r, the stored depth itself; blue: the comparison inside a
// function the texture is passed to.
Shader "pbrlab/test/s47 shadow both objects" {
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

            Texture2D _Depths;
            SamplerComparisonState sampler_DepthsCompare;
            SamplerState sampler_Depths;
            float _Reference;

            float4 vert(float4 positionOS : POSITION) : SV_POSITION { return TransformObjectToHClip(positionOS.xyz); }

            float CompareIn(Texture2D map, SamplerComparisonState s, float2 uv, float z) {
                return map.SampleCmpLevelZero(s, uv, z);
            }

            float4 frag(float4 positionCS : SV_POSITION) : SV_Target {
                float2 uv = GetNormalizedScreenSpaceUV(positionCS);
                float compared = _Depths.SampleCmpLevelZero(sampler_DepthsCompare, uv, _Reference);
                float plain = _Depths.Sample(sampler_Depths, uv).r;
                float passed = CompareIn(_Depths, sampler_DepthsCompare, uv, _Reference);
                return float4(compared, plain, passed, 1.0);
            }
            ENDHLSL
        }
    }
}
