// pbrlab test shader (written for pbrlab, CC0): a function whose texture lookups take their
// offset from its own parameter, each call passing a constant (FXC inlines the calls, so the
// offset is an immediate there), and a float3 initialised from the float4 lookup (truncated).
Shader "pbrlab tests/URP sample offset parameter" {
    Properties { _Grid ("Grid", 2D) = "white" {} }
    SubShader {
        Tags { "RenderPipeline" = "UniversalPipeline" }
        Pass {
            HLSLPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"

            Texture2D _Grid;
            SamplerState sampler_Grid;

            struct Attributes { float4 positionOS : POSITION; };
            struct Varyings { float4 positionCS : SV_POSITION; };

            Varyings vert(Attributes IN) {
                Varyings OUT;
                OUT.positionCS = TransformObjectToHClip(IN.positionOS.xyz);
                return OUT;
            }

            // the texels beside the one at uv, delta * -1 and delta * 1 away, and delta * 2 at LOD 0
            float4 Beside(float2 uv, int2 delta, Texture2D t, SamplerState s) {
                float3 before = t.Sample(s, uv, delta * -1);
                float3 after = t.Sample(s, uv, delta * 1);
                return float4(before.r, after.r, t.SampleLevel(s, uv, 0, delta * 2).r, 1.0);
            }

            float4 frag(Varyings IN) : SV_Target {
                float2 uv = float2(1.5, 1.5) / 4.0;  // the centre of texel (1, 1) of the 4 x 4 grid
                float4 across = Beside(uv, int2(1, 0), _Grid, sampler_Grid);
                float4 up = Beside(uv, int2(0, 1), _Grid, sampler_Grid);
                return float4(across.rgb * 0.5 + up.rgb * 0.25, 1.0);
            }
            ENDHLSL
        }
    }
}
