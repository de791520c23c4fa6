// pbrlab stand-in for Unity's UnityImageBasedLighting.cginc (which Unity's UnityPBSLighting,
// UnityGlobalIllumination and UnityStandardBRDF include). The one-argument
// Unity_GlossyEnvironment(glossIn) and Unity_GlossyEnvironmentData are already included by the
// generated program (pbr/unity/global_illumination.glsl); declared here: the three-argument form
// a program calls on the reflection probe itself,
//     Unity_GlossyEnvironment(UNITY_PASS_TEXCUBE(unity_SpecCube0), unity_SpecCube0_HDR, glossIn)
// Unity's behaviour (UnityImageBasedLighting.cginc, Unity 2019.4 built-in shaders, read for it and
// written here anew): the perceptual roughness r is remapped to r (1.7 - 0.7 r), read at mip
// r' * UNITY_SPECCUBE_LOD_STEPS (6) of the cube along glossIn.reflUVW, and decoded with
// DecodeHDR(rgbm, hdr), the identity for the harness's float environment (unity_SpecCube0_HDR).
// GLSL: the port spells the call on unity_SpecCube0 as pbrlab_unity_glossy_probe(hdr, glossIn)
// (importers/unity/texture_methods.py); HLSL: unity_SpecCube0 is unity_hlsl_support's probe
// object, and UNITY_PASS_TEXCUBE(tex) passes it as it is.
// Cg text in the plain subset harness/pbrlab/importers/unity/port.py ports to GLSL.
#ifndef PBRLAB_UNITY_IMAGE_BASED_LIGHTING_CGINC
#define PBRLAB_UNITY_IMAGE_BASED_LIGHTING_CGINC

// Unity's UNITY_SPECCUBE_LOD_STEPS: the mip of perceptual roughness 1
#ifndef UNITY_SPECCUBE_LOD_STEPS
#define UNITY_SPECCUBE_LOD_STEPS 6
#endif

half3 pbrlab_unity_glossy_probe(half4 hdr, Unity_GlossyEnvironmentData glossIn)
{
    half r = glossIn.roughness * (1.7 - 0.7 * glossIn.roughness);
    return UNITY_SAMPLE_TEXCUBE_LOD(unity_SpecCube0, glossIn.reflUVW, r * UNITY_SPECCUBE_LOD_STEPS).rgb;
}

#ifdef PBRLAB_UNITY_SPECCUBE0
#ifndef UNITY_PASS_TEXCUBE
#define UNITY_PASS_TEXCUBE(tex) tex
#endif
// HLSLSupport.cginc's pass of a cube with another's sampler (unity_SpecCube1 with unity_SpecCube0's):
// the probe object carries its own.
#define UNITY_PASS_TEXCUBE_SAMPLER(tex, samplertex) tex
half3 Unity_GlossyEnvironment(PbrlabUnityReflectionProbe probe, half4 hdr, Unity_GlossyEnvironmentData glossIn)
{
    return pbrlab_unity_glossy_probe(hdr, glossIn);
}
#endif

#endif
