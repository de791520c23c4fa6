// pbrlab stand-in for URP's ShaderLibrary/Debug/Debugging2D.hlsl: the rendering debugger's 2D
// functions, which 2D passes call under DEBUG_DISPLAY only (written for pbrlab; URP's own file is
// under the Unity Companion License and is not copied). pbrlab has no rendering debugger and
// never defines DEBUG_DISPLAY: nothing here.
#ifndef PBRLAB_URP_DEBUGGING_2D_HLSL
#define PBRLAB_URP_DEBUGGING_2D_HLSL
#endif
