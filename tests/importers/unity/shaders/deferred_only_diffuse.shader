// s46: one SubShader whose only pass is the deferred path's; its Fallback "Diffuse" (Unity's legacy
// Lambert shader, shipped with the editor) is what Unity's forward path draws
Shader "pbrlab-test/deferred_only_diffuse" {
    Properties {
        _Color ("Main Color", Color) = (1, 1, 1, 1)
        _MainTex ("Base (RGB)", 2D) = "white" {}
    }
    SubShader {
        Pass {
            Tags { "LightMode" = "Deferred" }
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "UnityCG.cginc"
            float4 vert(float4 v : POSITION) : SV_POSITION { return UnityObjectToClipPos(v); }
            float4 frag() : SV_Target { return float4(1.0, 0.0, 0.0, 1.0); }
            ENDCG
        }
    }
    Fallback "Diffuse"
}
