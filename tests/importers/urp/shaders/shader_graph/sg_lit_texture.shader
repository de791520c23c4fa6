// pbrlab test shader (written for pbrlab, CC0) in the form Shader Graph (URP 12) generates a
// Lit graph: as sg_unlit_texture.shader, with the normal, position and view direction carried
// (VARYINGS_NEED_*), the Lit stack's outputs (Base Color from _BaseMap times _BaseColor,
// Normal (tangent space, straight up), Metallic, Smoothness, Occlusion, Emission) and
// PBRForwardPass.hlsl's vert and frag. It draws what sg_reference_lit.shader draws by hand.
Shader "pbrlab tests/Shader Graph lit texture" {
    Properties {
        _BaseMap ("Base Map", 2D) = "white" {}
        _BaseColor ("Base Colour", Color) = (1, 0.5, 0.25, 1)
        _Metallic ("Metallic", Range(0, 1)) = 0.25
        _Smoothness ("Smoothness", Range(0, 1)) = 0.6
    }
    SubShader {
        Tags { "RenderPipeline" = "UniversalPipeline" "RenderType" = "Opaque" "UniversalMaterialType" = "Lit" }
        Pass {
            Name "Universal Forward"
            Tags { "LightMode" = "UniversalForward" }
            HLSLPROGRAM
            #pragma target 4.5
            #pragma multi_compile_instancing
            #pragma multi_compile_fog
            #pragma vertex vert
            #pragma fragment frag

            #define ATTRIBUTES_NEED_NORMAL
            #define ATTRIBUTES_NEED_TANGENT
            #define ATTRIBUTES_NEED_TEXCOORD0
            #pragma multi_compile _ _ADDITIONAL_LIGHTS
            #define _NORMALMAP 1
            #define _NORMAL_DROPOFF_TS 1
            #define VARYINGS_NEED_POSITION_WS
            #define VARYINGS_NEED_NORMAL_WS
            #define VARYINGS_NEED_TANGENT_WS
            #define VARYINGS_NEED_TEXCOORD0
            #define VARYINGS_NEED_VIEWDIRECTION_WS
            #define VARYINGS_NEED_FOG_AND_VERTEX_LIGHT
            #define FEATURES_GRAPH_VERTEX
            #define SHADERPASS SHADERPASS_FORWARD

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
                float3 positionWS;
                float3 normalWS;
                float4 tangentWS;
                float4 texCoord0;
                float3 viewDirectionWS;
            #if !defined(LIGHTMAP_ON)
                float3 sh;
            #endif
                float4 fogFactorAndVertexLight;
            #if UNITY_ANY_INSTANCING_ENABLED
                uint instanceID : CUSTOM_INSTANCE_ID;
            #endif
            };
            struct SurfaceDescriptionInputs {
                float3 TangentSpaceNormal;
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
                float3 interp1 : INTERP1;
                float3 interp2 : INTERP2;
                float4 interp3 : INTERP3;
                float3 interp4 : INTERP4;
                float3 interp5 : INTERP5;
                float4 interp6 : INTERP6;
            #if UNITY_ANY_INSTANCING_ENABLED
                uint instanceID : CUSTOM_INSTANCE_ID;
            #endif
            };

            PackedVaryings PackVaryings(Varyings input) {
                PackedVaryings output;
                ZERO_INITIALIZE(PackedVaryings, output);
                output.positionCS = input.positionCS;
                output.interp0.xyzw = input.texCoord0;
                output.interp1.xyz = input.positionWS;
                output.interp2.xyz = input.normalWS;
                output.interp3.xyzw = input.tangentWS;
                output.interp4.xyz = input.viewDirectionWS;
            #if !defined(LIGHTMAP_ON)
                output.interp5.xyz = input.sh;
            #endif
                output.interp6.xyzw = input.fogFactorAndVertexLight;
                return output;
            }
            Varyings UnpackVaryings(PackedVaryings input) {
                Varyings output;
                output.positionCS = input.positionCS;
                output.texCoord0 = input.interp0.xyzw;
                output.positionWS = input.interp1.xyz;
                output.normalWS = input.interp2.xyz;
                output.tangentWS = input.interp3.xyzw;
                output.viewDirectionWS = input.interp4.xyz;
            #if !defined(LIGHTMAP_ON)
                output.sh = input.interp5.xyz;
            #endif
                output.fogFactorAndVertexLight = input.interp6.xyzw;
                return output;
            }

            CBUFFER_START(UnityPerMaterial)
            float4 _BaseMap_TexelSize;
            float4 _BaseMap_ST;
            float4 _BaseColor;
            float _Metallic;
            float _Smoothness;
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
                float3 NormalTS;
                float3 Emission;
                float Metallic;
                float Smoothness;
                float Occlusion;
            };
            SurfaceDescription SurfaceDescriptionFunction(SurfaceDescriptionInputs IN) {
                SurfaceDescription surface = (SurfaceDescription)0;
                UnityTexture2D _Property_0_Out_0 = UnityBuildTexture2DStruct(_BaseMap);
                float4 _SampleTexture2D_1_RGBA_0 = SAMPLE_TEXTURE2D(_Property_0_Out_0.tex, _Property_0_Out_0.samplerstate,
                                                                    _Property_0_Out_0.GetTransformedUV(IN.uv0.xy));
                float4 _Multiply_2_Out_2;
                Unity_Multiply_float4_float4(_SampleTexture2D_1_RGBA_0, _BaseColor, _Multiply_2_Out_2);
                surface.BaseColor = (_Multiply_2_Out_2.xyz);
                surface.NormalTS = IN.TangentSpaceNormal;
                surface.Emission = float3(0, 0, 0);
                surface.Metallic = _Metallic;
                surface.Smoothness = _Smoothness;
                surface.Occlusion = 1;
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
                output.TangentSpaceNormal = float3(0.0f, 0.0f, 1.0f);
                output.uv0 = input.texCoord0;
                return output;
            }

            #include "Packages/com.unity.render-pipelines.universal/Editor/ShaderGraph/Includes/Varyings.hlsl"
            #include "Packages/com.unity.render-pipelines.universal/Editor/ShaderGraph/Includes/PBRForwardPass.hlsl"
            ENDHLSL
        }
    }
}
