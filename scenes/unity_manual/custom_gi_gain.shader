// Lighting examples, "Custom GI" with the GI modified: a (s, gi) model that shows only the
// indirect diffuse light, which its _GI function scales by _Gain.
Shader "Example/CustomGI_Gain" {
    Properties {
        _MainTex ("Albedo (RGB)", 2D) = "white" {}
        _Gain ("Ambient gain", Range(0, 4)) = 2.0
    }
    SubShader {
        Tags { "RenderType"="Opaque" }
        CGPROGRAM
        #pragma surface surf AmbientOnly
        #include "Lighting.cginc"
        sampler2D _MainTex;
        half _Gain;
        inline half4 LightingAmbientOnly(SurfaceOutput s, UnityGI gi)
        {
            return half4(s.Albedo * gi.indirect.diffuse, s.Alpha);
        }
        inline void LightingAmbientOnly_GI(SurfaceOutput s, UnityGIInput data, inout UnityGI gi)
        {
            gi = UnityGlobalIllumination(data, 1.0, s.Normal);
            gi.indirect.diffuse *= _Gain;
        }
        struct Input {
            float2 uv_MainTex;
        };
        void surf (Input IN, inout SurfaceOutput o) {
            o.Albedo = tex2D (_MainTex, IN.uv_MainTex).rgb * 0.5;
            o.Alpha = 1;
        }
        ENDCG
    }
    FallBack "Diffuse"
}
