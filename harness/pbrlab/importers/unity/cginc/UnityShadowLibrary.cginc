// pbrlab stand-in for Unity's UnityShadowLibrary.cginc.
//
// Provides: nothing. Every function of Unity's file reads a shadow map or the baked shadow
//   mask (UnitySampleShadowmap, UnitySampleShadowmap_PCF*, UnityComputeShadowFade(Distance),
//   UnityGetRawBakedOcclusions, UnitySampleBakedOcclusion, UnityMixRealtimeAndBakedShadows), and
//   the harness has neither: a shader that calls one is refused naming it (unprovided.py,
//   "shadow maps and shadow-caster passes"); one that only includes the file (GIDebug's
//   ShowLightMask) is read on, and refused or drawn by what it does use.
// Unity's file: the shadow-map sampling and shadow-fade helpers of the built-in pipeline.
#ifndef PBRLAB_UNITY_SHADOW_LIBRARY_CGINC
#define PBRLAB_UNITY_SHADOW_LIBRARY_CGINC
#endif
