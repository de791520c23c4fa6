// Vertex colour: a vertex function sets v.color, the surface function reads Input.color.
Shader "t" { SubShader { CGPROGRAM
#pragma surface surf Lambert vertex:vert
struct Input { float2 uv_MainTex; float4 color : COLOR; };
void vert (inout appdata_full v) { v.color = float4(abs(v.normal), 1); }
sampler2D _MainTex;
void surf (Input IN, inout SurfaceOutput o) { o.Albedo = tex2D(_MainTex, IN.uv_MainTex).rgb * IN.color.rgb; }
ENDCG } }
