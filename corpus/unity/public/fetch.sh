#!/usr/bin/env bash
# Public Unity shader corpus (surface + vertex/fragment shaders, built-in render pipeline).
#
# Every file under this folder is a byte-for-byte copy of a file in a public GitHub
# repository at the commit listed below; <owner>__<repo>/LICENSE is a byte-for-byte copy
# of that repository's licence text (for repositories that state their licence only in
# README.md, that README is what was copied - see "licence_file" in MANIFEST.json).
# MANIFEST.json lists every shader with repo, commit, source path, SPDX licence and the
# features it exercises.
#
# There is no general network access here, so this script does not download anything.
#   ./fetch.sh               verify every corpus file against SHA256SUMS (default)
#   ./fetch.sh --list        print, per repository, the commit and the files to fetch
#   ./fetch.sh --from-mirrors DIR
#                            re-extract the files from bare git snapshots laid out as
#                            DIR/<owner>+<repo>/repo (the layout the project's "fetch"
#                            tooling produces, e.g. DIR=/work/.mirror), checking that each
#                            snapshot's HEAD is the recorded commit, then verify checksums.
set -euo pipefail
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"

# repo|commit|licence source path|SPDX
REPOS=(
  "ronja-tutorials/ShaderTutorials|31899f7b7de1158be45c968c1ac039c04b849bbb|README.md|CC-BY-4.0"
  "keijiro/Skinner|4f1b8656985d89c92f31d20e93ca1b1446c4640e|LICENSE.md|MIT"
  "keijiro/Swarm|8b94c0d1ac89d33eb7d21590fc633baf32f380bd|LICENSE.md|MIT"
  "keijiro/StandardTriplanar|33544a08761f8f028f5e76785c697ad3df7370e4|README.md|Unlicense"
  "keijiro/KvantSpray|f103f8cbe0bde0337d098abbcb12ead576a7d823|README.md|MIT"
  "keijiro/KvantWall|b5c093bf7b37cdeef71338b207f7660b8579f0e1|README.md|MIT"
  "bgolus/Normal-Mapping-for-a-Triplanar-Shader|a3571bf5f6e857e85c2f37875e79568282277de8|LICENSE|Unlicense"
  "SebLague/Hydraulic-Erosion|f245576d204978e3186f41c8abbd75c326c6857e|LICENSE|MIT"
  "SebLague/Procedural-Landmass-Generation|e350384ce8b59286b522c9546dcd4a34475e4aec|LICENSE.md|MIT"
  "SebLague/Portals|53ff52abc836837eb248ffce980345fa645d817f|License|MIT"
  "SebLague/Solar-System|0c60882be69b8e96d6660c28405b9d19caee76d5|LICENSE|MIT"
  "IronWarrior/UnityToonShader|4095d68736e5051d6ebba32210863385bc858017|LICENSE|Unlicense"
  "Chaser324/unity-wireframe|d88bf0d042bef74d59258850db5c73a64e4423ad|Packages/unity-wireframe/LICENSE.md|MIT"
  "googlevr/tilt-brush-toolkit|a00160639c0b231fd2acd1a05f85084d9970c353|LICENSE|Apache-2.0"
)

