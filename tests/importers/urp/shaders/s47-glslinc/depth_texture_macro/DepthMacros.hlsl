// s47-glslinc: the texture-declaring macro defined in a file the program includes.
#ifndef S47_GLSLINC_DEPTH_MACROS_INCLUDED
#define S47_GLSLINC_DEPTH_MACROS_INCLUDED
#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
#define DEPTH_TEXTURE(name) TEXTURE2D_FLOAT(name)
#endif
