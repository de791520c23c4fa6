// pbrlab stand-in for Core RP's ShaderLibrary/FoveatedRendering.hlsl, which Shader Graph's
// generated passes include (written for pbrlab from Unity's documentation of foveated
// rendering; Core RP's own file is under the Unity Companion License and is not copied).
// Foveated rendering is an XR feature of the PlayStation 5's and Metal's APIs (non-uniform
// rasterization under _FOVEATED_RENDERING_NON_UNIFORM_RASTER); on Direct3D, Vulkan and OpenGL
// the file declares nothing, and pbrlab renders one uniform view: empty here too.
#ifndef PBRLAB_CORE_RP_FOVEATED_RENDERING_HLSL
#define PBRLAB_CORE_RP_FOVEATED_RENDERING_HLSL
#endif
