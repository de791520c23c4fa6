#!/usr/bin/env bash
# Public Universal Render Pipeline (URP) shader corpus: ShaderLab shaders with HLSLPROGRAM blocks
# that include Packages/com.unity.render-pipelines.universal/ShaderLibrary/*.hlsl - hand-written
# unlit, lit, toon and outline shaders, two Shader Graph outputs, and a few "other" shaders.
#
# Every file under this folder is a byte-for-byte copy of a file in a public GitHub
# repository at the commit listed below; <owner>__<repo>/LICENSE is a byte-for-byte copy
# of that repository's licence file (its path in the repository is "licence_file" in
# MANIFEST.json). Licences: MIT, Apache-2.0, CC0-1.0 only. Unity's own URP shaders (Unity
# Companion License) are NOT in this folder and must never be: see fetch_unity_urp.sh.
# MANIFEST.json lists every shader with repo, commit, source path, SPDX licence, category
# (unlit/lit/toon/outline/shadergraph/other), a note on what it should show, the features it
# exercises, its local includes and the Unity package includes it needs.
#
# Local includes keep their repository paths. Includes written as project paths
# ("Assets/...", "Packages/<package>/...") resolve against <owner>__<repo>/, except where
# MANIFEST.json gives "package_roots" (a package that is the repository itself).
#
# There is no general network access here, so this script does not download anything.
#   ./fetch.sh               verify every corpus file against SHA256SUMS (default)
#   ./fetch.sh --list        print, per repository, the commit and the files to fetch
#   ./fetch.sh --from-mirrors DIR
#                            re-extract the files from bare git snapshots laid out as
#                            DIR/<owner>+<repo>/repo (the layout the project's "fetch"
#                            tooling produces, e.g. DIR=/work/.mirror), checking that each
#                            snapshot's HEAD is the recorded commit, then verify checksums.
#                            (decentraland/unity-renderer is taken at an older commit than its
#                            snapshot's HEAD: the warning for it is expected; the snapshot
#                            holds the history, so the files still come from that commit.)
set -euo pipefail
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"

# repo|commit|licence source path|SPDX
REPOS=(
  "Cyanilux/URP_ShaderCodeTemplates|457b34127e0f4431275ebb0926513da049ec294b|LICENSE|CC0-1.0"
  "ColinLeung-NiloCat/UnityURPToonLitShaderExample|fbe276e0df1d1f9379e13581c20b6a080a1a6977|LICENSE|MIT"
  "VKev/Unity-URP-Shaders-Code|e8776ad01050c0514fbcde21b8a59f790031d92f|LICENSE|MIT"
  "Kink3d/kShading|cc62b3bef6d781762248552571d7e68b1c413d82|LICENSE|MIT"
  "Delt06/urp-toon-shader|6981f7dc931b53a0bd797725f4dac30b824041d7|LICENSE.md|MIT"
  "ChiliMilk/URP_Toon|1a44450dc19c653c4f213a7c5ca6b0d6640976ee|LICENSE|MIT"
  "wj-bj/Unity-Tutorial-ShaderGraph|fc41e51f4f59ab6b0e4b27ae63ec2295fdc796e3|LICENSE|MIT"
  "decentraland/unity-renderer|b7e299199ea8fb530e0611e3f9b93543a21b1c8e|LICENSE|Apache-2.0"
  "Cyanilux/URP_GrassGeometryShader|51364f64bafda290f93fd87fdd7a334a62d3b877|LICENSE|MIT"
  "ColinLeung-NiloCat/UnityURPUnlitScreenSpaceDecalShader|11b2e58c09bd869fd7dd4c7c098eea2256ae9c3e|LICENSE|MIT"
)

