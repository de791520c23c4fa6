// pbrlab stand-in for URP's ShaderLibrary/Debug/DebuggingCommon.hlsl: the Rendering Debugger's
// queries a lit pass asks (URP 12+). Without the debugger's DEBUG_DISPLAY keyword, the normal view
// pbrlab draws, URP's file answers that every lighting feature is on and that the view is not
// the ambient-occlusion-only one (URP 14.0.9 DebuggingCommon.hlsl, IsLightingFeatureEnabled,
// IsOnlyAOLightingFeatureEnabled); the debugger's views themselves are refused
// (Debugging3D.hlsl). Written for pbrlab from Unity's documentation of the Rendering Debugger;
// Unity's own file is under the Unity Companion License and is not copied.
#ifndef PBRLAB_URP_DEBUGGING_COMMON_HLSL
#define PBRLAB_URP_DEBUGGING_COMMON_HLSL

// URP's lighting features (DebugLightingFeatureFlags): any mask is enabled in the normal view.
bool IsLightingFeatureEnabled(uint bitMask) { return true; }
// The "ambient occlusion only" lighting view: never, in the normal view.
bool IsOnlyAOLightingFeatureEnabled() { return false; }

#endif
