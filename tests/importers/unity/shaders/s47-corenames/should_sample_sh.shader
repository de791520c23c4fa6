// s47-corenames: a built-in ForwardBase vertex/fragment pass that returns the ambient probe's SH
// at a normal where UnityCG's UNITY_SHOULD_SAMPLE_SH says so, else a marker colour; the test
// (test_builtin_s47_corenames.py) fills in the keyword pragma and the pass define.
Shader "Test/S47ShouldSampleSH"
{
    SubShader
    {
        Pass
        {
            Tags { "LightMode" = "ForwardBase" }
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            %(pragmas)s
            #include "UnityCG.cginc"
            struct v2f { float4 pos : SV_POSITION; };
            v2f vert(float4 p : POSITION)
            {
                v2f o;
                o.pos = UnityObjectToClipPos(p);
                return o;
            }
            float4 frag(v2f i) : SV_Target
            {
                float3 c = float3(1.0, 0.0, 1.0);
            #if UNITY_SHOULD_SAMPLE_SH
                c = ShadeSH9(float4(0.0, 1.0, 0.0, 1.0));
            #endif
                return float4(c, 1.0);
            }
            ENDCG
        }
    }
}
