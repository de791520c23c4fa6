// The lecture's own example ("DIY linear space in shader"): BlinnPhong with the texture
// decoded by DeGamma (pow 2.2) and the result encoded by ReGamma (pow 1/2.2) in a
// finalcolor function, for a linear (non-sRGB) texture and target.
Shader "Lecture/DIY Gamma" {
    Properties {
        _MainTex ("Texture (sRGB data, sampled raw)", 2D) = "white" {}
        _SpecColor ("Specular Color", Color) = (0.5, 0.5, 0.5, 1)
        _Shininess ("Shininess", Range(0.03, 1)) = 0.3
    }
    SubShader {
        Tags { "RenderType" = "Opaque" }
        CGPROGRAM
        #pragma surface surf BlinnPhong finalcolor:finalgamma
        inline float3 DeGamma (in float3 c) {
            // return c*c;
            return pow(c, 2.2);
        }
        inline float3 ReGamma (in float3 c) {
            // return sqrt(c);
            return pow(c, 1/2.2);
        }
        struct Input {
            float2 uv_MainTex;
        };
        sampler2D _MainTex;
        half _Shininess;
        void finalgamma (Input IN, SurfaceOutput o, inout fixed4 c) {
            c = fixed4(ReGamma(c.xyz),c.a);
        }
        void surf (Input IN, inout SurfaceOutput o) {
            float4 tex = tex2D(_MainTex,IN.uv_MainTex);
            tex.rgb = DeGamma(tex.rgb);
            o.Albedo = tex.rgb;
            o.Specular = _Shininess;
            o.Gloss = 1;
        }
        ENDCG
    }
    Fallback "Diffuse"
}
