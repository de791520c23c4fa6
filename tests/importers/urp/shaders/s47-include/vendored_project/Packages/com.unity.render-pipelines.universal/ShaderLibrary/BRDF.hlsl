#ifndef MY_EMBEDDED_BRDF_INCLUDED
#define MY_EMBEDDED_BRDF_INCLUDED
// s47-include: a file of the embedded package that pbrlab has a stand-in for but no guard
// entry (vendored_library.GUARDS): named by its package path, the stand-in is read first.
#error "the project's copy of BRDF.hlsl was compiled"
#endif
