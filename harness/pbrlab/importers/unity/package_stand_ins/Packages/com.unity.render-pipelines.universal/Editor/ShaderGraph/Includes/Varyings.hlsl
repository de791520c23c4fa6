// pbrlab stand-in for URP's Editor/ShaderGraph/Includes/Varyings.hlsl: BuildVaryings, which
// fills a Shader Graph pass's Varyings from its Attributes (the generated code declares both
// structs, with the members its ATTRIBUTES_NEED_* / VARYINGS_NEED_* defines ask for), after the
// graph's vertex stage (FEATURES_GRAPH_VERTEX: VertexDescriptionFunction's Position, Normal
// and Tangent, in object space). Written for pbrlab from Shader Graph's documented node
// outputs (Position, Normal, Tangent, View Direction, Screen Position; URP's own file is under
// the Unity Companion License and is not copied). The view direction is the unnormalised
// vector to the camera (GetWorldSpaceViewDir), as URP's Shader Graph passes carry it; the
// ambient light (sh) and the vertex lights are evaluated here per vertex as URP does, its
// fog factor 0 (no fog here).
#ifndef PBRLAB_URP_SG_VARYINGS_HLSL
#define PBRLAB_URP_SG_VARYINGS_HLSL

#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Lighting.hlsl"

Varyings BuildVaryings(Attributes input)
{
    Varyings output = (Varyings)0;
#if defined(FEATURES_GRAPH_VERTEX)
    VertexDescriptionInputs vertexDescriptionInputs = BuildVertexDescriptionInputs(input);
    VertexDescription vertexDescription = VertexDescriptionFunction(vertexDescriptionInputs);
    input.positionOS = vertexDescription.Position;
#if defined(ATTRIBUTES_NEED_NORMAL)
    input.normalOS = vertexDescription.Normal;
#endif
#if defined(ATTRIBUTES_NEED_TANGENT)
    input.tangentOS.xyz = vertexDescription.Tangent.xyz;
#endif
#endif
    float3 positionWS = TransformObjectToWorld(input.positionOS);
#if defined(ATTRIBUTES_NEED_NORMAL)
    float3 normalWS = TransformObjectToWorldNormal(input.normalOS);
#else
    float3 normalWS = float3(0.0, 0.0, 1.0);
#endif
#if defined(ATTRIBUTES_NEED_TANGENT)
    float4 tangentWS = float4(TransformObjectToWorldDir(input.tangentOS.xyz), input.tangentOS.w);
#endif
    output.positionCS = TransformWorldToHClip(positionWS);
#if defined(VARYINGS_NEED_POSITION_WS)
    output.positionWS = positionWS;
#endif
#if defined(VARYINGS_NEED_NORMAL_WS)
    output.normalWS = normalWS;
#endif
#if defined(VARYINGS_NEED_TANGENT_WS)
    output.tangentWS = tangentWS;
#endif
#if defined(VARYINGS_NEED_BITANGENT_WS)
    output.bitangentWS = cross(normalWS, tangentWS.xyz) * tangentWS.w;
#endif
#if defined(VARYINGS_NEED_TEXCOORD0)
    output.texCoord0 = input.uv0;
#endif
#if defined(VARYINGS_NEED_TEXCOORD1)
    output.texCoord1 = input.uv1;
#endif
#if defined(VARYINGS_NEED_TEXCOORD2)
    output.texCoord2 = input.uv2;
#endif
#if defined(VARYINGS_NEED_TEXCOORD3)
    output.texCoord3 = input.uv3;
#endif
#if defined(VARYINGS_NEED_COLOR)
    output.color = input.color;
#endif
#if defined(VARYINGS_NEED_VIEWDIRECTION_WS)
    output.viewDirectionWS = GetWorldSpaceViewDir(positionWS);
#endif
#if defined(VARYINGS_NEED_SCREENPOSITION)
    output.screenPosition = ComputeScreenPos(output.positionCS);
#endif
#if defined(VARYINGS_NEED_FOG_AND_VERTEX_LIGHT)
    output.fogFactorAndVertexLight = float4(ComputeFogFactor(output.positionCS.z), VertexLighting(positionWS, normalWS));
#endif
#if defined(VARYINGS_NEED_SH) || ((SHADERPASS == SHADERPASS_FORWARD) && !defined(LIGHTMAP_ON) && defined(VARYINGS_NEED_FOG_AND_VERTEX_LIGHT))
    output.sh = SampleSHVertex(normalWS);
#endif
#if defined(VARYINGS_NEED_SHADOW_COORD) && defined(REQUIRES_VERTEX_SHADOW_COORD_INTERPOLATOR)
    output.shadowCoord = TransformWorldToShadowCoord(positionWS);
#endif
    return output;
}

#endif
