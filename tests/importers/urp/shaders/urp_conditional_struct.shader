// pbrlab test shader (written for pbrlab, CC0): what real URP passes spell and the GLSL port
// must carry: Core RP's Packing.hlsl and UnityInstancing.hlsl and URP's
// ShaderVariablesFunctions.hlsl (pbrlab's stand-ins), a Varyings whose members depend on #if
// lines and macro members, zeroed by (Varyings)0; a default argument with a half literal
// (0.5h); rcp; a semantic before an #if line in a parameter list. It draws (0.5 u, v, 0) at each pixel: the
// member the #if keeps and vert never writes is 0 (its zero), rcp(2) halves the red.
Shader "pbrlab tests/URP conditional struct" {
    SubShader {
        Tags { "RenderPipeline" = "UniversalPipeline" }
        Pass {
            HLSLPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "Packages/com.unity.render-pipelines.core/ShaderLibrary/Packing.hlsl"
            #include "Packages/com.unity.render-pipelines.core/ShaderLibrary/UnityInstancing.hlsl"
            #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/ShaderVariablesFunctions.hlsl"

            #define PBRLAB_TEST_KEEP_UV 1

            struct Attributes {
                float4 positionOS : POSITION;
                float2 uv : TEXCOORD0;
                UNITY_VERTEX_INPUT_INSTANCE_ID
            };

            struct Varyings {
                float4 positionCS : SV_POSITION;
            #if PBRLAB_TEST_KEEP_UV
                float2 uv : TEXCOORD0;
                float unwritten : TEXCOORD1;
            #else
                float3 uv : TEXCOORD0;
            #endif
                UNITY_VERTEX_INPUT_INSTANCE_ID
                UNITY_VERTEX_OUTPUT_STEREO
            };

            half scaled(half x, half s = 0.5h) { return x * s; }

            Varyings vert(Attributes IN) {
                Varyings OUT = (Varyings)0;
                UNITY_SETUP_INSTANCE_ID(IN);
                OUT.positionCS = TransformObjectToHClip(IN.positionOS.xyz);
                OUT.uv = IN.uv;
                return OUT;
            }

            // a function of another pass (the drawn pass does not call it), its parameter list
            // ending under an #if after a semantic, as URP's DepthNormals passes write it
            void otherPassFragment(Varyings IN, out half4 outNormal : SV_Target0
            #if PBRLAB_TEST_KEEP_UV
                , out float4 outLayers : SV_Target1
            #endif
                ) {
                outNormal = half4(0.0, 0.0, 1.0, 1.0);
            #if PBRLAB_TEST_KEEP_UV
                outLayers = float4(0.0, 0.0, 0.0, 0.0);
            #endif
            }

            half4 frag(Varyings IN) : SV_Target {
                return half4(scaled(IN.uv.x) * rcp(0.5) * 0.5, IN.uv.y, IN.unwritten, 1.0);
            }
            ENDHLSL
        }
    }
}
