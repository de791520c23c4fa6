// pbrlab stand-in for Unity's UnityStandardCoreForward.cginc: the entry points the Standard
// shaders' forward passes name in #pragma vertex / fragment.
//
// Provides: vertBase, fragBase (LightMode ForwardBase: the main light, the ambient, the
//   environment and the emission), vertAdd, fragAdd (ForwardAdd: one more light, added);
//   UnityStandardCore.cginc does the work.
// Unity's file: the same names (UnityStandardCoreForward.cginc, Unity 2019.4 built-in
//   shaders), read for their behaviour and written here anew.
// Differences: vertAdd hands fragAdd the base pass's vertex output (Unity's has its own,
//   VertexOutputForwardAdd, with a per-vertex light direction; here it is per pixel).
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

VertexOutputForwardBase vertAdd(VertexInput v)
{
    return vertForwardBase(v);
}

half4 fragAdd(VertexOutputForwardBase i) : SV_Target
{
    return fragForwardAddInternal(i);
}

#endif
