// pbrlab stand-in for URP's Shaders/LitForwardPass.hlsl: the Lit shader's forward pass
// (LitPassVertex, LitPassFragment) over LitInput.hlsl's surface: world position, normal (through
// the tangent frame with _NORMALMAP), view direction and per-pixel SH to URP's InputData, then
// UniversalFragmentPBR, fog (none here) and OutputAlpha(alpha, _Surface). Written for pbrlab from
// Unity's documentation of the Lit shader (URP's own file is under the Unity Companion License
// and is not copied). No lightmaps, shadow maps or vertex lights here (Lighting.hlsl).
#ifndef PBRLAB_URP_LIT_FORWARD_PASS_HLSL
#define PBRLAB_URP_LIT_FORWARD_PASS_HLSL

#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Lighting.hlsl"

struct Attributes {
    float4 positionOS : POSITION;
    float3 normalOS : NORMAL;
    float4 tangentOS : TANGENT;
    float2 texcoord : TEXCOORD0;
};

struct Varyings {
    float2 uv : TEXCOORD0;
    float3 positionWS : TEXCOORD1;
    float3 normalWS : TEXCOORD2;
    float4 tangentWS : TEXCOORD3;    // xyz the tangent, w its sign times the transform's
    float4 positionCS : SV_POSITION;
};

void InitializeInputData(Varyings input, float3 normalTS, out InputData inputData) {
    inputData = (InputData)0;
    inputData.positionWS = input.positionWS;
    inputData.positionCS = input.positionCS;
#ifdef _NORMALMAP
    float3 bitangent = input.tangentWS.w * cross(input.normalWS, input.tangentWS.xyz);
    inputData.tangentToWorld = float3x3(input.tangentWS.xyz, bitangent, input.normalWS);
    inputData.normalWS = TransformTangentToWorld(normalTS, inputData.tangentToWorld);
#else
    inputData.normalWS = input.normalWS;
#endif
    inputData.normalWS = NormalizeNormalPerPixel(inputData.normalWS);
    inputData.viewDirectionWS = GetWorldSpaceNormalizeViewDir(input.positionWS);
    inputData.shadowCoord = TransformWorldToShadowCoord(input.positionWS);
    inputData.fogCoord = 0.0;
    inputData.vertexLighting = float3(0.0, 0.0, 0.0);
    inputData.bakedGI = SampleSH(inputData.normalWS);
    inputData.normalizedScreenSpaceUV = GetNormalizedScreenSpaceUV(input.positionCS);
    inputData.shadowMask = float4(1.0, 1.0, 1.0, 1.0);
}

Varyings LitPassVertex(Attributes input) {
    Varyings output = (Varyings)0;
    VertexPositionInputs vertexInput = GetVertexPositionInputs(input.positionOS.xyz);
    VertexNormalInputs normalInput = GetVertexNormalInputs(input.normalOS, input.tangentOS);
    output.uv = input.texcoord * _BaseMap_ST.xy + _BaseMap_ST.zw;
    output.positionWS = vertexInput.positionWS;
    output.normalWS = normalInput.normalWS;
    output.tangentWS = float4(normalInput.tangentWS, input.tangentOS.w * GetOddNegativeScale());
    output.positionCS = vertexInput.positionCS;
    return output;
}

float4 LitPassFragment(Varyings input) : SV_Target {
    SurfaceData surfaceData;
    InitializeStandardLitSurfaceData(input.uv, surfaceData);
    InputData inputData;
    InitializeInputData(input, surfaceData.normalTS, inputData);
    float4 color = UniversalFragmentPBR(inputData, surfaceData);
    color.rgb = MixFog(color.rgb, inputData.fogCoord);
    color.a = OutputAlpha(color.a, _Surface);
    return color;
}

#endif
