// s46: Unity's desktop UnpackScaleNormal (UnpackNormalmapRGorAG: x = r * a, y = g, z rebuilt)
// of a [Normal] property's default texture "gray" (0.5, 0.5, 0.5, 0.5), written out * 0.5 + 0.5
Shader "pbrlab-test/normal_map_unpack" {
    Properties {
        [Normal] _BumpMap ("Normal map", 2D) = "gray" {}
        _BumpScale ("Scale", Range(0, 1)) = 0.5
    }
    SubShader {
        Pass {
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "UnityCG.cginc"
            #include "UnityStandardUtils.cginc"
            sampler2D _BumpMap;
            float _BumpScale;
            struct v2f { float4 pos : SV_POSITION; float2 uv : TEXCOORD0; };
            v2f vert(appdata_base v) { v2f o; o.pos = UnityObjectToClipPos(v.vertex); o.uv = v.texcoord.xy; return o; }
            float4 frag(v2f i) : SV_Target {
                float3 n = UnpackScaleNormal(tex2D(_BumpMap, i.uv), _BumpScale);
                return float4(n * 0.5 + 0.5, 1.0);
            }
            ENDCG
        }
    }
}
