// pbrlab stand-in for Core RP's ShaderLibrary/DebugMipmapStreamingMacros.hlsl (Unity 6), which
// URP's terrain and lit passes (and Amplify's templates of them) include to declare the
// rendering debugger's mipmap-streaming constants inside UnityPerMaterial (written for pbrlab
// from Unity's documentation of the mipmap streaming debug views; Core RP's own file is under
// the Unity Companion License and is not copied). Its two macros declare float4 members whatever
// the debugger's state, so a constant buffer keeps its layout: UNITY_TEXTURE_STREAMING_DEBUG_VARS
// the shared debug texture's scale-offset, texel size, mip and stream information, and
// UNITY_TEXTURE_STREAMING_DEBUG_VARS_FOR_TEX(tex) a texture's tex_MipInfo and tex_StreamInfo.
// pbrlab has no rendering debugger: nothing sets them, and they read 0 like any unset uniform.
// CBUFFER_START is empty here (Core.hlsl), so they are globals, marked uniform: the GLSL port
// makes a global a uniform where it reads the declaration in the source, which a macro's
// expansion is not (without it they were uninitialised globals there).
#ifndef PBRLAB_CORE_RP_DEBUG_MIPMAP_STREAMING_MACROS_HLSL
#define PBRLAB_CORE_RP_DEBUG_MIPMAP_STREAMING_MACROS_HLSL

#define UNITY_TEXTURE_STREAMING_DEBUG_VARS uniform float4 unity_MipmapStreaming_DebugTex_ST; \
    uniform float4 unity_MipmapStreaming_DebugTex_TexelSize; uniform float4 unity_MipmapStreaming_DebugTex_MipInfo; \
    uniform float4 unity_MipmapStreaming_DebugTex_StreamInfo;
#define UNITY_TEXTURE_STREAMING_DEBUG_VARS_FOR_TEX(tex) uniform float4 tex##_MipInfo; uniform float4 tex##_StreamInfo;

#endif
