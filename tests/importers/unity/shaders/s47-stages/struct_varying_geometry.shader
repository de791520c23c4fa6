// s47-stages: a struct varying (v2g.inner, a struct member with a semantic) read by a point-input
// geometry function: the square around the point is coloured by (IN[0].inner.uv, 0.5). The plane's
// corners (x, z) / 0.3 are placed at clip (S x / 0.3, -S z / 0.3, 0, 1) (no camera).
Shader "s47-stages/struct_varying_geometry" {
    SubShader { Pass {
        Cull Off
        CGPROGRAM
        #pragma target 4.0
        #pragma vertex vert
        #pragma geometry geom
        #pragma fragment frag
        #include "UnityCG.cginc"
        #define S 0.6
        #define HALF 0.1
        struct In { float2 uv; }; struct v2g { float4 pos : SV_POSITION; In inner : TEXCOORD0; };
        struct g2f { float4 pos : SV_POSITION; float3 colour : TEXCOORD0; };
        v2g vert(appdata_base v) {
            v2g o;
            o.pos = float4(S * v.vertex.x / 0.3, -S * v.vertex.z / 0.3, 0.0, 1.0);
            o.inner.uv = v.texcoord.xy;
            return o;
        }
        [maxvertexcount(4)]
        void geom(point v2g IN[1], inout TriangleStream<g2f> stream) {
            g2f o;
            o.colour = float3(IN[0].inner.uv, 0.5);
            for (int k = 0; k < 4; k++) {
                float2 corner = float2(k & 1 ? HALF : -HALF, k & 2 ? HALF : -HALF);
                o.pos = IN[0].pos + float4(corner, 0, 0);
                stream.Append(o);
            }
        }
        float4 frag(g2f i) : SV_Target { return float4(i.colour, 1); }
        ENDCG
    } }
}
