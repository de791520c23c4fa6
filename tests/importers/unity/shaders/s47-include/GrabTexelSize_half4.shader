// s47-include: a GrabPass's texture whose _TexelSize the program declares as half4: Unity sets
// (1/width, 1/height, width, height) into the type the program declares.
Shader "s47-include/grab texel size half4" {
    SubShader {
        Tags { "Queue" = "Transparent" }
        GrabPass { }
        Pass {
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "UnityCG.cginc"
            sampler2D _GrabTexture;
            half4 _GrabTexture_TexelSize;
            float4 vert(float4 p : POSITION) : SV_POSITION { return UnityObjectToClipPos(p.xyz); }
            float4 frag() : SV_Target {
                return float4(_GrabTexture_TexelSize.xy * 16.0, 0.75, 1.0);
            }
            ENDCG
        }
    }
}
