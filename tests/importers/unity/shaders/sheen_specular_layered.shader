Shader "pbrlab tests/Sheen (StandardSpecularLayered)" {
// The specular workflow's layered model with a sheen and a coat: the JSON material
// workflow specular, albedo (0.2, 0.3, 0.6), specular 0.04, smoothness 0.5, sheen_color
// (0.6, 0.5, 0.9), sheen_smoothness 0.3, clearcoat 0.5 (tests/importers/unity/test_unity_layered.py).
Properties {
    _Color ("Color", Color) = (0.2, 0.3, 0.6, 1)
    _SpecColor ("Specular", Color) = (0.04, 0.04, 0.04, 1)
    _SheenColor ("Sheen Color", Color) = (0.6, 0.5, 0.9, 1)
}
SubShader {
    CGPROGRAM
    #pragma surface surf StandardSpecularLayered
    fixed4 _Color;
    fixed4 _SpecColor;
    fixed4 _SheenColor;
    struct Input { float3 worldPos; };
    void surf (Input IN, inout SurfaceOutputStandardSpecularLayered o) {
        o.Albedo = _Color.rgb;
        o.Specular = _SpecColor.rgb;
        o.Smoothness = 0.5;
        o.SheenColor = _SheenColor.rgb;
        o.SheenSmoothness = 0.3;
        o.ClearCoatMask = 0.5;
    }
    ENDCG
}
}
