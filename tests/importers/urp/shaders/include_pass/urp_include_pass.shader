// pbrlab test shader (written for pbrlab, CC0): a URP pass whose fragment function lives in an
// included file (include_pass.hlsl), as many public URP shaders write theirs: it takes
// FRONT_FACE_TYPE : FRONT_FACE_SEMANTIC, zero-casts a struct, reads an int function of another
// include into a uint, and writes what CreateTangentToWorld and CalculateFinalColor compute.
Shader "pbrlab tests/URP include pass" {
    SubShader {
        Tags { "RenderPipeline" = "UniversalPipeline" }
        Pass {
            HLSLPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
            #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Lighting.hlsl"
            #include "include_pass.hlsl"
            ENDHLSL
        }
    }
}