# repo|path in repo (shaders and the local .cginc files they include)
FILES=(
  "ronja-tutorials/ShaderTutorials|Assets/005_Surface_Basics/simple_surface.shader"
  "ronja-tutorials/ShaderTutorials|Assets/012_Fresnel/Fresnel.shader"
  "ronja-tutorials/ShaderTutorials|Assets/013_CustomSurfaceLighting/CustomLighting.shader"
  "ronja-tutorials/ShaderTutorials|Assets/015_VertexManipulation/vertexmanipulation.shader"
  "ronja-tutorials/ShaderTutorials|Assets/020_Inverted_Hull/SurfaceOutlines.shader"
  "ronja-tutorials/ShaderTutorials|Assets/021_Clipping_Plane/ClippingPlane.shader"
  "ronja-tutorials/ShaderTutorials|Assets/022_Stencil_Buffer/stencil_read.shader"
  "ronja-tutorials/ShaderTutorials|Assets/024_White_Noise/white_noise_cells.shader"
  "ronja-tutorials/ShaderTutorials|Assets/024_White_Noise/WhiteNoise.cginc"
  "ronja-tutorials/ShaderTutorials|Assets/026_Perlin_Noise/perlin_noise_3d.shader"
  "ronja-tutorials/ShaderTutorials|Assets/026_Perlin_Noise/Random.cginc"
  "ronja-tutorials/ShaderTutorials|Assets/027_Layered_Noise/layered_noise_special.shader"
  "ronja-tutorials/ShaderTutorials|Assets/027_Layered_Noise/Random.cginc"
  "ronja-tutorials/ShaderTutorials|Assets/028_Voronoi_Noise/voronoi_noise_2d.shader"
  "ronja-tutorials/ShaderTutorials|Assets/028_Voronoi_Noise/Random.cginc"
  "ronja-tutorials/ShaderTutorials|Assets/032_ImprovedToon/ImprovedToonLighting.shader"
  "ronja-tutorials/ShaderTutorials|Assets/033_River/FlowingRiver.shader"
  "ronja-tutorials/ShaderTutorials|Assets/038_Dissolve/Dissolve.shader"
  "ronja-tutorials/ShaderTutorials|Assets/040_Halftone_Lighting/HalftoneShading.shader"
  "ronja-tutorials/ShaderTutorials|Assets/042_Dithering/DistanceFade.shader"
  "ronja-tutorials/ShaderTutorials|Assets/020_Inverted_Hull/UnlitOutlines.shader"
  "ronja-tutorials/ShaderTutorials|Assets/010_Triplanar_Mapping/triplanar_mapping.shader"
  "ronja-tutorials/ShaderTutorials|Assets/041_HSV_Colorspace/HSVAdjust.shader"
  "ronja-tutorials/ShaderTutorials|Assets/041_HSV_Colorspace/HSVLibrary.cginc"
  "ronja-tutorials/ShaderTutorials|Assets/006_Transparency/transparent.shader"
  "ronja-tutorials/ShaderTutorials|Assets/044_SphereTracingShading/SphereTracingShading.shader"
  "keijiro/Skinner|Assets/Skinner/Shader/ParticleSurfaceStandard.shader"
  "keijiro/Skinner|Assets/Skinner/Shader/ParticleMotion.cginc"
  "keijiro/Skinner|Assets/Skinner/Shader/Common.cginc"
  "keijiro/Skinner|Assets/Skinner/Shader/ParticleSurface.cginc"
  "keijiro/Skinner|Assets/Skinner/Shader/TrailSurface.shader"
  "keijiro/Skinner|Assets/Skinner/Shader/TrailMotion.cginc"
  "keijiro/Skinner|Assets/Skinner/Shader/TrailSurface.cginc"
  "keijiro/Skinner|Assets/Skinner/Shader/GlitchSurface.shader"
  "keijiro/Skinner|Assets/Skinner/Shader/GlitchSurface.cginc"
  "keijiro/Swarm|Assets/Swarm/Shader/Tube.shader"
  "keijiro/StandardTriplanar|Assets/Triplanar/Shaders/StandardTriplanar.shader"
  "keijiro/KvantSpray|Assets/Kvant/Spray/Shaders/Opaque.shader"
  "keijiro/KvantSpray|Assets/Kvant/Spray/Shaders/Common.cginc"
  "keijiro/KvantWall|Assets/Kvant/Wall/Shaders/Surface.shader"
  "bgolus/Normal-Mapping-for-a-Triplanar-Shader|TriplanarSurfaceShader.shader"
  "bgolus/Normal-Mapping-for-a-Triplanar-Shader|TriplanarWhiteout.shader"
  "bgolus/Normal-Mapping-for-a-Triplanar-Shader|TriplanarRNM.shader"
  "SebLague/Hydraulic-Erosion|Assets/Shaders/Terrain2.shader"
  "SebLague/Procedural-Landmass-Generation|Proc Gen E21/Assets/Scripts/Terrain.shader"
  "SebLague/Portals|Assets/Scripts/Core/Shaders/Slice.shader"
  "SebLague/Portals|Assets/Scripts/Demo/Shaders/CloudTest.shader"
  "SebLague/Portals|Assets/Scripts/Core/Shaders/Portal.shader"
  "SebLague/Solar-System|Assets/Scripts/Celestial/Shaders/Surface/Earth.shader"
  "SebLague/Solar-System|Assets/Scripts/Celestial/Shaders/Includes/Triplanar.cginc"
  "SebLague/Solar-System|Assets/Scripts/Celestial/Shaders/Includes/Math.cginc"
  "SebLague/Solar-System|Assets/Scripts/Celestial/Shaders/Surface/MoonA.shader"
  "SebLague/Solar-System|Assets/Scripts/Game/Shaders/Stipple.shader"
  "IronWarrior/UnityToonShader|Assets/Toon.shader"
  "Chaser324/unity-wireframe|Packages/unity-wireframe/Runtime/Shaders/Wireframe.shader"
  "Chaser324/unity-wireframe|Packages/unity-wireframe/Runtime/Shaders/Wireframe.cginc"
  "Chaser324/unity-wireframe|Packages/unity-wireframe/Runtime/Shaders/WireframeShaded-Unlit.shader"
  "googlevr/tilt-brush-toolkit|UnitySDK/Assets/TiltBrush/Assets/Brushes/Basic/Disco/Disco.shader"
  "googlevr/tilt-brush-toolkit|UnitySDK/Assets/TiltBrush/Assets/Shaders/Include/Brush.cginc"
  "googlevr/tilt-brush-toolkit|UnitySDK/Assets/TiltBrush/Assets/Brushes/Shared/Shaders/DiffuseDoubleSided.shader"
  "googlevr/tilt-brush-toolkit|UnitySDK/Assets/TiltBrush/Assets/Brushes/Shared/Shaders/StandardSingleSided.shader"
  "googlevr/tilt-brush-toolkit|UnitySDK/Assets/TiltBrush/Assets/Brushes/Basic/Hypercolor/HypercolorSingleSided.shader"
  "googlevr/tilt-brush-toolkit|UnitySDK/Assets/TiltBrush/Assets/Brushes/Blocks/BlocksGlass/BlocksGlass.shader"
  "googlevr/tilt-brush-toolkit|UnitySDK/Assets/TiltBrush/Materials/PbrBlendSingleSided.shader"
  "googlevr/tilt-brush-toolkit|UnitySDK/Assets/TiltBrush/Assets/Brushes/Basic/WaveformPulse/NeonPulse.shader"
)

# The commands (verify, list, from-mirrors): shared by every corpus folder.
source "$HERE/../../fetch_corpus.sh" "$@"
