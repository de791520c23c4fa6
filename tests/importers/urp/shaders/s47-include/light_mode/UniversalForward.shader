// s47-include: a pass tagged for URP's forward renderer in a shader naming no RenderPipeline,
// its program CG (a .cginc included): Unity's built-in pipeline draws no pass of this
// LightMode, URP does, so it is a URP shader.
Shader "s47-include/UniversalForward without a pipeline tag" {
    Properties { _Tint ("Tint", Color) = (0.25, 0.5, 0.75, 1) }
    SubShader {
        Pass {
            Tags { "LightMode" = "UniversalForward" }
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "UnityCG.cginc"
            float4 _Tint;
            float4 vert(float4 p : POSITION) : SV_POSITION { return UnityObjectToClipPos(p.xyz); }
            float4 frag() : SV_Target {
                return _Tint;
            }
            ENDCG
        }
    }
}
