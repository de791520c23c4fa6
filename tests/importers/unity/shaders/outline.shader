// An inverted-hull outline as users write it: a vertex/fragment Pass drawing the back faces of
// the mesh pushed out along its normals by _Outline, in _OutlineColor, before the surface
// program (Unity draws a SubShader's passes in order).
Shader "pbrlab tests/Outline" {
    Properties {
        _Color ("Color", Color) = (0.8, 0.8, 0.8)
        _OutlineColor ("Outline", Color) = (1, 0, 0, 1)
        _Outline ("Outline width", Range(0, 0.5)) = 0.2
    }
    SubShader {
        Tags { "RenderType" = "Opaque" }
        Pass {
            Name "OUTLINE"
            Cull Front ZWrite On
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "UnityCG.cginc"
            float _Outline;
            fixed4 _OutlineColor;
            struct v2f { float4 pos : SV_POSITION; };
            v2f vert(appdata_base v) {
                v2f o;
                o.pos = UnityObjectToClipPos(v.vertex + float4(v.normal * _Outline, 0));
                return o;
            }
            fixed4 frag(v2f i) : SV_Target { return _OutlineColor; }
            ENDCG
        }
        CGPROGRAM
        #pragma surface surf Lambert
        fixed4 _Color;
        struct Input { float3 worldPos; };
        void surf(Input IN, inout SurfaceOutput o) { o.Albedo = _Color.rgb; }
        ENDCG
    }
    FallBack "Diffuse"
}
