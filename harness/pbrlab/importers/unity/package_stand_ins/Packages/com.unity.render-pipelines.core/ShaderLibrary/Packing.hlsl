// pbrlab stand-in for Core RP's ShaderLibrary/Packing.hlsl: the normal-map unpacking (UnpackNormal, UnpackNormalScale, UnpackNormalRGB, ...), which pbrlab's
// stand-in Core.hlsl defines (written for pbrlab from Unity's documentation of the names;
// Unity's own file is under the Unity Companion License and is not copied).
#ifndef PBRLAB_CORE_RP_PACKING_HLSL
#define PBRLAB_CORE_RP_PACKING_HLSL

#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"

#endif
