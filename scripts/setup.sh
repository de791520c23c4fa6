#!/usr/bin/env bash
# Installs what pbrlab needs on a Debian/Ubuntu machine, then exits 0.
#   1. System packages (Mesa EGL + OSMesa + llvmpipe, glslang, spirv-cross, binutils'
#      objdump for pbrlab.checking.codescan, the Vulkan loader and Mesa's RADV for the AMD GPU
#      instruction counts of pbrlab.gpu.isa, python3-venv):
#      installed with apt-get when run as root, otherwise the exact command is printed and
#      the script stops with exit 1.
#      A C++ compiler (g++) for the meshoptimizer bindings, published as source only.
#      Chromium and node/npm (Debian's chromium, nodejs; npm unless node brings it) for the glTF Sample Viewer
#      comparison (pbrlab.checking.sample_viewer) are among them.
#   2. A virtualenv .venv with requirements.txt, pyrender (--no-deps, see docs/getting-started.md) and
#      pbrlab itself in editable mode. Skipped when .venv is up to date with the
#      requirements (a stamp records their hash).
#   3. npm ci in tools/sample_viewer (the Khronos glTF Sample Renderer and playwright-core),
#      tools/gltf_validator (the Khronos glTF Validator) and tools/threejs (three.js and
#      playwright-core, for examples/threejs) and tools/babylonjs (Babylon.js and playwright-core, for
#      examples/babylonjs and tests/library/test_engine_preprocessors.py), each pinned by its package-lock.json. Skipped where node_modules matches the lock file.
#      (tools/chromium/launch.mjs, the Chromium start-up both browser tools import, needs no npm package.)
#   4. naga-cli (the shader translator of wgpu, Bevy and Firefox's WebGPU; crates.io, pinned) into tools/naga,
#      with `cargo install --locked`: examples/wgpu and the shipped WGSL (wgsl/pbrlab.wgsl, docs/wgsl.md)
#      are made by it. Compiles for about 2 minutes on 2 cores, once per machine (kept in ~/.cache/pbrlab);
#      skipped when tools/naga holds that version.
#      Needs cargo (rustup.rs, or Debian's cargo if it is recent enough); stops with a message where it is missing.
set -euo pipefail
cd "$(dirname "$0")/.."

# Debian package -> a file that proves it is installed (works without dpkg too).
declare -A need=(
  [libegl1]=/usr/lib/x86_64-linux-gnu/libEGL.so.1
  [libegl-mesa0]=/usr/lib/x86_64-linux-gnu/libEGL_mesa.so.0
  [libgl1-mesa-dri]=/usr/lib/x86_64-linux-gnu/dri/swrast_dri.so
  [libosmesa6]=/usr/lib/x86_64-linux-gnu/libOSMesa.so.8
  [glslang-tools]=/usr/bin/glslangValidator
  [spirv-cross]=/usr/bin/spirv-cross
  [binutils]=/usr/bin/objdump
  [libvulkan1]=/usr/lib/x86_64-linux-gnu/libvulkan.so.1
  [mesa-vulkan-drivers]=/usr/share/vulkan/icd.d/radeon_icd.x86_64.json
  [chromium]=/usr/bin/chromium
  [nodejs]=/usr/bin/node
  [g++]=/usr/bin/g++  # meshoptimizer (requirements.txt) is an sdist: its C++ codecs compile at install
)
missing=()
for pkg in "${!need[@]}"; do
  if command -v dpkg-query >/dev/null 2>&1; then
    dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed" || missing+=("$pkg")
  else
    [ -e "${need[$pkg]}" ] || missing+=("$pkg")
  fi
done
python3 -c 'import venv, ensurepip' 2>/dev/null || missing+=(python3-venv)
command -v npm >/dev/null 2>&1 || missing+=(npm)  # Debian's nodejs ships without it

