// pbrlab stand-in for URP's Editor/ShaderGraph/Includes/PBRForwardPass.hlsl: the vertex and
// fragment functions (vert, frag) of a Shader Graph Lit pass, shaded by URP's
// UniversalFragmentPBR (pbrlab's stand-in Lighting.hlsl), written for pbrlab from the Lit
// master stack's documented outputs (Base Color, Normal in tangent, object or world space by
// its Fragment Normal Space, Metallic or Specular, Smoothness, Occlusion, Emission, Alpha;
// URP's own file is under the Unity Companion License and is not copied). Shader Graph
// before URP 10 named them Albedo and Normal (tangent space) and defined SHADERPASS_FORWARD
// without SHADERPASS: read as such.
#ifndef PBRLAB_URP_SG_PBR_FORWARD_PASS_HLSL
#define PBRLAB_URP_SG_PBR_FORWARD_PASS_HLSL

#ifdef SHADERPASS
#define PBRLAB_SG_ALBEDO(s) (s).BaseColor
#define PBRLAB_SG_NORMAL_TS(s) (s).NormalTS
#else
#define PBRLAB_SG_ALBEDO(s) (s).Albedo
#define PBRLAB_SG_NORMAL_TS(s) (s).Normal
#define _NORMAL_DROPOFF_TS 1
#endif

void InitializeInputData(Varyings input, SurfaceDescription surfaceDescription, out InputData inputData)
{
    inputData = (InputData)0;
    inputData.positionWS = input.positionWS;
    inputData.positionCS = input.positionCS;
#if defined(_NORMALMAP) && defined(_NORMAL_DROPOFF_TS)
    float crossSign = (input.tangentWS.w > 0.0 ? 1.0 : -1.0) * GetOddNegativeScale();
    float3 bitangent = crossSign * cross(input.normalWS.xyz, input.tangentWS.xyz);
    inputData.normalWS = TransformTangentToWorld(PBRLAB_SG_NORMAL_TS(surfaceDescription),
                                                 float3x3(input.tangentWS.xyz, bitangent, input.normalWS.xyz));
#elif defined(_NORMAL_DROPOFF_OS)
    inputData.normalWS = TransformObjectToWorldNormal(surfaceDescription.NormalOS);
#elif defined(_NORMAL_DROPOFF_WS)
    inputData.normalWS = surfaceDescription.NormalWS;
#else
    inputData.normalWS = input.normalWS;
#endif
    inputData.normalWS = NormalizeNormalPerPixel(inputData.normalWS);
#if defined(VARYINGS_NEED_VIEWDIRECTION_WS)
    inputData.viewDirectionWS = SafeNormalize(input.viewDirectionWS);
#else
    // URP 12's generated passes carry no view direction: the fragment takes it from positionWS.
    inputData.viewDirectionWS = GetWorldSpaceNormalizeViewDir(input.positionWS);
#endif
    inputData.shadowCoord = float4(0.0, 0.0, 0.0, 0.0);
    inputData.fogCoord = 0.0;
    inputData.vertexLighting = input.fogFactorAndVertexLight.yzw;
    inputData.bakedGI = SampleSH(inputData.normalWS);
    inputData.normalizedScreenSpaceUV = GetNormalizedScreenSpaceUV(input.positionCS);
    inputData.shadowMask = float4(1.0, 1.0, 1.0, 1.0);
}

#include "Packages/com.unity.render-pipelines.universal/Editor/ShaderGraph/Includes/PbrlabGraphPass.hlsl"

float4 frag(PackedVaryings packedInput) : SV_Target
{
    Varyings unpacked;
    float alpha;
    SurfaceDescription surfaceDescription = pbrlab_graph_surface(packedInput, unpacked, alpha);
    InputData inputData;
    InitializeInputData(unpacked, surfaceDescription, inputData);
    SurfaceData surface = (SurfaceData)0;
    surface.albedo = PBRLAB_SG_ALBEDO(surfaceDescription);
#ifdef _SPECULAR_SETUP
    surface.specular = surfaceDescription.Specular;
    surface.metallic = 1.0;
#else
    surface.specular = float3(0.0, 0.0, 0.0);
    surface.metallic = saturate(surfaceDescription.Metallic);
#endif
    surface.smoothness = saturate(surfaceDescription.Smoothness);
    surface.occlusion = surfaceDescription.Occlusion;
    surface.emission = surfaceDescription.Emission;
    surface.alpha = saturate(alpha);
    surface.normalTS = float3(0.0, 0.0, 1.0);
    return UniversalFragmentPBR(inputData, surface);
}

#endif
