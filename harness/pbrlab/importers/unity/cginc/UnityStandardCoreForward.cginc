// pbrlab stand-in for Unity's UnityStandardCoreForward.cginc: the entry points the Standard
// shaders' forward passes name in #pragma vertex / fragment.
//
// Provides: vertBase, fragBase (LightMode ForwardBase: the main light, the ambient, the
//   environment and the emission), vertAdd, fragAdd (ForwardAdd: one more light, added);
//   UnityStandardCore.cginc does the work.
// Unity's file: the same names (UnityStandardCoreForward.cginc, Unity 2019.4 built-in
//   shaders), read for their behaviour and written here anew.
// Differences: the add pass's vertex output, VertexOutputForwardAdd, holds the base pass's
//   members (Unity's has a per-vertex light direction; here it is per pixel); it is its own
//   struct, as Unity's, so that a program's fragment function that takes one and calls fragAdd
//   (a dissolve effect over the Standard passes) reads its tex as in Unity.
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

struct VertexOutputForwardAdd
{
    float4 pos : SV_POSITION;
    float4 tex : TEXCOORD0;          // xy: main UV, zw: detail UV
    float3 posWorld : TEXCOORD1;
    float3 normalWorld : TEXCOORD2;
    float4 tangentWorld : TEXCOORD3; // w: the bitangent's sign
};

VertexOutputForwardAdd vertAdd(VertexInput v)
{
    VertexOutputForwardBase b = vertForwardBase(v);
    VertexOutputForwardAdd o;
    o.pos = b.pos;
    o.tex = b.tex;
    o.posWorld = b.posWorld;
    o.normalWorld = b.normalWorld;
    o.tangentWorld = b.tangentWorld;
    return o;
}

half4 fragAdd(VertexOutputForwardAdd i) : SV_Target
{
    VertexOutputForwardBase b;
    b.pos = i.pos;
    b.tex = i.tex;
    b.posWorld = i.posWorld;
    b.normalWorld = i.normalWorld;
    b.tangentWorld = i.tangentWorld;
    return fragForwardAddInternal(b);
}

#endif