if [ ${#missing[@]} -gt 0 ]; then
  IFS=$'\n' missing=($(sort <<<"${missing[*]}")); unset IFS
  if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then
    echo "setup: installing system packages: ${missing[*]}"
    export DEBIAN_FRONTEND=noninteractive
    apt-get update -qq
    apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
  else
    echo "setup: pbrlab needs these system packages, which are not installed:" >&2
    echo "    sudo apt-get install -y ${missing[*]}" >&2
    echo "Run that line (or run this script as root), then run the command again." >&2
    exit 1
  fi
fi

# The npm tools, each from its lock file: the Khronos Sample Renderer (tools/sample_viewer)
# the Khronos glTF Validator (tools/gltf_validator), three.js for examples/threejs (tools/threejs) and
# three.js as the fidelity benchmark's peer (tools/threejs_gltf) and Babylon.js (tools/babylonjs).
for tool in tools/sample_viewer tools/gltf_validator tools/threejs tools/threejs_gltf tools/babylonjs; do
  tool_stamp=$tool/node_modules/.pbrlab-installed
  tool_want=$(sha256sum < $tool/package-lock.json | cut -c1-16)
  if ! { [ -f "$tool_stamp" ] && [ "$(cat "$tool_stamp")" = "$tool_want" ]; }; then
    echo "setup: npm ci in $tool"
    (cd $tool && npm ci --no-audit --no-fund --loglevel=error >/dev/null)
    echo "$tool_want" > "$tool_stamp"
  fi
done

# naga-cli, pinned (docs/wgsl.md): the version's stamp beside the binary. Built once per machine
# into a cache outside the checkout ($PBRLAB_TOOL_CACHE, default ~/.cache/pbrlab), then copied into
# tools/naga, so a fresh clone (CI's) costs a copy, not a 2-minute compile.
NAGA_VERSION=30.0.1
naga_stamp=tools/naga/.pbrlab-installed
if ! { [ -x tools/naga/bin/naga ] && [ "$(cat "$naga_stamp" 2>/dev/null)" = "$NAGA_VERSION" ]; }; then
  naga_cache=${PBRLAB_TOOL_CACHE:-$HOME/.cache/pbrlab}/naga-cli-$NAGA_VERSION
  if ! [ -x "$naga_cache/bin/naga" ]; then
    cargo=$(command -v cargo || true)
    [ -z "$cargo" ] && [ -x "$HOME/.cargo/bin/cargo" ] && cargo=$HOME/.cargo/bin/cargo  # rustup's, off PATH
    if [ -z "$cargo" ]; then
      echo "setup: naga-cli $NAGA_VERSION needs cargo (Rust), which is not on PATH: install it (https://rustup.rs) and run again." >&2
      exit 1
    fi
    echo "setup: cargo install naga-cli $NAGA_VERSION (about 2 minutes, once per machine)"
    "$cargo" install --quiet --locked naga-cli --version "$NAGA_VERSION" --root "$naga_cache.part"
    rm -rf "$naga_cache" && mv "$naga_cache.part" "$naga_cache"
  fi
  mkdir -p tools/naga/bin
  cp "$naga_cache/bin/naga" tools/naga/bin/naga
  echo "$NAGA_VERSION" > "$naga_stamp"
fi

stamp=.venv/.pbrlab-installed
want=$(cat requirements.txt pyproject.toml | sha256sum | cut -c1-16)
if [ -f "$stamp" ] && [ "$(cat "$stamp")" = "$want" ] && [ -x .venv/bin/python ]; then
  exit 0
fi
echo "setup: creating the virtualenv .venv"
python3 -m venv .venv
.venv/bin/python -m pip install -q --upgrade pip
.venv/bin/python -m pip install -q -r requirements.txt
# pyrender 0.1.45 pins PyOpenGL==3.1.0 (broken EGL/OSMesa here); its other dependencies
# are in requirements.txt with PyOpenGL 3.1.10, so it is installed without its pin.
.venv/bin/python -m pip install -q --no-deps pyrender==0.1.45
.venv/bin/python -m pip install -q --no-deps -e .
echo "$want" > "$stamp"
echo "setup: .venv is ready"
