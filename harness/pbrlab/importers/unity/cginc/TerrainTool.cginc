// pbrlab stand-in for Unity's TerrainTool.cginc (the terrain editor's brush shaders: PaintHeight,
// BrushPreview and the Terrain Tools' own): a refusal.
//
// Provides: nothing; including it stops the shader with one message.
// Unity's file: the terrain editor's PaintContext transforms (a paint context's UV or pixel to
//   the brush's, the heightmap's and the terrain's object space), read through the uniforms the
//   editor sets for the terrain tile being painted (_PCUVToBrushUVScales, _PCUVToBrushUVOffset,
//   _PCPixelsToHeightmapUV and their kin).
// Differences: the harness has no terrain and no editor to set them (they would read as zero,
//   drawing nothing Unity draws). The harness's parser reads this #error (outside every #if)
//   and refuses the shader at its #include line: harness/pbrlab/importers/unity/parse.py,
//   check_refusals.
#error "the terrain editor's brush shaders read the paint context the editor sets for the terrain being painted, which pbrlab does not have"
