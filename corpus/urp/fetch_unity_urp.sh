#!/usr/bin/env bash
# =====================================================================================
#  UNITY'S OWN URP SHADERS ARE UNDER THE UNITY COMPANION LICENSE. THEY MUST NEVER BE
#  COMMITTED TO THIS REPOSITORY. This script fetches them for local measurement only
#  (which URP features our front end still lacks), into a git-ignored folder outside
#  corpus/unity/ (default: <repo>/out/unity-urp-graphics/; out/ is in .gitignore).
# =====================================================================================
#
# Not run by anything in this project, and not needed by the tests: a documented recipe.
# It needs network access to github.com and git >= 2.27 (sparse checkout, partial clone).
#
# What it fetches, from https://github.com/Unity-Technologies/Graphics (branch $REF,
# default master), with only these folders checked out:
#   <pkg>/com.unity.render-pipelines.universal/Shaders/        Lit, SimpleLit, Unlit, BakedLit,
#                                                              ComplexLit .shader and their
#                                                              *Input.hlsl / *Pass.hlsl
#   <pkg>/com.unity.render-pipelines.universal/ShaderLibrary/  Core.hlsl, Lighting.hlsl, ...
#   <pkg>/com.unity.render-pipelines.core/ShaderLibrary/       Common.hlsl, ...
#   <pkg>/com.unity.render-pipelines.universal/LICENSE.md      the Unity Companion License
# where <pkg> is "Packages/" on master (Unity 6 and later) and "" (the repository root) on
# older branches such as 2022.3/staging; the script finds which.
#
# The five shaders the corpus is measured against:
#   Shaders/Lit.shader  Shaders/SimpleLit.shader  Shaders/Unlit.shader
#   Shaders/BakedLit.shader  Shaders/ComplexLit.shader
#
# Keep the destination out of corpus/unity/: pbrlab.checking.unity_corpus and
# tests/importers/unity/test_corpus.py take every *.shader under corpus/unity/.
#
# Usage: ./fetch_unity_urp.sh [DEST]        (REF=2022.3/staging ./fetch_unity_urp.sh to pick a branch)
set -euo pipefail
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
ROOT="$(cd "$HERE/../../.." && pwd)"
DEST="${1:-$ROOT/out/unity-urp-graphics}"
REF="${REF:-master}"
URL="https://github.com/Unity-Technologies/Graphics.git"
SHADERS=(Lit SimpleLit Unlit BakedLit ComplexLit)

case "$DEST" in
  "$ROOT"/corpus/*) echo "refusing: $DEST is under corpus/ (Unity Companion License files must stay out of it)" >&2; exit 2 ;;
esac
if [[ "$DEST" == "$ROOT"/* ]] && ! git -C "$ROOT" check-ignore -q "$DEST"; then
  echo "refusing: $DEST is inside the repository but not git-ignored" >&2; exit 2
fi

if [[ ! -d "$DEST/.git" ]]; then
  git clone --filter=blob:none --no-checkout --depth 1 --branch "$REF" "$URL" "$DEST"
fi
cd "$DEST"
if git cat-file -e "HEAD:Packages/com.unity.render-pipelines.universal/Shaders/Lit.shader" 2>/dev/null; then
  PKG="Packages/"
else
  PKG=""
fi
git sparse-checkout init --cone
git sparse-checkout set \
  "${PKG}com.unity.render-pipelines.universal/Shaders" \
  "${PKG}com.unity.render-pipelines.universal/ShaderLibrary" \
  "${PKG}com.unity.render-pipelines.core/ShaderLibrary"
git checkout --quiet
# the package licence (a file at the package root, outside the cone)
git show "HEAD:${PKG}com.unity.render-pipelines.universal/LICENSE.md" > UNITY_COMPANION_LICENSE.md 2>/dev/null || true

{
  echo "Unity-Technologies/Graphics $REF @ $(git rev-parse HEAD)"
  echo "Unity Companion License: never commit these files. Measurement only."
  for s in "${SHADERS[@]}"; do
    p="${PKG}com.unity.render-pipelines.universal/Shaders/$s.shader"
    if [[ -f "$p" ]]; then echo "$DEST/$p"; else echo "MISSING $p" ; fi
  done
} | tee SOURCE.txt
