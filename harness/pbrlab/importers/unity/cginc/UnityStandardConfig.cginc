// pbrlab stand-in for Unity's UnityStandardConfig.cginc (Standard, StandardSpecular,
// AutodeskInteractive and shaders built on UnityStandardCore.cginc).
//
// Provides: UNITY_STANDARD_SIMPLE (0: the full forward path; pbrlab has one path for both of
//   Unity's, see UnityStandardCore.cginc), UNITY_ENABLE_DETAIL_NORMALMAP (1: the detail normal
//   map is read, as Unity's default on shader model 3), UNITY_SETUP_BRDF_INPUT (MetallicSetup
//   unless the shader defines it first, as Standard*.shader do in their CGINCLUDE),
//   UNITY_SPECCUBE_LOD_STEPS (6: the mip of a reflection probe's roughest level, the mip a
//   shader reads being its remapped perceptual roughness times this; the value Unity's file
//   gives and pbrlab's own probe sampling takes, maths/reference/unity_brdf.py).
// Unity's file: the same names (UnityStandardConfig.cginc, Unity 2019.4 built-in shaders),
//   read for their behaviour and written here anew.
#ifndef PBRLAB_UNITY_STANDARD_CONFIG_CGINC
#define PBRLAB_UNITY_STANDARD_CONFIG_CGINC

#ifndef UNITY_STANDARD_SIMPLE
#define UNITY_STANDARD_SIMPLE 0
#endif
#ifndef UNITY_ENABLE_DETAIL_NORMALMAP
#define UNITY_ENABLE_DETAIL_NORMALMAP 1
#endif
#ifndef UNITY_SPECCUBE_LOD_STEPS
#define UNITY_SPECCUBE_LOD_STEPS 6
#endif
#ifndef UNITY_SETUP_BRDF_INPUT
#define UNITY_SETUP_BRDF_INPUT MetallicSetup
#endif

#endif
