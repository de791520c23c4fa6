// pbrlab stand-in for URP's ShaderLibrary/ParticlesInstancing.hlsl: the helpers of a particle
// shader's GPU-instanced variant, in the variant the harness draws, without instancing
// (UNITY_PARTICLE_INSTANCING_ENABLED undefined: the harness draws no particle system; written for
// pbrlab from Unity's documentation of Particle System GPU instancing in URP; URP's own file is
// under the Unity Companion License and is not copied). There a particle's colour and texture
// coordinates are the mesh's own vertex data, passed through unchanged.
#ifndef PBRLAB_URP_PARTICLES_INSTANCING_HLSL
#define PBRLAB_URP_PARTICLES_INSTANCING_HLSL

#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"

// `#pragma instancing_options procedural:ParticleInstancingSetup`'s function: it fetches the
// instance's transform when instanced; without instancing there is nothing to set up.
void ParticleInstancingSetup() {}

// The vertex colour (instanced: blended with the instance's colour; here the vertex's own).
half4 GetParticleColor(half4 color) { return color; }

// The flipbook's texture coordinates: the frame's uv in xy; with flipbook blending
// (_FLIPBOOKBLENDING_ON) the next frame's uv (zw) and the blend between them, otherwise 0.
void GetParticleTexcoords(out float2 outputTexcoord, out float3 outputTexcoord2AndBlend, in float4 inputTexcoords,
                          in float inputBlend) {
    outputTexcoord = inputTexcoords.xy;
#ifdef _FLIPBOOKBLENDING_ON
    outputTexcoord2AndBlend = float3(inputTexcoords.zw, inputBlend);
#else
    outputTexcoord2AndBlend = float3(0.0, 0.0, 0.0);
#endif
}

void GetParticleTexcoords(out float2 outputTexcoord, in float2 inputTexcoord) { outputTexcoord = inputTexcoord; }

#endif
