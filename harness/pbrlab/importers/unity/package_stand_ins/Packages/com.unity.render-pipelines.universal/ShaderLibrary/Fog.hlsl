// pbrlab stand-in for URP's ShaderLibrary/Fog.hlsl (Unity 2023 and later), a keywords file a pass
// includes with #include_with_pragmas: in URP it declares the fog keywords FOG_LINEAR, FOG_EXP
// and FOG_EXP2 (as a dynamic branch when USE_DYNAMIC_BRANCH_FOG_KEYWORD is 1, else with
// multi_compile_fog); written for pbrlab from Unity's documentation of the names (URP's own file
// is under the Unity Companion License and is not copied). pbrlab's scenes have no fog: every
// fog keyword is off, so ComputeFogFactor and MixFog (Core.hlsl) leave the colour as it is.
#ifndef PBRLAB_URP_FOG_HLSL
#define PBRLAB_URP_FOG_HLSL
#endif
