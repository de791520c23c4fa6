// s47-port: a URP program's 2D texture array declared by Core RP's TEXTURE2D_ARRAY and sampled
// through the object's methods (what the macro declares on Direct3D 11: a Texture2DArray) beside
// Core RP's SAMPLE_TEXTURE2D_ARRAY; the property's default "gray" fills the array's one layer.
Shader "s47port/TextureArrayMacroMethods" {
    Properties {
        _Layers ("Layers", 2DArray) = "gray" {}
    }
    SubShader {
        Tags { "RenderPipeline" = "UniversalPipeline" "RenderType" = "Opaque" }
        Pass {
            Tags { "LightMode" = "UniversalForward" }
            HLSLPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
            TEXTURE2D_ARRAY(_Layers); SAMPLER(sampler_Layers);
            struct Attributes { float4 positionOS : POSITION; float2 uv : TEXCOORD0; };
            struct Varyings { float4 positionCS : SV_POSITION; float2 uv : TEXCOORD0; };
            Varyings vert(Attributes input) {
                Varyings output;
                output.positionCS = TransformObjectToHClip(input.positionOS.xyz);
                output.uv = input.uv;
                return output;
            }
            float4 frag(Varyings input) : SV_Target {
                float4 a = _Layers.Sample(sampler_Layers, float3(input.uv, 0));
                float4 b = _Layers.SampleLevel(sampler_Layers, float3(input.uv, 2), 0);
                float4 c = SAMPLE_TEXTURE2D_ARRAY(_Layers, sampler_Layers, input.uv, 1);
                return float4(a.r * 0.5, b.g, c.b * 0.25, 1.0);
            }
            ENDHLSL
        }
    }
}
