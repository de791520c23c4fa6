// A custom lighting function that branches on Unity's per-light keywords, as UI-Lit-* and
// many toon shaders do: red marks a light seen as directional, green one seen as a point
// light, blue one seen as neither.
Shader "pbrlab tests/Light keywords" {
    SubShader {
        CGPROGRAM
        #pragma surface surf Marked
        struct Input { float3 worldPos; };
        half4 LightingMarked(SurfaceOutput s, half3 lightDir, half atten) {
        #if defined(USING_DIRECTIONAL_LIGHT)
            return half4(_LightColor0.rgb * half3(1, 0, 0), 1);
        #elif defined(POINT)
            return half4(_LightColor0.rgb * half3(0, 1, 0), 1);
        #else
            return half4(0, 0, _LightColor0.b, 1);
        #endif
        }
        void surf(Input IN, inout SurfaceOutput o) { o.Albedo = 0; }
        ENDCG
    }
}
