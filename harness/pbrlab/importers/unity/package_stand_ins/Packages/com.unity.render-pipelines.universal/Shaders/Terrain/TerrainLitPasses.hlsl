// pbrlab stand-in for URP 12's Shaders/Terrain/TerrainLitPasses.hlsl: the Terrain Lit shader's own
// passes (SplatmapVert / SplatmapFragment, SplatmapMix's layer blending with height-based
// transitions, the terrain's shadow and depth passes), written for pbrlab (Unity's own file is
// under the Unity Companion License and is not copied). They are not provided: a custom terrain
// shader that reads the terrain's inputs (TerrainLitInput.hlsl) with passes of its own is drawn;
// one that takes URP's passes is refused, naming them. The parser reads this #error (outside
// every #if) and refuses the shader at its #include line.
#ifndef PBRLAB_URP_TERRAIN_LIT_PASSES_HLSL
#define PBRLAB_URP_TERRAIN_LIT_PASSES_HLSL
#error "URP's Terrain Lit passes (TerrainLitPasses.hlsl: SplatmapVert, SplatmapFragment, SplatmapMix and the terrain's shadow and depth passes) are not provided by pbrlab's stand-in; its inputs (TerrainLitInput.hlsl) are"
#endif
