// s46: a geometry stage whose output struct declares a nointerpolation member: each triangle's
// first and last vertices carry 0.75, its middle one 0.25, so a flat value is 0.75 whichever
// vertex provokes (Direct3D's first, OpenGL's last) and an interpolated one lies below it
Shader "pbrlab-test/geometry_nointerpolation" {
    SubShader {
        Pass {
            Cull Off
            CGPROGRAM
            #pragma vertex vert
            #pragma geometry geom
            #pragma fragment frag
            #include "UnityCG.cginc"
            struct v2g { float4 pos : SV_POSITION; };
            struct g2f { float4 pos : SV_POSITION; nointerpolation float value : TEXCOORD0; };
            v2g vert(appdata_base v) { v2g o; o.pos = UnityObjectToClipPos(v.vertex); return o; }
            [maxvertexcount(3)]
            void geom(triangle v2g IN[3], inout TriangleStream<g2f> stream) {
                g2f o;
                for (int k = 0; k < 3; k++) {
                    o.pos = IN[k].pos;
                    o.value = k == 1 ? 0.25 : 0.75;
                    stream.Append(o);
                }
            }
            float4 frag(g2f i) : SV_Target { return float4(i.value, 0.5, 0.125, 1.0); }
            ENDCG
        }
    }
}
