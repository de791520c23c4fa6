// pbrlab test shader (session 47): HLSL flow attributes given through a program's own macros,
// as URP's SubpixelMorphologicalAntialiasing.hlsl writes them (#define SMAA_FLATTEN [flatten]).
Shader "pbrlab/s47/AttributeMacros" {
  SubShader {
    Pass {
      CGPROGRAM
      #pragma vertex vert
      #pragma fragment frag
      #include "UnityCG.cginc"
      #define MY_FLATTEN [flatten]
      #define MY_BRANCH  [ branch ]
      #define MY_UNROLL [unroll(4)]
      struct v2f { float4 pos : SV_POSITION; float2 uv : TEXCOORD0; };
      v2f vert(appdata_base v) { v2f o; o.pos = UnityObjectToClipPos(v.vertex); o.uv = v.texcoord.xy; return o; }
      fixed4 frag(v2f i) : SV_Target {
          float4 c = float4(0, 0, 0, 1);
          MY_FLATTEN if (frac(i.uv.x * 8) > 0.5) c.r = 1;
          MY_BRANCH if (frac(i.uv.y * 8) > 0.5) c.g = 1;
          MY_UNROLL for (int k = 0; k < 4; k++) { c.b += 0.125; }
          return c;
      }
      ENDCG
    }
  }
}
