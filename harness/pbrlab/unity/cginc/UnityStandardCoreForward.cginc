// pbrlab stand-in for Unity's UnityStandardCoreForward.cginc: the entry points the Standard
// shaders' forward passes name in #pragma vertex / fragment.
//
// Provides: vertBase, fragBase (LightMode ForwardBase: the main light, the ambient, the
//   environment and the emission; UnityStandardCore.cginc does the work).
// Unity's file: the same names (UnityStandardCoreForward.cginc, Unity 2019.4 built-in
//   shaders), read for their behaviour and written here anew.
// Differences: vertAdd / fragAdd (ForwardAdd) are not provided: the harness does not draw
//   ForwardAdd passes of vertex/fragment programs (README, "Unity shaders").
#ifndef PBRLAB_UNITY_STANDARD_CORE_FORWARD_CGINC
#define PBRLAB_UNITY_STANDARD_CORE_FORWARD_CGINC

#include "UnityStandardCore.cginc"

VertexOutputForwardBase vertBase(VertexInput v)
{
    return vertForwardBase(v);
}

half4 fragBase(VertexOutputForwardBase i) : SV_Target
{
    return fragForwardBaseInternal(i);
}

#endif
