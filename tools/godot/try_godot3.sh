#!/usr/bin/env bash
# How far Godot's shading language takes the library (issue 36): Godot 3.2.3, the only Godot
# the package registries here offer (Debian's godot3; no Godot 4 build), run under Xvfb on
# llvmpipe (GLES3). Godot's language has no preprocessor, so the amalgamated library is first
# preprocessed by glslang (-E: every macro expanded, every conditional resolved, the selectors'
# defaults chosen), then handed to a spatial shader whose fragment() calls one function.
#   1. a control: a shader of one line draws the sphere (proves the set-up renders);
#   2. the library: prints Godot's first SHADER ERROR.
# Needs: apt-get install godot3 xvfb (not installed by scripts/setup.sh: nothing in CI uses it).
# Measured 2026-12-06 with Godot 3.2.3: the control draws; the library stops at its first
# overloaded function, "SHADER ERROR: (null): Redefinition of 'pbr_saturate'" (Godot 3 has no
# overloading); past that, a struct declaration alone (tried in a shader of three lines) gives
# "Expected constant, function, uniform or varying" (Godot 3 has no structs; the library's
# SurfaceOutputStandard, UnityGI and layer records are 13 structs).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
repo=$(cd "$here/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp -r "$here/project" "$work/project"
godot() {  # $1: shader file; prints Godot's SHADER ERROR lines, writes $work/frame.png
  cp "$1" "$work/project/shader.shader"
  PBRLAB_GODOT_OUT="$work/frame.png" timeout 120 xvfb-run -a -s "-screen 0 320x240x24" \
    godot3 --path "$work/project" --resolution 128x128 > "$work/godot.log" 2>&1 || true
  grep "SHADER ERROR" "$work/godot.log" || true
}

printf 'shader_type spatial;\nvoid fragment() { ALBEDO = vec3(1.0, 0.2, 0.1); }\n' > "$work/control.shader"
godot "$work/control.shader"
[ -s "$work/frame.png" ] && echo "control: Godot drew the one-line shader" || { echo "control: no frame (see $work/godot.log)"; exit 1; }

"$repo/.venv/bin/pbrlab" amalgamate "$repo/examples/threejs/library_entry.glsl" -o "$work/library.glsl" >/dev/null
{ printf '#version 330\n'; cat "$work/library.glsl"; printf '\nvoid main() {}\n'; } > "$work/library_main.glsl"
glslangValidator -E -S frag "$work/library_main.glsl" | grep -v '^#' | grep -v '^[[:space:]]*$' \
  | grep -v '^void main() {}$' > "$work/library_expanded.glsl"
{ echo "shader_type spatial;"; cat "$work/library_expanded.glsl"
  echo "void fragment() { ALBEDO = vec3(pbr_saturate(0.5)); }"; } > "$work/library.shader"
echo "the library ($(wc -l < "$work/library.shader") lines after preprocessing):"
godot "$work/library.shader"
