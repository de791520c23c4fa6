// pbrlab stand-in for URP's ShaderLibrary/GlobalIllumination.hlsl: SampleSH, GlossyEnvironmentReflection and GlobalIllumination, which pbrlab's
// stand-in Lighting.hlsl defines (written for pbrlab from Unity's documentation of the names;
// Unity's own file is under the Unity Companion License and is not copied).
#ifndef PBRLAB_URP_GLOBALILLUMINATION_HLSL
#define PBRLAB_URP_GLOBALILLUMINATION_HLSL

#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Lighting.hlsl"

#endif
