// pbrlab stand-in for Unity's UnityUIE.cginc (Internal-UIRDefault and UI Toolkit shaders): a refusal.
//
// Provides: nothing; including it stops the shader with one message.
// Unity's file: UI Toolkit's (UIElements') renderer: its vertex and fragment functions, which
//   read the per-vertex transform and clip-rect indices, the atlas, font and custom textures,
//   and the shader-info texture UI Toolkit fills for each panel it draws.
// Differences: the harness has no UI Toolkit panel to feed those, so no stand-in could draw
//   what Unity draws. The harness's parser reads this #error (outside every #if) and refuses
//   the shader at its #include line: harness/pbrlab/importers/unity/parse.py, check_refusals.
#error "UI Toolkit's renderer draws from the per-vertex transforms, clip rects and atlases a UI Toolkit panel feeds, which pbrlab does not have"
