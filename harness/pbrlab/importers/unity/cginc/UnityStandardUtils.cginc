// pbrlab stand-in for Unity's UnityStandardUtils.cginc.
//
// Provides: ParallaxOffset1Step(h, height, viewDir), the one-step parallax shift the
//   Standard shader's Parallax() takes (the same formula as UnityCG's ParallaxOffset,
//   pbr/unity/unity_cg.glsl, which documents it). The file's other names
//   (DiffuseAndSpecularFromMetallic, EnergyConservationBetweenDiffuseAndSpecular,
//   PreMultiplyAlpha, UnpackScaleNormal, BlendNormals, ...) are already included by the
//   generated program (harness/pbrlab/importers/unity/generate.py; README, "Unity shaders", lists them).
//   BoxProjectedCubemapDirection(worldRefl, worldPos, cubemapCenter, boxMin, boxMax): the
//   reflection direction re-aimed for a box-projected probe (cubemapCenter.w > 0): from the
//   surface point along the unit direction to where it leaves the box (per axis, the distance
//   to the box face it heads for; the nearest of the three), taken as seen from the probe's
//   centre; with w <= 0 (pbrlab's probe: the sky, unity_SpecCube0_ProbePosition.w = 0) the
//   direction as given.
// Unity's file: the same names (UnityStandardUtils.cginc, Unity 2019.4 built-in shaders),
//   read for their behaviour and written here anew.
// Cg text in the plain subset harness/pbrlab/importers/unity/port.py ports to GLSL.
#ifndef PBRLAB_UNITY_STANDARD_UTILS_CGINC
#define PBRLAB_UNITY_STANDARD_UTILS_CGINC

float2 ParallaxOffset1Step(half h, half height, half3 viewDir)
{
    return ParallaxOffset(h, height, viewDir);
}

float3 BoxProjectedCubemapDirection(float3 worldRefl, float3 worldPos, float4 cubemapCenter, float4 boxMin,
                                    float4 boxMax)
{
    if (cubemapCenter.w > 0.0)
    {
        float3 direction = normalize(worldRefl);
        float3 toMax = (boxMax.xyz - worldPos) / direction;
        float3 toMin = (boxMin.xyz - worldPos) / direction;
        float3 exit = float3(direction.x > 0.0 ? toMax.x : toMin.x, direction.y > 0.0 ? toMax.y : toMin.y,
                             direction.z > 0.0 ? toMax.z : toMin.z);
        float along = min(min(exit.x, exit.y), exit.z);
        return worldPos - cubemapCenter.xyz + direction * along;
    }
    return worldRefl;
}

#endif
