// pbrlab test shader (written for pbrlab, CC0) in the form Shader Graph (URP 12) generates an
// Unlit graph: Attributes, Varyings and PackedVaryings with their pack and unpack functions,
// the graph's SurfaceDescriptionFunction reading _BaseMap through a UnityTexture2D with its
// tiling and offset, times _BaseColor; vert and frag from URP's Shader Graph includes
// (pbrlab's stand-ins: ShaderPass.hlsl, Varyings.hlsl, UnlitPass.hlsl). It draws what
// sg_reference_unlit.shader draws by hand.
Shader "pbrlab tests/Shader Graph unlit texture" {
    Properties {
        _BaseMap ("Base Map", 2D) = "white" {}
        _BaseColor ("Base Colour", Color) = (1, 0.5, 0.25, 1)
    }
    SubShader {
        Tags { "RenderPipeline" = "UniversalPipeline" "RenderType" = "Opaque" "UniversalMaterialType" = "Unlit" }
        Pass {
            Name "Universal Forward"
            Tags { }
            HLSLPROGRAM
            #pragma target 4.5
            #pragma multi_compile_instancing
            #pragma multi_compile_fog
            #pragma vertex vert
            #pragma fragment frag

            #define ATTRIBUTES_NEED_NORMAL
            #define ATTRIBUTES_NEED_TANGENT
            #define ATTRIBUTES_NEED_TEXCOORD0
            #define VARYINGS_NEED_TEXCOORD0
            #define FEATURES_GRAPH_VERTEX
            #define SHADERPASS SHADERPASS_UNLIT

            #include "Packages/com.unity.render-pipelines.core/ShaderLibrary/Color.hlsl"
            #include "Packages/com.unity.render-pipelines.core/ShaderLibrary/Texture.hlsl"
            #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
            #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Lighting.hlsl"
            #include "Packages/com.unity.render-pipelines.core/ShaderLibrary/TextureStack.hlsl"
            #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/ShaderGraphFunctions.hlsl"
            #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/DBuffer.hlsl"
            #include "Packages/com.unity.render-pipelines.universal/Editor/ShaderGraph/Includes/ShaderPass.hlsl"

            struct Attributes {
                float3 positionOS : POSITION;
                float3 normalOS : NORMAL;
                float4 tangentOS : TANGENT;
                float4 uv0 : TEXCOORD0;
            #if UNITY_ANY_INSTANCING_ENABLED
                uint instanceID : INSTANCEID_SEMANTIC;
            #endif
            };
            struct Varyings {
                float4 positionCS : SV_POSITION;
                float4 texCoord0;
            #if UNITY_ANY_INSTANCING_ENABLED
                uint instanceID : CUSTOM_INSTANCE_ID;
            #endif
            };
            struct SurfaceDescriptionInputs {
                float4 uv0;
            };
            struct VertexDescriptionInputs {
                float3 ObjectSpaceNormal;
                float3 ObjectSpaceTangent;
                float3 ObjectSpacePosition;
            };
            struct PackedVaryings {
                float4 positionCS : SV_POSITION;
                float4 interp0 : INTERP0;
            #if UNITY_ANY_INSTANCING_ENABLED
                uint instanceID : CUSTOM_INSTANCE_ID;
            #endif
            };

            PackedVaryings PackVaryings(Varyings input) {
                PackedVaryings output;
                ZERO_INITIALIZE(PackedVaryings, output);
                output.positionCS = input.positionCS;
                output.interp0.xyzw = input.texCoord0;
                return output;
            }
            Varyings UnpackVaryings(PackedVaryings input) {
                Varyings output;
                output.positionCS = input.positionCS;
                output.texCoord0 = input.interp0.xyzw;
                return output;
            }

            CBUFFER_START(UnityPerMaterial)
            float4 _BaseMap_TexelSize;
            float4 _BaseMap_ST;
            float4 _BaseColor;
            CBUFFER_END
            TEXTURE2D(_BaseMap);
            SAMPLER(sampler_BaseMap);

            void Unity_Multiply_float4_float4(float4 A, float4 B, out float4 Out) { Out = A * B; }

            struct VertexDescription {
                float3 Position;
                float3 Normal;
                float3 Tangent;
            };
            VertexDescription VertexDescriptionFunction(VertexDescriptionInputs IN) {
                VertexDescription description = (VertexDescription)0;
                description.Position = IN.ObjectSpacePosition;
                description.Normal = IN.ObjectSpaceNormal;
                description.Tangent = IN.ObjectSpaceTangent;
                return description;
            }

            struct SurfaceDescription {
                float3 BaseColor;
                float Alpha;
            };
            SurfaceDescription SurfaceDescriptionFunction(SurfaceDescriptionInputs IN) {
                SurfaceDescription surface = (SurfaceDescription)0;
                UnityTexture2D _Property_0_Out_0 = UnityBuildTexture2DStruct(_BaseMap);
                float4 _SampleTexture2D_1_RGBA_0 = SAMPLE_TEXTURE2D(_Property_0_Out_0.tex, _Property_0_Out_0.samplerstate,
                                                                    _Property_0_Out_0.GetTransformedUV(IN.uv0.xy));
                float4 _Multiply_2_Out_2;
                Unity_Multiply_float4_float4(_SampleTexture2D_1_RGBA_0, _BaseColor, _Multiply_2_Out_2);
                surface.BaseColor = (_Multiply_2_Out_2.xyz);
                surface.Alpha = 1;
                return surface;
            }

            VertexDescriptionInputs BuildVertexDescriptionInputs(Attributes input) {
                VertexDescriptionInputs output;
                ZERO_INITIALIZE(VertexDescriptionInputs, output);
                output.ObjectSpaceNormal = input.normalOS;
                output.ObjectSpaceTangent = input.tangentOS.xyz;
                output.ObjectSpacePosition = input.positionOS;
                return output;
            }
            SurfaceDescriptionInputs BuildSurfaceDescriptionInputs(Varyings input) {
                SurfaceDescriptionInputs output;
                ZERO_INITIALIZE(SurfaceDescriptionInputs, output);
                output.uv0 = input.texCoord0;
                return output;
            }

            #include "Packages/com.unity.render-pipelines.universal/Editor/ShaderGraph/Includes/Varyings.hlsl"
            #include "Packages/com.unity.render-pipelines.universal/Editor/ShaderGraph/Includes/UnlitPass.hlsl"
            ENDHLSL
        }
    }
}