# repo|path in repo (shaders and the local .hlsl files they include)
FILES=(
  "Cyanilux/URP_ShaderCodeTemplates|URP_UnlitTemplate.shader"
  "Cyanilux/URP_ShaderCodeTemplates|URP_TransparentUnlitTemplate.shader"
  "Cyanilux/URP_ShaderCodeTemplates|URP_Unlit+Template.shader"
  "Cyanilux/URP_ShaderCodeTemplates|URP_DiffuseLitTemplate.shader"
  "Cyanilux/URP_ShaderCodeTemplates|URP_SimpleLitTemplate.shader"
  "Cyanilux/URP_ShaderCodeTemplates|URP_PBRLitTemplate.shader"
  "Cyanilux/URP_ShaderCodeTemplates|PBRSurface.hlsl"
  "Cyanilux/URP_ShaderCodeTemplates|PBRInput.hlsl"
  "VKev/Unity-URP-Shaders-Code|Assets/Shaders/Object_Shader/Basic_Shader/Unlit_Shader/URP_Unlit.shader"
  "VKev/Unity-URP-Shaders-Code|Assets/Shaders/Object_Shader/Glow_Shader/URP_Glow.shader"
  "VKev/Unity-URP-Shaders-Code|Assets/VkevShaderLib.hlsl"
  "VKev/Unity-URP-Shaders-Code|Assets/Shaders/Object_Shader/Basic_Shader/BlinnPhong_Shader/URP_BlinnPhong.shader"
  "VKev/Unity-URP-Shaders-Code|Assets/Shaders/Object_Shader/Basic_Shader/BlinnPhong_Shader/ForwardLit_Pass.hlsl"
  "VKev/Unity-URP-Shaders-Code|Assets/Shaders/Object_Shader/Basic_Shader/BlinnPhong_Shader/ShadowCaster_Pass.hlsl"
  "Kink3d/kShading|Shaders/Lit.shader"
  "Kink3d/kShading|ShaderLibrary/LitInput.hlsl"
  "Kink3d/kShading|ShaderLibrary/Lighting.hlsl"
  "Kink3d/kShading|ShaderLibrary/LitForwardPass.hlsl"
  "Kink3d/kShading|ShaderLibrary/LitGBufferPass.hlsl"
  "Kink3d/kShading|ShaderLibrary/Input.hlsl"
  "ColinLeung-NiloCat/UnityURPToonLitShaderExample|SimpleURPToonLitOutlineExample.shader"
  "ColinLeung-NiloCat/UnityURPToonLitShaderExample|SimpleURPToonLitOutlineExample_Shared.hlsl"
  "ColinLeung-NiloCat/UnityURPToonLitShaderExample|NiloOutlineUtil.hlsl"
  "ColinLeung-NiloCat/UnityURPToonLitShaderExample|NiloZOffset.hlsl"
  "ColinLeung-NiloCat/UnityURPToonLitShaderExample|NiloInvLerpRemap.hlsl"
  "ColinLeung-NiloCat/UnityURPToonLitShaderExample|SimpleURPToonLitOutlineExample_LightingEquation.hlsl"
  "VKev/Unity-URP-Shaders-Code|Assets/Shaders/Object_Shader/Toon_Shader/URP_Toon.shader"
  "VKev/Unity-URP-Shaders-Code|Assets/Shaders/Object_Shader/Toon_Shader/Toon_ForwardLit_Pass.hlsl"
  "VKev/Unity-URP-Shaders-Code|Assets/Shaders/Object_Shader/Toon_Shader/Toon_ShadowCaster_Pass.hlsl"
  "Kink3d/kShading|Shaders/ToonLit.shader"
  "Kink3d/kShading|ShaderLibrary/ToonLitInput.hlsl"
  "Kink3d/kShading|ShaderLibrary/ToonLighting.hlsl"
  "Delt06/urp-toon-shader|Packages/com.deltation.toon-shader/Assets/DELTation/ToonShader/Shaders/ToonShaderLite.shader"
  "Delt06/urp-toon-shader|Packages/com.deltation.toon-shader/Assets/DELTation/ToonShader/Shaders/ToonShaderLiteInput.hlsl"
  "Delt06/urp-toon-shader|Packages/com.deltation.toon-shader/Assets/DELTation/ToonShader/Shaders/ToonShaderLiteForwardPass.hlsl"
  "Delt06/urp-toon-shader|Packages/com.deltation.toon-shader/Assets/DELTation/ToonShader/Shaders/ToonShaderShadowCasterPass.hlsl"
  "Delt06/urp-toon-shader|Packages/com.deltation.toon-shader/Assets/DELTation/ToonShader/Shaders/ToonShaderDepthOnlyPass.hlsl"
  "Delt06/urp-toon-shader|Packages/com.deltation.toon-shader/Assets/DELTation/ToonShader/Shaders/ToonShaderDepthNormalsPass.hlsl"
  "Delt06/urp-toon-shader|Packages/com.deltation.toon-shader/Assets/DELTation/ToonShader/Shaders/ToonShaderUtils.hlsl"
  "Delt06/urp-toon-shader|Packages/com.deltation.toon-shader/Assets/DELTation/ToonShader/Shaders/ToonShaderShadowCasterPass_AppData.hlsl"
  "Delt06/urp-toon-shader|Packages/com.deltation.toon-shader/Assets/DELTation/ToonShader/Shaders/ToonShaderUtilsV2f.hlsl"
  "Delt06/urp-toon-shader|Packages/com.deltation.toon-shader/Assets/DELTation/ToonShader/Shaders/ToonShaderDepthOnlyPass_AppData.hlsl"
  "Delt06/urp-toon-shader|Packages/com.deltation.toon-shader/Assets/DELTation/ToonShader/Shaders/ToonShaderDepthNormalsPass_AppData.hlsl"
  "ChiliMilk/URP_Toon|Assets/ChiliMilkToonShader/Shader/Toon.shader"
  "ChiliMilk/URP_Toon|Assets/ChiliMilkToonShader/Include/ToonInput.hlsl"
  "ChiliMilk/URP_Toon|Assets/ChiliMilkToonShader/Include/ToonHairShadowMaskPass.hlsl"
  "ChiliMilk/URP_Toon|Assets/ChiliMilkToonShader/Include/ToonFunction.hlsl"
  "ChiliMilk/URP_Toon|Assets/ChiliMilkToonShader/Include/ToonOutlinePass.hlsl"
  "ChiliMilk/URP_Toon|Assets/ChiliMilkToonShader/Include/ToonLighting.hlsl"
  "ChiliMilk/URP_Toon|Assets/ChiliMilkToonShader/Include/ToonForwardPass.hlsl"
  "ChiliMilk/URP_Toon|Assets/ChiliMilkToonShader/Include/ToonMetaPass.hlsl"
  "Delt06/urp-toon-shader|Packages/com.deltation.toon-shader/Assets/DELTation/ToonShader/Shaders/InvertedHullOutline.shader"
  "wj-bj/Unity-Tutorial-ShaderGraph|Unity-Tutorial-ShaderGraph/Assets/Samples/Lighting/Shaders/ToonOutline.shader"
  "decentraland/unity-renderer|unity-renderer/Assets/Rendering/Shaders/ToonBasicOutline.shader"
  "wj-bj/Unity-Tutorial-ShaderGraph|Unity-Tutorial-ShaderGraph/Assets/Test/testAutodest.shader"
  "decentraland/unity-renderer|unity-renderer/Assets/Rendering/Shaders/Toon/Compiled/ToonShaderCompiled.shader"
  "decentraland/unity-renderer|unity-renderer/Assets/Rendering/Shaders/Triplanar/Triplanar.shader"
  "Cyanilux/URP_GrassGeometryShader|GrassGeometry/GeoGrass.shader"
  "Cyanilux/URP_GrassGeometryShader|GrassGeometry/Grass.hlsl"
  "Cyanilux/URP_GrassGeometryShader|GrassGeometry/Tessellation.hlsl"
  "ColinLeung-NiloCat/UnityURPUnlitScreenSpaceDecalShader|URP_NiloCatExtension_ScreenSpaceDecal_Unlit.shader"
)

# The commands (verify, list, from-mirrors): shared by every corpus folder.
source "$HERE/../fetch_corpus.sh" "$@"
