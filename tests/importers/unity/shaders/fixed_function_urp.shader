// s46: an unlit fixed-function pass (no program) in a URP SubShader: Unity converts it to a
// vertex/fragment program at import, and URP draws the untagged pass (SRPDefaultUnlit)
Shader "pbrlab-test/fixed_function_urp" {
    Properties {
        _Color ("Color", Color) = (0.25, 0.5, 0.75, 1)
        _MainTex ("Texture", 2D) = "gray" {}
    }
    SubShader {
        Tags { "RenderPipeline" = "UniversalPipeline" }
        Pass {
            Color [_Color]
            SetTexture [_MainTex] { combine texture * primary DOUBLE }
        }
    }
}
