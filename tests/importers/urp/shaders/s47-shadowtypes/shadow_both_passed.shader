// pbrlab test shader (written for pbrlab, session 47): one Direct3D 11 Texture2D read plainly and
// compared only inside a function it is passed to (glslang then types the global a plain
// sampler2D, the function's parameter a sampler2DShadow). Red: the comparison at (uv,
// _Reference) through the function; green: _Depths.Sample(sampler_Depths, uv).r, the stored
// depth itself; blue: 0.
Shader "pbrlab/test/s47 shadow both passed" {
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
                float passed = CompareIn(_Depths, sampler_DepthsCompare, uv, _Reference);
                float plain = _Depths.Sample(sampler_Depths, uv).r;
                return float4(passed, plain, 0.0, 1.0);
            }
            ENDHLSL
        }
    }
}
