// pbrlab test shader (written for pbrlab, CC0): varyings under custom semantics (HLSL allows any
// identifier), the fragment function reading them as parameters in another order than the
// vertex function's struct writes them: linked by semantic, it writes the UV urp_uv.shader writes.
Shader "pbrlab tests/URP custom semantic" {
    SubShader {
        Tags { "RenderPipeline" = "UniversalPipeline" }
        Pass {
            HLSLPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"

            struct Attributes {
                float4 positionOS : POSITION;
                float2 uv : TEXCOORD0;
            };

            struct Varyings {
                float4 positionCS : SV_POSITION;
                float v : MY_V;
                float u : FOG_FACTOR;
            };

            Varyings vert(Attributes IN) {
                Varyings OUT;
                OUT.positionCS = TransformObjectToHClip(IN.positionOS.xyz);
                OUT.v = IN.uv.y;
                OUT.u = IN.uv.x > 2.0 ? 0.0 : IN.uv.x;
                return OUT;
            }

            float4 frag(float4 positionCS : SV_POSITION, float u : FOG_FACTOR, float v : MY_V) : SV_Target {
                return float4(u, v, 0.0, 1.0);
            }
            ENDHLSL
        }
    }
}
