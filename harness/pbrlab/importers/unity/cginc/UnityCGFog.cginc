// pbrlab stand-in for the fog-factor macros of Unity's UnityCG.cginc that a program calls itself
// (the harness's UnityCG, glsl/pbr/unity/unity_cg.glsl, has the fog macros that a program's
// v2f and fragment take: UNITY_FOG_COORDS, UNITY_TRANSFER_FOG, UNITY_APPLY_FOG); UnityCG.cginc's
// stand-in includes this file.
//
// Provides: UNITY_CALC_FOG_FACTOR_RAW(coord) and UNITY_CALC_FOG_FACTOR(coord), each declaring
//   float unityFogFactor at the call.
// Unity's file: the same names (UnityCG.cginc, Unity 2019.4 built-in shaders), read for their
//   behaviour and written here anew. Unity's macros compute the factor (1 = no fog, 0 = all fog
//   colour) from unity_FogParams for the FOG_LINEAR, FOG_EXP and FOG_EXP2 variants, and declare
//   it 0.0 in the variant with none of them. The harness draws no fog (no fog variant is
//   compiled, as for UNITY_APPLY_FOG), so the factor is Unity's no-fog one, 0.0: a program that
//   blends lerp(unity_FogColor, colour, unityFogFactor) itself shows unity_FogColor, as it does
//   in Unity with fog switched off.
// Differences: none in that variant; the fog variants are not drawn.
// Cg text in the plain subset harness/pbrlab/importers/unity/port.py ports to GLSL.
#ifndef PBRLAB_UNITY_CG_FOG_CGINC
#define PBRLAB_UNITY_CG_FOG_CGINC

#define UNITY_CALC_FOG_FACTOR_RAW(coord) float unityFogFactor = 0.0
#define UNITY_CALC_FOG_FACTOR(coord) UNITY_CALC_FOG_FACTOR_RAW(coord)

#endif
