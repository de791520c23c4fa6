// s47-glslinc: a pass whose include in a subfolder (Sub/Pass.hlsl) includes "Common/Tone.hlsl",
// a file found only from the shader's own folder (as lclandrews' URP toon shading's
// TwoTone/ToonTwoToneVertexPass.hlsl includes "Core/ToonURP.hlsl"); Common/Tone.hlsl includes
// URP's Lighting.hlsl and fills URP's SurfaceData (SurfaceData.hlsl, which Core.hlsl does not
// include).
Shader "s47glslinc/ShaderFolderInclude" {
    Properties {
        _Base ("Base", Color) = (0.25, 0.5, 0.125, 1)
    }
    SubShader {
        Tags { "RenderPipeline" = "UniversalPipeline" "RenderType" = "Opaque" }
        Pass {
            Tags { "LightMode" = "UniversalForward" }
            HLSLPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
            half4 _Base;
            #include "Sub/Pass.hlsl"
            ENDHLSL
        }
    }
}
