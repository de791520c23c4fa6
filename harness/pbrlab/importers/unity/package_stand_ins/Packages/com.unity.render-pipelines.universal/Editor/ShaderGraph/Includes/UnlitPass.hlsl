// pbrlab stand-in for URP's Editor/ShaderGraph/Includes/UnlitPass.hlsl: the vertex and fragment
// functions (vert, frag) of a Shader Graph Unlit pass, written for pbrlab from the Unlit
// master stack's documented outputs (Base Color, Alpha, Alpha Clip Threshold; URP's own file
// is under the Unity Companion License and is not copied). Shader Graph before URP 10 named
// the colour output Color and defined SHADERPASS_UNLIT without SHADERPASS: read as such.
#ifndef PBRLAB_URP_SG_UNLIT_PASS_HLSL
#define PBRLAB_URP_SG_UNLIT_PASS_HLSL

#include "Packages/com.unity.render-pipelines.universal/Editor/ShaderGraph/Includes/PbrlabGraphPass.hlsl"

float4 frag(PackedVaryings packedInput) : SV_Target
{
    Varyings unpacked;
    float alpha;
    SurfaceDescription surfaceDescription = pbrlab_graph_surface(packedInput, unpacked, alpha);
#ifdef SHADERPASS
    float3 color = surfaceDescription.BaseColor;
#else
    float3 color = surfaceDescription.Color;
#endif
#ifdef _ALPHAPREMULTIPLY_ON
    color *= alpha;
#endif
    return float4(color, alpha);
}

#endif
