// pbrlab stand-in for URP's Shaders/2D/Include/LightingUtility.hlsl (the 2D Renderer's light
// passes, Light2D-Point / Light2D-Shape and their volumetric forms): a refusal.
//
// Provides: nothing; including it stops the shader with one message.
// Unity's file: the 2D Renderer's helpers for drawing one 2D light into its light textures: the
//   light's normal-map and shadow inputs, read with the per-light data the 2D Renderer sets for
//   each Light2D it draws (_LightLookup, the renderer's distance/angle lookup texture;
//   _FalloffLookup; _LightInvMatrix; _LightColor; the shadow texture). Unity draws these passes
//   only for a 2D light, never on a scene's object.
// Differences: a pbrlab scene has no 2D lights, nor the lookup textures the 2D Renderer builds,
//   so a neutral stand-in would draw a picture Unity never shows (written for pbrlab from Unity's
//   documentation of the 2D Renderer's lights; Unity's file is under the Unity Companion License
//   and is not copied). The parser reads this #error (outside every #if) and refuses the shader
//   at its #include line: source_text.check_refusals.
#error "the 2D Renderer's light pass (LightingUtility.hlsl) draws a 2D light into the 2D Renderer's light textures from its lookup textures (_LightLookup, _FalloffLookup) and per-light matrices, which pbrlab's scenes (no 2D lights) do not have"
