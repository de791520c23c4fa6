// pbrlab stand-in for URP's ShaderLibrary/Debug/DebuggingFullscreen.hlsl (URP 12 on): the
// rendering debugger's full-screen overrides (CanDebugOverrideOutputColor and the functions it
// calls), which URP defines under DEBUG_DISPLAY only and which full-screen passes call under
// DEBUG_DISPLAY only (written for pbrlab from the names of URP 12's file; Unity's own file is under
// the Unity Companion License and is not copied). pbrlab has no rendering debugger and never
// defines DEBUG_DISPLAY: with it off URP's file declares nothing, and neither does this one.
#ifndef PBRLAB_URP_DEBUGGING_FULLSCREEN_HLSL
#define PBRLAB_URP_DEBUGGING_FULLSCREEN_HLSL
#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
#endif
