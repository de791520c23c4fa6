Shader "pbrlab tests/Clear coat (StandardLayered)" {
// A surface shader on pbrlab's layered Standard model: Unity's SurfaceOutputStandard fields
// plus URP's clear-coat names. The same material as the JSON fields albedo (0.8, 0.3, 0.2),
// metallic 0.25, smoothness 0.4, clearcoat 1, clearcoat_smoothness 0.85
// (tests/importers/unity/test_unity_layered.py).
Properties {
    _Color ("Color", Color) = (0.8, 0.3, 0.2, 1)
    _Glossiness ("Smoothness", Range(0, 1)) = 0.4
    _Metallic ("Metallic", Range(0, 1)) = 0.25
    _ClearCoatSmoothness ("Clear Coat Smoothness", Range(0, 1)) = 0.85
}
SubShader {
    Tags { "RenderType" = "Opaque" }
    CGPROGRAM
    #pragma surface surf StandardLayered fullforwardshadows
    fixed4 _Color;
    half _Glossiness;
    half _Metallic;
    half _ClearCoatSmoothness;
    struct Input { float3 worldPos; };
    void surf (Input IN, inout SurfaceOutputStandardLayered o) {
        o.Albedo = _Color.rgb;
        o.Metallic = _Metallic;
        o.Smoothness = _Glossiness;
        o.ClearCoatMask = 1;
        o.ClearCoatSmoothness = _ClearCoatSmoothness;
    }
    ENDCG
}
}
