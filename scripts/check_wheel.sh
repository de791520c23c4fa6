#!/usr/bin/env bash
# The release check a new user would do, run by .ci/run after `make test`:
#   1. build the sdist, then the wheel FROM the sdist (python -m build), so a file missing
#      from the sdist fails the wheel;
#   2. install only the wheel into a fresh virtualenv outside the checkout; `pip check`;
#   3. as that user, in an empty folder: pbrlab --version, pbrlab eval (GLSL and HLSL),
#      pbrlab render of a scene the wheel ships, pbrlab demo (no goldens in the wheel: it renders,
#      says so once and exits 0), and an external pytest project using the
#      golden fixture (a missing golden fails, --update-goldens writes it, the rerun passes).
# Needs the package index (or pip's cache) for the wheel's dependencies. About 1 minute
# with a warm pip cache.
set -euo pipefail
cd "$(dirname "$0")/.."
repo=$(pwd)
work=$(mktemp -d "${TMPDIR:-/tmp}/pbrlab-wheel-check.XXXXXX")
trap 'rm -rf "$work"' EXIT
say() { echo "check_wheel: $*"; }

say "building the sdist and, from it, the wheel"
.venv/bin/python -m build -q --outdir "$work/dist" . >/dev/null
wheel=$(ls "$work"/dist/pbrlab-*.whl)
sdist=$(ls "$work"/dist/pbrlab-*.tar.gz)
tar -tzf "$sdist" | sed 's|^[^/]*/||' > "$work/sdist.txt"
for name in glsl/pbr/pbr.glsl hlsl_ports/pbr/pbr.hlsl wgsl/pbrlab.wgsl scenes/example.json harness/pbrlab/commands/cli.py \
            tests/conftest.py goldens/chart_f0.exr docs/pyrender_vs_pbrlab.png docs/index.md mkdocs.yml \
            scripts/mkdocs_hooks.py scripts/mkdocs_cli_reference.py scripts/mkdocs_goldens.py docs/api/index.md \
            LICENSE requirements.txt Makefile; do
  grep -qx "$name" "$work/sdist.txt" || { say "the sdist lacks $name"; exit 1; }
done
"$repo/.venv/bin/python" -c 'import sys, zipfile; print("\n".join(zipfile.ZipFile(sys.argv[1]).namelist()))' "$wheel" > "$work/wheel.txt"
for name in pbrlab/data/glsl/pbr/pbr.glsl pbrlab/data/hlsl_ports/pbr/pbr.hlsl pbrlab/data/wgsl/pbrlab.wgsl pbrlab/data/scenes/example.json; do
  grep -qx "$name" "$work/wheel.txt" || { say "the wheel lacks $name"; exit 1; }
done

say "installing $(basename "$wheel") into a fresh virtualenv"
python3 -m venv "$work/venv"
"$work/venv/bin/python" -m pip install -q --upgrade pip
"$work/venv/bin/python" -m pip install -q "$wheel" "pytest>=9.2.0"
"$work/venv/bin/python" -m pip check

mkdir "$work/user"
cd "$work/user"  # outside the checkout: nothing of the repository is importable from here
export PATH="$work/venv/bin:$PATH"
unset PBRLAB_GLSL_ROOT PBRLAB_HLSL_ROOT PBRLAB_WGSL_ROOT PBRLAB_SCENES_ROOT PYTHONPATH
pbrlab --version | tee version.txt
if grep -q "$repo" version.txt; then say "the wheel found shaders in the checkout"; exit 1; fi
grep -q "(package data)" version.txt
pbrlab eval 'pbr_D_GGX(NdotH, alpha)' --var NdotH=0:1:3 --var alpha=0.5
pbrlab eval --language hlsl 'pbr_D_GGX(NdotH, alpha)' --var NdotH=0:1:3 --var alpha=0.5
scenes=$(python -c 'from pbrlab.foundation.locations import locate; print(locate("scenes"))')
pbrlab render "$scenes/example.json" -o example.png --hdr example.exr --size 64x48
test -s example.png && test -s example.exr

say "pbrlab demo from the wheel (it ships no goldens: it renders and says so, exit 0)"
pbrlab demo --out demo | tee demo.log
test "$(grep -c "no golden to compare" demo.log)" = 1 || { say "the demo did not say once that it has no goldens"; exit 1; }
test -s demo/index.html && test -s demo/lit_scene_high_sheet.png && test -s demo/chart_metallic_environment.exr

say "an external pytest project using the golden fixture"
mkdir project && cd project
cp "$repo/scripts/wheel_check/test_external_golden.py" .
printf '[pytest]\naddopts = -p no:cacheprovider\n' > pytest.ini
if python -m pytest -q > missing.log 2>&1; then
  cat missing.log; say "a missing golden did not fail"; exit 1
fi
grep -q "no golden" missing.log || grep -qi "missing" missing.log || { cat missing.log; say "the missing-golden failure does not say so"; exit 1; }
python -m pytest -q --update-goldens
test -f goldens/example_scene.exr
python -m pytest -q
say "ok: the wheel installs, renders and tests outside the checkout"
