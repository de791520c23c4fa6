// s47-include: a URP program that declares _SpecColor as a half3 of its own (pbrlab's Unity
// prelude declares a float4 _SpecColor; URP's core declares none): the program's is the only one.
Shader "s47-include/own half3 _SpecColor (Global)" {
    Properties { _SpecColor ("Specular", Color) = (0.25, 0.5, 0.75, 0.125) }
    SubShader {
        Tags { "RenderPipeline" = "UniversalPipeline" }
        Pass {
            Tags { "LightMode" = "UniversalForward" }
            HLSLPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
            half3 _SpecColor;
            float4 vert(float4 p : POSITION) : SV_POSITION { return TransformObjectToHClip(p.xyz); }
            half4 frag() : SV_Target { return half4(_SpecColor, 1.0); }
            ENDHLSL
        }
    }
}
