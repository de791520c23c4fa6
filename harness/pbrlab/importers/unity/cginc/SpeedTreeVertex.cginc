// pbrlab stand-in for Unity's SpeedTreeVertex.cginc (Nature/SpeedTree*.shader): a refusal.
//
// Provides: nothing; including it stops the shader with one message.
// Unity's file: part of the SpeedTree integration (SpeedTreeCommon, SpeedTree8Common,
//   SpeedTreeBillboardCommon, SpeedTreeVertex, SpeedTreeWind .cginc, Unity 2019.4 built-in
//   shaders): the tree's vertices are moved by SpeedTree's wind, whose per-tree constants
//   (_ST_Wind*, dozens of float4s) the engine feeds from the .spm/.st8 asset, and its
//   billboards read baked per-tree geometry (_BillboardNormals, _BillboardTangents,
//   _ImageTexCoords) and per-vertex data packed in the mesh's UV channels.
// Differences: pbrlab has none of that data, so no stand-in could draw the tree as Unity does.
//   The harness's parser reads this #error (outside every #if) and refuses the shader at its
//   #include line: harness/pbrlab/importers/unity/parse.py, check_refusals.
#error "SpeedTree shaders need SpeedTree's wind and billboard data, which pbrlab does not have"
