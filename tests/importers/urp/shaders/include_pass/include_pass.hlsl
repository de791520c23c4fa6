// pbrlab test include (written for pbrlab, CC0): urp_include_pass.shader's functions.
struct Attributes {
    float4 positionOS : POSITION;
};

struct Varyings {
    float4 positionCS : SV_POSITION;
};

Varyings vert(Attributes IN) {
    Varyings OUT = (Varyings)0;
    OUT.positionCS = TransformObjectToHClip(IN.positionOS.xyz);
    return OUT;
}

float4 frag(Varyings IN, FRONT_FACE_TYPE frontFace : FRONT_FACE_SEMANTIC) : SV_Target {
    uint lights = GetAdditionalLightsCount();          // int read into a uint (HLSL converts)
    LightingData lightingData = (LightingData)0;
    lightingData.giColor = float3(0.1, 0.1, 0.1);
    lightingData.mainLightColor = float3(0.2, 0.2, 0.2);
    lightingData.additionalLightsColor = float3(0.05, 0.05, 0.05) + float(lights) * 0.0;
    lightingData.vertexLightingColor = float3(0.05, 0.05, 0.05);
    lightingData.emissionColor = float3(0.1, 0.1, 0.1);
    float lit = CalculateFinalColor(lightingData, 1.0).r;                      // 0.5
    float3x3 frame = CreateTangentToWorld(float3(0, 0, 1), float3(1, 0, 0), -1.0);
    float bitangentY = TransformTangentToWorld(float3(0, 1, 0), frame).y;     // -1
    return float4(lit, 0.5 + 0.25 * bitangentY, IS_FRONT_VFACE(frontFace, 0.75, 0.125), 1.0);
}
