// pbrlab stand-in for Unity's UnityPBSLighting.cginc: the names a surface shader reads from it are
// already included by the generated program (harness/pbrlab/importers/unity/generate.py; README,
// "Unity shaders", lists them). It adds UNITY_BRDF_PBS, which a vertex/fragment program calls
// (the deferred light passes): Unity's macro for the graphics tier's BRDF (UNITY_PBS_USE_BRDF1/2/3),
// here pbrlab's quality tier's (pbr_unity_brdf_pbs: HIGH BRDF1, MEDIUM BRDF2, LOW BRDF3).
#ifndef PBRLAB_UNITY_PBS_LIGHTING_CGINC
#define PBRLAB_UNITY_PBS_LIGHTING_CGINC

half4 pbrlab_unity_brdf_pbs(half3 diffColor, half3 specColor, half oneMinusReflectivity, half smoothness,
                            float3 normal, float3 viewDir, UnityLight light, UnityIndirect gi)
{
    return half4(pbr_unity_brdf_pbs(diffColor, specColor, oneMinusReflectivity, smoothness, normal, viewDir,
                                    light.color, light.dir, gi.diffuse, gi.specular), 1.0);
}
#define UNITY_BRDF_PBS pbrlab_unity_brdf_pbs

#endif
