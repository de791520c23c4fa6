// pbrlab stand-in for URP's ShaderLibrary/Debug/Debugging3D.hlsl: the Rendering Debugger's hooks
// in a 3D pass. Without the debugger's DEBUG_DISPLAY keyword (a normal view, a player build) URP's
// file only defines SETUP_DEBUG_TEXTURE_DATA as nothing, which pbrlab's stand-in Core.hlsl does
// (written for pbrlab from Unity's documentation of the Rendering Debugger; Unity's own file is
// under the Unity Companion License and is not copied). The debugger's views are not drawn here.
#ifndef PBRLAB_URP_DEBUGGING3D_HLSL
#define PBRLAB_URP_DEBUGGING3D_HLSL

#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Debug/DebuggingCommon.hlsl"

#if defined(DEBUG_DISPLAY)
#error "URP's Rendering Debugger (DEBUG_DISPLAY, Debugging3D.hlsl's debug views) is not provided by pbrlab's stand-in"
#endif

#endif
