// pbrlab stand-in for "Legacy Shaders/Diffuse", one of the shaders Unity ships with the editor
// (no project holds its file, so a Fallback "Diffuse" found nothing before; parse.find_shader
// searches this folder after the project's and $PBRLAB_UNITY_SHADERS). Written by pbrlab from
// Unity's manual ("Diffuse", the Normal Shader Family: a Lambertian lighting model; its
// properties "Main Color" and "Base (RGB)", the texture times the colour), not from Unity's file.
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
Shader "Legacy Shaders/Diffuse" {
    Properties {
        _Color ("Main Color", Color) = (1, 1, 1, 1)
        _MainTex ("Base (RGB)", 2D) = "white" {}
    }
    SubShader {
        Tags { "RenderType" = "Opaque" }
        CGPROGRAM
        #pragma surface surf Lambert
        sampler2D _MainTex;
        fixed4 _Color;
        struct Input { float2 uv_MainTex; };
        void surf(Input IN, inout SurfaceOutput o) {
            fixed4 albedo = tex2D(_MainTex, IN.uv_MainTex) * _Color;
            o.Albedo = albedo.rgb;
            o.Alpha = albedo.a;
        }
        ENDCG
    }
}
