// pbrlab test shader (written for pbrlab, CC0): by hand, what sg_lit_texture.shader's graph
// computes: URP's UniversalFragmentPBR with the albedo _BaseMap (tiled and offset) times
// _BaseColor, _Metallic, _Smoothness, occlusion 1, no emission, the interpolated normal, the
// normalised view direction and the ambient light along the normal.
Shader "pbrlab tests/Shader Graph lit reference" {
    Properties {
        _BaseMap ("Base Map", 2D) = "white" {}
        _BaseColor ("Base Colour", Color) = (1, 0.5, 0.25, 1)
        _Metallic ("Metallic", Range(0, 1)) = 0.25
        _Smoothness ("Smoothness", Range(0, 1)) = 0.6
    }
    SubShader {
        Tags { "RenderPipeline" = "UniversalPipeline" }
        Pass {
            Tags { "LightMode" = "UniversalForward" }
            HLSLPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma multi_compile _ _ADDITIONAL_LIGHTS
            #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
            #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Lighting.hlsl"

            float4 _BaseMap_ST;
            float4 _BaseColor;
            float _Metallic;
            float _Smoothness;
            TEXTURE2D(_BaseMap);
            SAMPLER(sampler_BaseMap);

            struct Attributes {
                float4 positionOS : POSITION;
                float3 normalOS : NORMAL;
                float2 uv : TEXCOORD0;
            };
            struct Varyings {
                float4 positionCS : SV_POSITION;
                float2 uv : TEXCOORD0;
                float3 positionWS : TEXCOORD1;
                float3 normalWS : TEXCOORD2;
            };

            Varyings vert(Attributes IN) {
                Varyings OUT;
                OUT.positionWS = TransformObjectToWorld(IN.positionOS.xyz);
                OUT.positionCS = TransformWorldToHClip(OUT.positionWS);
                OUT.normalWS = TransformObjectToWorldNormal(IN.normalOS);
                OUT.uv = IN.uv;
                return OUT;
            }

            float4 frag(Varyings IN) : SV_Target {
                InputData inputData = (InputData)0;
                inputData.positionWS = IN.positionWS;
                inputData.normalWS = normalize(IN.normalWS);
                inputData.viewDirectionWS = SafeNormalize(GetWorldSpaceViewDir(IN.positionWS));
                inputData.bakedGI = SampleSH(inputData.normalWS);
                inputData.shadowMask = float4(1.0, 1.0, 1.0, 1.0);
                float2 uv = IN.uv * _BaseMap_ST.xy + _BaseMap_ST.zw;
                SurfaceData surface = (SurfaceData)0;
                surface.albedo = SAMPLE_TEXTURE2D(_BaseMap, sampler_BaseMap, uv).rgb * _BaseColor.rgb;
                surface.metallic = _Metallic;
                surface.smoothness = _Smoothness;
                surface.occlusion = 1.0;
                surface.alpha = 1.0;
                surface.normalTS = float3(0.0, 0.0, 1.0);
                return UniversalFragmentPBR(inputData, surface);
            }
            ENDHLSL
        }
    }
}
