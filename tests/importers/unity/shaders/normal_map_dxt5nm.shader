// s46: a normal map read as Unity stores it on desktop (DXT5nm: 1, y, 1, x): UnpackNormalDXT5nm
// reads .wy, and the raw .rgb shows the layout; written out * 0.5 + 0.5 and as the raw texel
Shader "pbrlab-test/normal_map_dxt5nm" {
    Properties {
        [Normal] _NormalMap ("Normal map", 2D) = "bump" {}
        _Raw ("Raw texel instead", Float) = 0
    }
    SubShader {
        Pass {
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "UnityCG.cginc"
            sampler2D _NormalMap;
            float _Raw;
            struct v2f { float4 pos : SV_POSITION; float2 uv : TEXCOORD0; };
            v2f vert(appdata_base v) { v2f o; o.pos = UnityObjectToClipPos(v.vertex); o.uv = v.texcoord.xy; return o; }
            float4 frag(v2f i) : SV_Target {
                float4 packed = tex2D(_NormalMap, i.uv);
                float3 n = UnpackNormalDXT5nm(packed) * 0.5 + 0.5;
                return float4(_Raw > 0.5 ? packed.rgb : n, 1.0);
            }
            ENDCG
        }
    }
}
