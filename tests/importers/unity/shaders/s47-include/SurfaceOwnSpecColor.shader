// s47-include: a surface shader (BlinnPhong) that declares _SpecColor as a half3 of its own: the
// program's albedo reads its own declaration, the lighting the prelude's (same colour).
Shader "s47-include/surface own half3 _SpecColor" {
    Properties { _SpecColor ("Specular", Color) = (0.25, 0.5, 0.75, 1) }
    SubShader {
        CGPROGRAM
        #pragma surface surf Lambert
        half3 _SpecColor;
        struct Input { float2 uv_MainTex; };
        void surf(Input IN, inout SurfaceOutput o) { o.Albedo = 0; o.Emission = half3(_SpecColor); }
        ENDCG
    }
}
