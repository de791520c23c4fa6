Shader "t/forward add light space" {
    SubShader {
        Pass {
            Tags { "LightMode" = "ForwardBase" }
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "UnityCG.cginc"
            float4 vert(float4 v : POSITION) : SV_POSITION { return UnityObjectToClipPos(v); }
            float4 frag() : SV_Target { return float4(0.0, 0.0, 0.0, 1.0); }
            ENDCG
        }
        Pass {
            Tags { "LightMode" = "ForwardAdd" }
            Blend One One
            CGPROGRAM
            #pragma multi_compile_fwdadd
            #pragma vertex vert
            #pragma fragment frag
            #include "Lighting.cginc"
            #include "AutoLight.cginc"
            struct v2f { float4 pos : SV_POSITION; float3 worldPos : TEXCOORD0; };
            v2f vert(float4 v : POSITION) {
                v2f o;
                o.pos = UnityObjectToClipPos(v);
                o.worldPos = mul(unity_ObjectToWorld, v).xyz;
                return o;
            }
            float4 frag(v2f i) : SV_Target {
            #if defined(POINT)
                float3 lightCoord = mul(unity_WorldToLight, float4(i.worldPos, 1)).xyz;
                float atten = tex2D(_LightTexture0, dot(lightCoord, lightCoord).rr).UNITY_ATTEN_CHANNEL;
                return float4(dot(lightCoord, lightCoord), atten, 0.0, 0.0);
            #elif defined(SPOT)
                float4 lightCoord = mul(unity_WorldToLight, float4(i.worldPos, 1));
                float atten = (lightCoord.z > 0) * tex2D(_LightTexture0, lightCoord.xy / lightCoord.w + 0.5).w
                              * tex2D(_LightTextureB0, dot(lightCoord, lightCoord).rr).UNITY_ATTEN_CHANNEL;
                return float4(lightCoord.xy / lightCoord.w + 0.5, atten, 0.0);
            #else
                return float4(0.0, 0.0, 0.0, 0.0);
            #endif
            }
            ENDCG
        }
    }
}
