// pbrlab test shader (written for pbrlab, CC0): URP's UniversalFragmentBlinnPhong over a grid of
// inputs read from the UV, so a float64 transcription can be evaluated at each pixel.
// u: the view's angle from the normal, -1.4 .. 1.4 rad in the xz plane; v: the smoothness.
// The normal is +z; the main light comes from the scene's first directional light.
Shader "pbrlab tests/URP Blinn-Phong grid" {
    Properties {
        _BaseColor ("Base Colour", Color) = (0.8, 0.3, 0.2, 1)
        _SpecularTint ("Specular", Color) = (0.5, 0.5, 0.5, 1)
    }
    SubShader {
        Tags { "RenderPipeline" = "UniversalPipeline" "RenderType" = "Opaque" }
        Pass {
            Tags { "LightMode" = "UniversalForward" }
            HLSLPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma multi_compile _ _ADDITIONAL_LIGHTS
            #define _SPECULAR_COLOR
            #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
            #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Lighting.hlsl"

            CBUFFER_START(UnityPerMaterial)
            half4 _BaseColor;
            half4 _SpecularTint;
            CBUFFER_END

            struct Attributes {
                float4 positionOS : POSITION;
                float2 uv : TEXCOORD0;
            };

            struct Varyings {
                float4 positionCS : SV_POSITION;
                float2 uv : TEXCOORD0;
                float3 positionWS : TEXCOORD1;
            };

            Varyings vert(Attributes IN) {
                Varyings OUT;
                VertexPositionInputs positions = GetVertexPositionInputs(IN.positionOS.xyz);
                OUT.positionCS = positions.positionCS;
                OUT.positionWS = positions.positionWS;
                OUT.uv = IN.uv;
                return OUT;
            }

            half4 frag(Varyings IN) : SV_Target {
                float angle = (IN.uv.x * 2.0 - 1.0) * 1.4;
                InputData inputData = (InputData)0;
                inputData.positionWS = IN.positionWS;
                inputData.normalWS = float3(0.0, 0.0, 1.0);
                inputData.viewDirectionWS = float3(sin(angle), 0.0, cos(angle));
                SurfaceData surfaceData = (SurfaceData)0;
                surfaceData.albedo = _BaseColor.rgb;
                surfaceData.specular = _SpecularTint.rgb;
                surfaceData.smoothness = IN.uv.y;
                surfaceData.occlusion = 1.0;
                surfaceData.alpha = 1.0;
                return UniversalFragmentBlinnPhong(inputData, surfaceData);
            }
            ENDHLSL
        }
    }
}
