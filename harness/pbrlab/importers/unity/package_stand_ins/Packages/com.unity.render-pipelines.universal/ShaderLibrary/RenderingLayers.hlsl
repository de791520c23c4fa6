// pbrlab stand-in for URP's ShaderLibrary/RenderingLayers.hlsl: every mesh and every light in
// every rendering layer (pbrlab's scenes have no layers), written for pbrlab from Unity's
// documentation of the names (URP's own file is under the Unity Companion License).
#ifndef PBRLAB_URP_RENDERING_LAYERS_HLSL
#define PBRLAB_URP_RENDERING_LAYERS_HLSL

uint GetMeshRenderingLayer() { return 0xFFFFFFFFu; }
bool IsMatchingLightLayer(uint lightLayers, uint renderingLayers) { return (lightLayers & renderingLayers) != 0u; }

#endif
