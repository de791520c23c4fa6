// pbrlab stand-in for URP's ShaderLibrary/Input.hlsl: the InputData struct and the camera's and
// lights' globals (the main light's are Core.hlsl's here), including the additional lights' arrays.
// As URP's Core.hlsl, pbrlab's brings this file,
// written for pbrlab from Unity's documentation of the names and URP 12's and 14's files read for
// their names (Unity's own files are under the Unity Companion License and are not copied).
#ifndef PBRLAB_URP_INPUT_HLSL
#define PBRLAB_URP_INPUT_HLSL
#define UNIVERSAL_INPUT_INCLUDED

#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"

// URP's indirect specular where a shader's glossy reflections are off (Input.hlsl's
// _GlossyEnvironmentColor): URP sets it to the ambient probe's constant (L0) term times the
// reflection intensity (1 here), which is the probe's mean over all directions: the Unity
// prelude's Unity_LightmodelAmbient() (black without an environment).
#define _GlossyEnvironmentColor Unity_LightmodelAmbient()
// The probes' baked occlusion of the shadow mask: none here (every channel 1).
#define unity_ProbesOcclusion float4(1.0, 1.0, 1.0, 1.0)

struct InputData {
    float3 positionWS;
    float4 positionCS;
    float3 normalWS;
    float3 viewDirectionWS;
    float4 shadowCoord;
    float fogCoord;
    float3 vertexLighting;
    float3 bakedGI;
    float2 normalizedScreenSpaceUV;
    float4 shadowMask;
    float3x3 tangentToWorld;
};

// URP's additional lights as its Input.hlsl declares them for the uniform-array path (cbuffer
// AdditionalLights, without structured buffers): per light its position (a directional light's
// direction towards it, w 0; else its position, w 1), colour, attenuation (x 1 / range^2, y
// range^2 / (range^2 - (0.8 range)^2); z, w a spot cone's 1 / (cos inner - cos outer) and
// -cos outer of that: else 0 and 1) and spot direction (towards the light, the spot's forward
// negated), URP 12 UniversalRenderPipelineCore.cs / ForwardLights.cs InitializeLightConstants.
// MAX_VISIBLE_LIGHTS is URP 12's for OpenGL Core (32; 256 on desktop Direct3D, 16 on GLES).
// Here the lights are the scene's, in this order: its directional lights after the first (the
// main light), its point lights, its spot lights; each array is a global the entry points fill
// from the scene before the program runs (engine_inputs.FILLED), and the functions below give
// the same values to the stand-ins' own code.
// (Core.hlsl defines it, with the same guard, for a program that includes this file through it.)
#if !defined(MAX_VISIBLE_LIGHTS) && !defined(PBRLAB_USER_DEFINES_MAX_VISIBLE_LIGHTS)
#define MAX_VISIBLE_LIGHTS 32  // a program's own, defined before or after (user_definitions), stands
#endif
#if PBRLAB_DIRECTIONAL_COUNT > 1
#define PBRLAB_URP_EXTRA_DIRECTIONAL_COUNT (PBRLAB_DIRECTIONAL_COUNT - 1)
#else
#define PBRLAB_URP_EXTRA_DIRECTIONAL_COUNT 0
#endif
#define PBRLAB_URP_ADDITIONAL_LIGHT_COUNT (PBRLAB_URP_EXTRA_DIRECTIONAL_COUNT + PBRLAB_POINT_COUNT + PBRLAB_SPOT_COUNT)
// x: the number of additional lights (URP's half4 _AdditionalLightsCount).
#define _AdditionalLightsCount float4(float(PBRLAB_URP_ADDITIONAL_LIGHT_COUNT), 0.0, 0.0, 0.0)
// URP's range window start: the fade begins at 0.8 of the range (ForwardLights.cs).
#define PBRLAB_URP_FADE_START_FRACTION 0.8
static float4 _AdditionalLightsPosition[32];
static float4 _AdditionalLightsColor[32];
static float4 _AdditionalLightsAttenuation[32];
static float4 _AdditionalLightsSpotDir[32];

float4 pbrlab_urp_additional_light_position(int index) {
#if PBRLAB_DIRECTIONAL_COUNT > 1
    if (index < PBRLAB_URP_EXTRA_DIRECTIONAL_COUNT)
        return float4(-u_directional_direction[index + 1], 0.0);
#endif
    index -= PBRLAB_URP_EXTRA_DIRECTIONAL_COUNT;
#if PBRLAB_POINT_COUNT > 0
    if (index >= 0 && index < PBRLAB_POINT_COUNT)
        return float4(u_point_position[index], 1.0);
#endif
    index -= PBRLAB_POINT_COUNT;
#if PBRLAB_SPOT_COUNT > 0
    if (index >= 0 && index < PBRLAB_SPOT_COUNT)
        return float4(u_spot_position[index], 1.0);
#endif
    return float4(0.0, 0.0, 1.0, 0.0);
}

float4 pbrlab_urp_additional_light_color(int index) {
#if PBRLAB_DIRECTIONAL_COUNT > 1
    if (index < PBRLAB_URP_EXTRA_DIRECTIONAL_COUNT)
        return float4(u_directional_radiance[index + 1], 1.0);
#endif
    index -= PBRLAB_URP_EXTRA_DIRECTIONAL_COUNT;
#if PBRLAB_POINT_COUNT > 0
    if (index >= 0 && index < PBRLAB_POINT_COUNT)
        return float4(u_point_radiance[index], 1.0);
#endif
    index -= PBRLAB_POINT_COUNT;
#if PBRLAB_SPOT_COUNT > 0
    if (index >= 0 && index < PBRLAB_SPOT_COUNT)
        return float4(u_spot_radiance[index], 1.0);
#endif
    return float4(0.0, 0.0, 0.0, 0.0);
}

// (1 / range^2, range^2 / (range^2 - fade start^2)) of a positional light's range.
float2 pbrlab_urp_range_attenuation(float range) {
    float fadeStart = PBRLAB_URP_FADE_START_FRACTION * PBRLAB_URP_FADE_START_FRACTION;
    return float2(1.0 / (range * range), 1.0 / (1.0 - fadeStart));
}

float4 pbrlab_urp_additional_light_attenuation(int index) {
    index -= PBRLAB_URP_EXTRA_DIRECTIONAL_COUNT;
#if PBRLAB_POINT_COUNT > 0
    if (index >= 0 && index < PBRLAB_POINT_COUNT)
        return float4(pbrlab_urp_range_attenuation(u_point_range[index]), 0.0, 1.0);
#endif
    index -= PBRLAB_POINT_COUNT;
#if PBRLAB_SPOT_COUNT > 0
    if (index >= 0 && index < PBRLAB_SPOT_COUNT)  // u_spot_cone: (cos outer, 1 / (cos inner - cos outer))
        return float4(pbrlab_urp_range_attenuation(u_spot_range[index]), u_spot_cone[index].y,
                      -u_spot_cone[index].x * u_spot_cone[index].y);
#endif
    return float4(0.0, 1.0, 0.0, 1.0);  // a directional light (or none): no window, no cone
}

float4 pbrlab_urp_additional_light_spot_direction(int index) {
    index -= PBRLAB_URP_EXTRA_DIRECTIONAL_COUNT + PBRLAB_POINT_COUNT;
#if PBRLAB_SPOT_COUNT > 0
    if (index >= 0 && index < PBRLAB_SPOT_COUNT)
        return float4(-u_spot_direction[index], 0.0);
#endif
    return float4(0.0, 0.0, 1.0, 0.0);
}

#endif
