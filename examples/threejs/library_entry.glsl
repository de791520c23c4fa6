// examples/threejs/library_entry.glsl: what the three.js example takes from pbrlab, amalgamated
// into one file by `pbrlab amalgamate examples/threejs/library_entry.glsl -o pbrlab_library.glsl`:
// the library and its Unity-style surface API (SurfaceOutputStandard, UnityGI, LightingStandard).
#include "pbr/pbr.glsl"
#include "pbr/unity/surface_standard.glsl"
