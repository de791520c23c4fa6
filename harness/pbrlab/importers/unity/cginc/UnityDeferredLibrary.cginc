// pbrlab stand-in for Unity's UnityDeferredLibrary.cginc (Internal-DeferredShading,
// Internal-DeferredReflections, Internal-PrePassLighting): a refusal.
//
// Provides: nothing; including it stops the shader with one message.
// Unity's file: the deferred path's light and reflection passes' helpers: a full-screen or
//   light-volume vertex stage, and the reading of the G-buffer (_CameraGBufferTexture0..3) and
//   the camera's depth at each pixel to rebuild the surface a light shades.
// Differences: the harness shades forward; it renders no G-buffer, so a deferred pass has no
//   surface to light. The harness's parser reads this #error (outside every #if) and refuses
//   the shader at its #include line: harness/pbrlab/importers/unity/parse.py, check_refusals.
#error "a deferred lighting pass reads the G-buffer Unity's deferred path renders, which the harness (forward shading) does not make"
