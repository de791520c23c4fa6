// s47-stages: a struct-typed member inside the vertex stage's output struct (a varying that is a
// struct). The plane's uv reaches the fragment through v2f.inner.uv and v2f.inner.tint.
Shader "s47-stages/struct_varying" {
    SubShader { Pass {
        Cull Off
        CGPROGRAM
        #pragma vertex vert
        #pragma fragment frag
        #include "UnityCG.cginc"
        struct Inner { float2 uv; float tint; };
        struct v2f { float4 pos : SV_POSITION; Inner inner : TEXCOORD0; float w : TEXCOORD2; };
        v2f vert(appdata_base v) {
            v2f o;
            o.pos = float4(v.vertex.x / 0.3, -v.vertex.z / 0.3, 0.0, 1.0);
            o.inner.uv = v.texcoord.xy;
            o.inner.tint = 0.25;
            o.w = 0.75;
            return o;
        }
        float4 frag(v2f i) : SV_Target { return float4(i.inner.uv, i.inner.tint, i.w); }
        ENDCG
    } }
}
