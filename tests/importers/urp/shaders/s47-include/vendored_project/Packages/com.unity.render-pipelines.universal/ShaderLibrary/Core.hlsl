#ifndef UNIVERSAL_PIPELINE_CORE_INCLUDED
#define UNIVERSAL_PIPELINE_CORE_INCLUDED
// s47-include: a project's embedded copy of URP's ShaderLibrary/Core.hlsl (Unity's include
// guard). pbrlab reads its stand-in in this file's place; compiled as written it stops here.
#error "the project's copy of Core.hlsl was compiled"
#endif
