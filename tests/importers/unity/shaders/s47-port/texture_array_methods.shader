// s47-port: a Direct3D 11 Texture2DArray sampled through its methods (Sample, SampleLevel), as
// a built-in-pipeline program may declare it; the property's default "gray" fills the array's one
// layer (texture_arrays.py), which every layer index reads.
Shader "s47port/TextureArrayMethods" {
    Properties {
        _Layers ("Layers", 2DArray) = "gray" {}
    }
    SubShader {
        Pass {
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "UnityCG.cginc"
            Texture2DArray<float4> _Layers;
            SamplerState sampler_Layers;
            struct v2f { float4 pos : SV_POSITION; float2 uv : TEXCOORD0; };
            v2f vert(float4 vertex : POSITION, float2 uv : TEXCOORD0) {
                v2f o; o.pos = UnityObjectToClipPos(vertex); o.uv = uv; return o; }
            float4 frag(v2f i) : SV_Target {
                float4 a = _Layers.Sample(sampler_Layers, float3(i.uv, 0));
                float4 b = _Layers.SampleLevel(sampler_Layers, float3(i.uv, 1), 0);
                return float4(a.r * 0.5, b.g, 0.25, 1);
            }
            ENDCG
        }
    }
}
