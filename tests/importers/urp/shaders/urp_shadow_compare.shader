// pbrlab test shader (written for pbrlab): URP's comparison-sampler family. Red: a shadow map of
// the material's (its red channel the stored depths) compared with _Reference at the pixel's
// screen uv through SAMPLE_TEXTURE2D_SHADOW in a function it is passed to; green: the same through Direct3D 11's
// SampleCmpLevelZero on a SamplerComparisonState the shader declares; blue: the fraction of
// _Steps references spread over the depth range that URP's main light shadow map
// (_MainLightShadowmapTexture) finds lit, times its reads at the point's shadow coordinate
// (TransformWorldToShadowCoord, MainLightRealtimeShadow), as a god-ray shader's ray march reads
// them, or (_MarchOwnMap 1) that fraction for the material's own map alone.
Shader "pbrlab/test/urp shadow compare" {
    Properties {
        _Depths ("Stored depths (red)", 2D) = "white" {}
        _DepthsAgain ("The same depths, for SampleCmpLevelZero", 2D) = "white" {}
        _Reference ("Compared depth", Range(0, 1)) = 0.5
        _Steps ("Ray-march steps", Int) = 16
        _MarchOwnMap ("Blue marches _Depths, not the main light's map", Float) = 0
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
            #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Lighting.hlsl"

            TEXTURE2D_SHADOW(_Depths);
            SAMPLER_CMP(sampler_Depths);
            Texture2D _DepthsAgain;
            SamplerComparisonState sampler_DepthsAgain;
            float _Reference;
            int _Steps;
            float _MarchOwnMap;

            struct Attributes { float4 positionOS : POSITION; };
            struct Varyings { float4 positionCS : SV_POSITION; float3 positionWS : TEXCOORD0; };

            Varyings vert(Attributes IN) {
                Varyings OUT;
                OUT.positionWS = TransformObjectToWorld(IN.positionOS.xyz);
                OUT.positionCS = TransformWorldToHClip(OUT.positionWS);
                return OUT;
            }

            // the fraction of _Steps references z = (i + 0.5) / _Steps, spread over the depth range,
            // that a shadow map passed with its comparison sampler finds lit at uv
            float LitFraction(TEXTURE2D_SHADOW_PARAM(map, sampler_map), float2 uv) {
                float lit = 0;
                for (int i = 0; i < _Steps; i++) {
                    lit += SAMPLE_TEXTURE2D_SHADOW(map, sampler_map, float3(uv, (i + 0.5) / _Steps));
                }
                return lit / _Steps;
            }

            // a map passed on to a function that compares (the program reads _Depths only so)
            float Compare(TEXTURE2D_SHADOW_PARAM(map, sampler_map), float2 uv, float z) {
                return SAMPLE_TEXTURE2D_SHADOW(map, sampler_map, float3(uv, z));
            }

            float4 frag(Varyings IN) : SV_Target {
                float2 uv = GetNormalizedScreenSpaceUV(IN.positionCS);
                float compared = Compare(TEXTURE2D_SHADOW_ARGS(_Depths, sampler_Depths), uv, _Reference);
                float again = _DepthsAgain.SampleCmpLevelZero(sampler_DepthsAgain, uv, _Reference);
                // URP's main light: its shadow map over the whole depth range, and at the point's
                // own shadow coordinate, as a god-ray shader's ray march reads it
                float4 shadowCoord = TransformWorldToShadowCoord(IN.positionWS);
                float mainLit = LitFraction(TEXTURE2D_SHADOW_ARGS(_MainLightShadowmapTexture, sampler_MainLightShadowmapTexture), uv)
                              * SAMPLE_TEXTURE2D_SHADOW(_MainLightShadowmapTexture, sampler_MainLightShadowmapTexture, shadowCoord)
                              * MainLightRealtimeShadow(shadowCoord);
                float ownLit = LitFraction(TEXTURE2D_SHADOW_ARGS(_Depths, sampler_Depths), uv);
                return float4(compared, again, _MarchOwnMap > 0.5 ? ownLit : mainLit, 1.0);
            }
            ENDHLSL
        }
    }
}
