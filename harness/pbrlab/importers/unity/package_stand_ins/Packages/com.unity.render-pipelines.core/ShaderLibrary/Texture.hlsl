// pbrlab stand-in for Core RP's ShaderLibrary/Texture.hlsl: the texture and sampler macros (TEXTURE2D, SAMPLER, SAMPLE_TEXTURE2D, ...) and UnityTexture2D, which pbrlab's
// stand-in Core.hlsl defines (written for pbrlab from Unity's documentation of the names;
// Unity's own file is under the Unity Companion License and is not copied).
#ifndef PBRLAB_CORE_RP_TEXTURE_HLSL
#define PBRLAB_CORE_RP_TEXTURE_HLSL

#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"

#endif
