// pbrlab stand-in for Core RP's ShaderLibrary/TextureStack.hlsl: Streaming Virtual Texturing's
// stacks, which Shader Graph's generated code includes whether or not a graph samples one. No
// virtual texturing here: the include adds nothing, and a graph that samples a stack is
// refused by the names it uses (written for pbrlab from Unity's documentation; Core RP's own
// file is under the Unity Companion License and is not copied).
#ifndef PBRLAB_CORE_RP_TEXTURE_STACK_HLSL
#define PBRLAB_CORE_RP_TEXTURE_STACK_HLSL

#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"

#endif
