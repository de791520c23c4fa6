// pbrlab stand-in for Core RP's ShaderLibrary/GlobalSamplers.hlsl: the shared inline sampler
// states sampler_PointClamp, sampler_LinearClamp, sampler_PointRepeat and sampler_LinearRepeat
// (written for pbrlab from Unity's documentation of inline sampler states, whose names give
// the filter and wrap; Core RP's own file is under the Unity Companion License and is not
// copied). Here, as for every sampler, the GL texture's own filtering applies: the full-screen
// pass's _BlitTexture is bilinear and clamped to its edge (importers/unity/fullscreen_pass.py),
// so a point sampler reads the same value at a texel's centre.
#ifndef PBRLAB_CORE_RP_GLOBAL_SAMPLERS_HLSL
#define PBRLAB_CORE_RP_GLOBAL_SAMPLERS_HLSL

#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"

SAMPLER(sampler_PointClamp);
SAMPLER(sampler_LinearClamp);
SAMPLER(sampler_PointRepeat);
SAMPLER(sampler_LinearRepeat);

#endif
