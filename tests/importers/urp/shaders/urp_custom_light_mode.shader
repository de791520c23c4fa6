// A pass of a custom LightMode tag (drawn in URP by a Render Objects renderer feature) returning
// a constant colour, and a ShadowCaster pass (URP's own: skipped; red, to tell it apart)
// (tests/importers/urp/test_urp_passes.py replaces the tag for its controls).
Shader "pbrlab tests/urp custom light mode" {
    SubShader {
        Tags { "RenderPipeline" = "UniversalPipeline" "RenderType" = "Opaque" }
        HLSLINCLUDE
        #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
        struct Attributes { float4 positionOS : POSITION; };
        struct Varyings { float4 positionCS : SV_POSITION; };
        Varyings vert(Attributes IN) {
            Varyings OUT;
            OUT.positionCS = TransformObjectToHClip(IN.positionOS.xyz);
            return OUT;
        }
        ENDHLSL
        Pass {
            Name "Highlight"
            Tags { "LightMode" = "PbrlabHighlight" }
            HLSLPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            float4 frag(Varyings IN) : SV_Target { return float4(0.25, 0.5, 0.75, 1.0); }
            ENDHLSL
        }
        Pass {
            Name "ShadowCaster"
            Tags { "LightMode" = "ShadowCaster" }
            HLSLPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            float4 frag(Varyings IN) : SV_Target { return float4(1.0, 0.0, 0.0, 1.0); }
            ENDHLSL
        }
    }
}
