// pbrlab stand-in for URP's ShaderLibrary/UnityGBuffer.hlsl, the G-buffer layout of URP's
// deferred renderer: its lighting-mode and material-flag constants and the flags' packing into
// an 8-bit channel (written for pbrlab from Unity's documentation of URP's deferred path, whose
// G-buffer's gbuffer0.a holds the material flags; URP's own file is under the Unity Companion
// License and is not copied). As URP's, it includes SurfaceData.hlsl and Lighting.hlsl.
//
// pbrlab renders forward: a forward pass that includes this file for its helpers compiles and
// reads the constants below. Not provided: the G-buffer's FragmentOutput struct and its encoders
// and decoders (SurfaceDataToGbuffer, BRDFDataToGbuffer, SurfaceDataFromGbuffer,
// BRDFDataFromGbuffer, InputDataFromGbufferAndWorldPosition), which only a deferred G-buffer pass
// calls, and its PackNormal / UnpackNormal, whose half3 UnpackNormal Core.hlsl's normal-map
// UnpackNormal would hide (a call of one of them fails to compile, naming it).
#ifndef PBRLAB_URP_UNITY_GBUFFER_HLSL
#define PBRLAB_URP_UNITY_GBUFFER_HLSL

#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/SurfaceData.hlsl"
#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Lighting.hlsl"

// The lighting mode the deferred lights shade a pixel with (its stencil bits): none, Lit, Simple Lit.
#define kLightingInvalid -1
#define kLightingLit 1
#define kLightingSimpleLit 2
// The material flags (bits of gbuffer0.a) and the light's flag for subtractive mixed lighting.
#define kMaterialFlagReceiveShadowsOff 1
#define kMaterialFlagSpecularHighlightsOff 2
#define kMaterialFlagSubtractiveMixedLighting 4
#define kMaterialFlagSpecularSetup 8
#define kLightFlagSubtractiveMixedLighting 4

// The flags (0..255) as an 8-bit UNORM channel's value, flags / 255, and back, round(255 v).
float PackMaterialFlags(uint materialFlags) { return float(materialFlags) / 255.0; }
uint UnpackMaterialFlags(float packedMaterialFlags) { return uint(packedMaterialFlags * 255.0 + 0.5); }

#endif
