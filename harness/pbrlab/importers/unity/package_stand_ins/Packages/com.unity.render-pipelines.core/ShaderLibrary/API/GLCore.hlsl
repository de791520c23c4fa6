// pbrlab stand-in for Core RP's ShaderLibrary/API/GLCore.hlsl: the texture and sampler macros of
// the platform pbrlab compiles for (OpenGL core, SHADER_API_GLCORE: importers/unity/graphics_api.py).
// pbrlab's stand-in Core.hlsl defines the family's common forms and includes this file for the rest
// (written for pbrlab from Unity's documentation of the names; Unity's own file is under the Unity
// Companion License and is not copied).
// Provides: the declarations' precision forms, TEXTURE2D_FLOAT / _HALF, TEXTURECUBE_FLOAT / _HALF,
//   TEXTURE3D_FLOAT / _HALF, TEXTURE2D_ARRAY_FLOAT / _HALF: the same texture objects as TEXTURE2D
//   etc. (Unity's GL targets have no half-precision texture type; pbrlab reads float32 throughout).
#ifndef PBRLAB_CORE_RP_API_GLCORE_HLSL
#define PBRLAB_CORE_RP_API_GLCORE_HLSL

#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"

#define TEXTURE2D_FLOAT(t) Texture2D t
#define TEXTURE2D_HALF(t) Texture2D t
#define TEXTURECUBE_FLOAT(t) TextureCube t
#define TEXTURECUBE_HALF(t) TextureCube t
#define TEXTURE3D_FLOAT(t) Texture3D t
#define TEXTURE3D_HALF(t) Texture3D t
#define TEXTURE2D_ARRAY_FLOAT(t) Texture2DArray t
#define TEXTURE2D_ARRAY_HALF(t) Texture2DArray t

#endif
