// pbrlab stand-in for URP's Shaders/2D/Include/Core2D.hlsl (the 2D renderer's sprite inputs),
// written for pbrlab from Unity's documentation of the SpriteRenderer (its colour and flip) and
// of sprite skinning; URP's own file is under the Unity Companion License and is not copied.
// pbrlab draws meshes, not sprites: a mesh is drawn as a SpriteRenderer with no flip, a white
// colour and no bones draws its sprite. unity_SpriteColor is that white colour, unity_SpriteProps
// the flip (1, 1) in xy and, in z, the skinning's bone offset, -1 (none); UnityFlipSprite scales
// the position's xy by the flip. The skinned-sprite macros are those of the unskinned variant
// (SKINNED_SPRITE undefined): no vertex inputs and no skinning.
#ifndef PBRLAB_URP_CORE_2D_HLSL
#define PBRLAB_URP_CORE_2D_HLSL

static const float4 unity_SpriteColor = float4(1.0, 1.0, 1.0, 1.0);
static const float4 unity_SpriteProps = float4(1.0, 1.0, -1.0, 0.0);

#define UNITY_SKINNED_VERTEX_INPUTS
#define UNITY_SKINNED_VERTEX_COMPUTE(x)

float3 UnityFlipSprite(float3 pos, float2 flip) { return float3(pos.xy * flip, pos.z); }

#endif
