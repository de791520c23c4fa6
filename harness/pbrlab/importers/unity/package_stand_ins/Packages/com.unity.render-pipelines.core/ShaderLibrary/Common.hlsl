// pbrlab stand-in for Core RP's ShaderLibrary/Common.hlsl: the precision types (real), the constants (PI, HALF_MIN, FLT_EPS), SafeNormalize and the API macros, which pbrlab's
// stand-in Core.hlsl defines (written for pbrlab from Unity's documentation of the names;
// Unity's own file is under the Unity Companion License and is not copied).
#ifndef PBRLAB_CORE_RP_COMMON_HLSL
#define PBRLAB_CORE_RP_COMMON_HLSL

#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"

#endif
