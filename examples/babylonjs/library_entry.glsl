// examples/babylonjs/library_entry.glsl: what the Babylon.js example takes from pbrlab, amalgamated
// into one file by `pbrlab amalgamate examples/babylonjs/library_entry.glsl -o pbrlab_library.glsl`
// and handed to Babylon.js as it is (Babylon.js's own preprocessor evaluates its conditionals):
// the library and its Unity-style surface API (SurfaceOutputStandard, UnityGI, LightingStandard).
#include "pbr/pbr.glsl"
#include "pbr/unity/surface_standard.glsl"
