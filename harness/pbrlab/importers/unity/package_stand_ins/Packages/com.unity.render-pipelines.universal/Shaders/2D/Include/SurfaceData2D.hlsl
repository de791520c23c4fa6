// pbrlab stand-in for URP's Shaders/2D/Include/SurfaceData2D.hlsl: the 2D renderer's surface and
// input data for its rendering debugger, which 2D passes read under DEBUG_DISPLAY only (written
// for pbrlab; URP's own file is under the Unity Companion License and is not copied). pbrlab has
// no rendering debugger and never defines DEBUG_DISPLAY: nothing here (a shader that reads
// SurfaceData2D elsewhere is refused naming it).
#ifndef PBRLAB_URP_SURFACE_DATA_2D_HLSL
#define PBRLAB_URP_SURFACE_DATA_2D_HLSL
#endif
