// pbrlab test shader (written for pbrlab, CC0): a two-band toon ramp as real URP toon shaders
// write one: URP's GetMainLight, N.L stepped at _Threshold into _LitColor or _ShadeColor
// (no ambient, no additional lights), unlit otherwise.
Shader "pbrlab tests/URP toon ramp" {
    Properties {
        _LitColor ("Lit", Color) = (1, 0.75, 0.5, 1)
        _ShadeColor ("Shade", Color) = (0.25, 0.125, 0.5, 1)
        _Threshold ("Threshold", Range(0, 1)) = 0.5
    }
    SubShader {
        Tags { "RenderPipeline" = "UniversalPipeline" }
        Pass {
            Tags { "LightMode" = "UniversalForward" }
            HLSLPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
            #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Lighting.hlsl"

            CBUFFER_START(UnityPerMaterial)
            half4 _LitColor;
            half4 _ShadeColor;
            half _Threshold;
            CBUFFER_END

            struct Attributes {
                float4 positionOS : POSITION;
                float3 normalOS : NORMAL;
            };
            struct Varyings {
                float4 positionCS : SV_POSITION;
                float3 normalWS : TEXCOORD0;
            };

            Varyings vert(Attributes IN) {
                Varyings OUT = (Varyings)0;
                VertexPositionInputs position = GetVertexPositionInputs(IN.positionOS.xyz);
                VertexNormalInputs normal = GetVertexNormalInputs(IN.normalOS);
                OUT.positionCS = position.positionCS;
                OUT.normalWS = normal.normalWS;
                return OUT;
            }

            half4 frag(Varyings IN) : SV_Target {
                Light mainLight = GetMainLight();
                half NdotL = dot(normalize(IN.normalWS), mainLight.direction);
                half band = step(_Threshold, NdotL);
                return half4(lerp(_ShadeColor.rgb, _LitColor.rgb, band), 1.0);
            }
            ENDHLSL
        }
    }
}
