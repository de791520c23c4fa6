// s47-stages: a hull function whose [partitioning(...)] argument is a macro (as Catlike
// Coding's tessellation tutorial and many shaders write it), with Unity's UNITY_ attribute
// spellings. Each plane triangle is a patch in NDC (no camera); the domain function pushes the
// vertices on a patch edge outward by h = 4 A s t (s, t: the edge's two other coordinates).
Shader "s47-stages/urp_partitioning_macro" {
    SubShader { Tags { "RenderPipeline" = "UniversalPipeline" } Pass {
        Tags { "LightMode" = "UniversalForward" }
        Cull Off
        HLSLPROGRAM
        #pragma target 5.0
        #pragma vertex vert
        #pragma hull hull
        #pragma domain domain
        #pragma fragment frag
        #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
        // (URP shaders define the UNITY_ spellings themselves, Core.hlsl has none)
        #define UNITY_domain domain
        #define UNITY_outputtopology outputtopology
        #define UNITY_patchconstantfunc patchconstantfunc
        #define UNITY_partitioning partitioning
        #define UNITY_outputcontrolpoints outputcontrolpoints
        #define MY_INTEGER "integer"
        #define PARTITION_METHOD MY_INTEGER
        #ifndef PARTITION_METHOD  // (a library's default, as Catlike Coding-derived includes write it: not taken)
        #define PARTITION_METHOD "fractional_odd"
        #endif
        #define CONTROL_POINTS 3
        #define LEVEL 2.5
        #define HALF_SIDE 0.6
        #define BULGE 0.25
        struct CP { float4 position : INTERNALTESSPOS; };
        struct Levels { float edge[3] : SV_TessFactor; float inside : SV_InsideTessFactor; };
        struct v2f { float4 pos : SV_POSITION; };
        struct Attributes { float4 positionOS : POSITION; };
        CP vert(Attributes v) {
            CP o;
            o.position = float4(HALF_SIDE * v.positionOS.x / 0.3, -HALF_SIDE * v.positionOS.z / 0.3, 0.0, 1.0);
            return o;
        }
        Levels levels(InputPatch<CP, 3> patch) {
            Levels l;
            l.edge[0] = LEVEL; l.edge[1] = LEVEL; l.edge[2] = LEVEL; l.inside = LEVEL;
            return l;
        }
        [UNITY_domain("tri")]
        [UNITY_outputcontrolpoints(CONTROL_POINTS)]
        [UNITY_outputtopology("triangle_cw")]
        [UNITY_partitioning(PARTITION_METHOD)]
        [UNITY_patchconstantfunc("levels")]
        CP hull(InputPatch<CP, 3> patch, uint id : SV_OutputControlPointID) { return patch[id]; }
        float2 away(float2 p0, float2 p1, float2 opposite) {
            float2 e = p1 - p0;
            float2 n = normalize(float2(-e.y, e.x));
            return dot(n, opposite - p0) > 0 ? -n : n;
        }
        [UNITY_domain("tri")]
        v2f domain(Levels l, OutputPatch<CP, 3> patch, float3 b : SV_DomainLocation) {
            v2f o;
            float4 p = patch[0].position * b.x + patch[1].position * b.y + patch[2].position * b.z;
            float2 p0 = patch[0].position.xy, p1 = patch[1].position.xy, p2 = patch[2].position.xy;
            if (b.x == 0) p.xy += away(p1, p2, p0) * 4 * BULGE * b.y * b.z;
            if (b.y == 0) p.xy += away(p0, p2, p1) * 4 * BULGE * b.x * b.z;
            if (b.z == 0) p.xy += away(p0, p1, p2) * 4 * BULGE * b.x * b.y;
            o.pos = p;
            return o;
        }
        float4 frag(v2f i) : SV_Target { return 1; }
        ENDHLSL
    } }
}
