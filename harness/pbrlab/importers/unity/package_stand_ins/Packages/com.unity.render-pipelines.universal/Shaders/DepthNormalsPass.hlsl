// pbrlab stand-in for URP's Shaders/DepthNormalsPass.hlsl: the depth-normals prepass's vertex and
// fragment functions (URP 12-14's names: Attributes, Varyings, DepthNormalsVertex,
// DepthNormalsFragment), written for pbrlab from Unity's documentation of the pass (it writes each
// pixel's world-space normal, w 0, into _CameraNormalsTexture, where no normal packing is asked
// for); URP's own file is under the Unity Companion License and is not copied. pbrlab runs no
// depth-normals prepass (a DepthNormals pass is skipped), so a pass draws with these only where a
// shader calls them itself; a shader's forward pass that includes the file, as Unity's Lit
// templates' copies do, compiles as in Unity. No alpha test, no normal map (Unity's default
// variant: _ALPHATEST_ON and _NORMALMAP off).
#ifndef PBRLAB_URP_DEPTH_NORMALS_PASS_HLSL
#define PBRLAB_URP_DEPTH_NORMALS_PASS_HLSL

#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"

struct Attributes {
    float4 positionOS : POSITION;
    float4 tangentOS : TANGENT;
    float2 texcoord : TEXCOORD0;
    float3 normal : NORMAL;
};

struct Varyings {
    float4 positionCS : SV_POSITION;
    float2 uv : TEXCOORD1;
    float3 normalWS : TEXCOORD2;
};

Varyings DepthNormalsVertex(Attributes input) {
    Varyings output;
    output.uv = input.texcoord;
    output.positionCS = TransformObjectToHClip(input.positionOS.xyz);
    output.normalWS = TransformObjectToWorldNormal(input.normal);
    return output;
}

// the pixel's world-space normal, renormalized, w 0
void DepthNormalsFragment(Varyings input, out float4 outNormalWS : SV_Target0) {
    outNormalWS = float4(NormalizeNormalPerPixel(input.normalWS), 0.0);
}

#endif
