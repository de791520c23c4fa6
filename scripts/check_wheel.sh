#!/usr/bin/env bash
# The release check a new user would do, run by .ci/run after `make test`:
#   1. build the sdist, then the wheel FROM the sdist (python -m build), so a file missing
#      from the sdist fails the wheel;
#   2. install only the wheel, with its test extra as the README says, into a fresh virtualenv
#      outside the checkout; `pip check`;
#   3. as that user, in an empty folder: pbrlab --version, python -m pbrlab --version, pbrlab eval
#      (GLSL and HLSL), pbrlab render of a scene the wheel ships and of a lone Unity .shader,
#      pbrlab tables, pbrlab demo (no goldens in the wheel: it renders, says so once and exits 0),
#      an external pytest project using the golden fixture (a missing golden fails,
#      --update-goldens writes it, the rerun passes), and the README's "Test your own shader"
#      project as pasted;
#   4. on every other Python the wheel's Requires-Python claims that this machine has (python3.X
#      on PATH, or pyenv's): a fresh virtualenv, the wheel with its test extra, pip check, the
#      smoke commands and the README's project; the Python just below the claim must be refused.
# Needs the package index (or pip's cache) for the wheel's dependencies. With a warm pip
# cache on 2 cores: 1 min 11 s at a load average of 1 to 2, 2 min under 5 (3.11 in full, 3.12
# and 3.13 smoke; 43 s before it checked other Pythons and the README's project); 3.12 and 3.13 run
# one after the other: side by side they took as long here (2 min 4 s against 2 min 0 s).
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

# install PYTHON VENV: the wheel with its test extra (pytest: README "Test your own shader")
install() {
  "$1" -m venv "$2"
  "$2/bin/python" -m pip install -q --upgrade pip
  "$2/bin/python" -m pip install -q "$wheel[test]"
  "$2/bin/python" -m pip check
}
# smoke VENV FOLDER: the commands a new user runs first, and the README's own-shader project as pasted
smoke() (
  mkdir -p "$2" && cd "$2"
  export PATH="$1/bin:$PATH"
  pbrlab --version | tee version.txt
  if grep -q "$repo" version.txt; then say "the wheel found shaders in the checkout"; exit 1; fi
  grep -q "(package data)" version.txt
  test "$(python -m pbrlab --version)" = "$(cat version.txt)" || { say "python -m pbrlab --version differs"; exit 1; }
  pbrlab eval 'pbr_D_GGX(NdotH, alpha)' --var NdotH=0:1:3 --var alpha=0.5
  scenes=$(python -c 'from pbrlab.foundation.locations import locate; print(locate("scenes"))')
  pbrlab render "$scenes/example.json" -o example.png --hdr example.exr --size 64x48
  test -s example.png && test -s example.exr
  pbrlab render "$scenes/unity_manual/standard_template.shader" -o lone_shader.png --size 64x64
  test -s lone_shader.png
  pbrlab tables --out tables -q
  test -s tables/pbrlab_dfg.exr && test -s tables/pbrlab_tables.glsl && test -s tables/pbrlab_tables.hlsl
  mkdir readme && "$repo/.venv/bin/python" "$repo/scripts/wheel_check/readme_project.py" readme
  (cd readme && bash -e run.sh > ../readme.log 2>&1) || { cat readme.log; say "the README's own-shader project failed"; exit 1; }
  test -f readme/goldens/rim_sphere.exr
)

say "installing $(basename "$wheel")[test] into a fresh virtualenv ($(python3 --version))"
install python3 "$work/venv"

mkdir "$work/user"
cd "$work/user"  # outside the checkout: nothing of the repository is importable from here
export PATH="$work/venv/bin:$PATH"
unset PBRLAB_GLSL_ROOT PBRLAB_HLSL_ROOT PBRLAB_WGSL_ROOT PBRLAB_SCENES_ROOT PYTHONPATH
smoke "$work/venv" "$work/user/smoke"
pbrlab eval --language hlsl 'pbr_D_GGX(NdotH, alpha)' --var NdotH=0:1:3 --var alpha=0.5

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
cd "$work/user"

# Every Python the wheel's Requires-Python claims, found on this machine (python3.X on PATH, or
# pyenv's newest 3.X.*); the first minor version below the claim must be refused by pip.
claims=$("$repo/.venv/bin/python" - "$wheel" <<'PY'
import sys, zipfile
from email.parser import Parser
from packaging.specifiers import SpecifierSet
wheel = zipfile.ZipFile(sys.argv[1])
meta = Parser().parsestr(wheel.read(next(n for n in wheel.namelist() if n.endswith(".dist-info/METADATA"))).decode())
spec = SpecifierSet(meta["Requires-Python"])
claimed = [f"3.{m}" for m in range(6, 30) if f"3.{m}.0" in spec]
print(" ".join(claimed), f"3.{int(claimed[0].split('.')[1]) - 1}")
PY
)
read -r -a claimed <<< "$claims"
below=${claimed[-1]}; unset 'claimed[-1]'
find_python() {  # a pyenv shim that is not enabled exits 127: each candidate must run as 3.X
  for candidate in $(command -v "python$1") $(ls -d "${PYENV_ROOT:-$HOME/.pyenv}/versions/$1".*/bin/python 2>/dev/null | sort -rV); do
    if [ "$("$candidate" -c 'import sys; print("%d.%d" % sys.version_info[:2])' 2>/dev/null)" = "$1" ]; then
      echo "$candidate"; return
    fi
  done
}
say "Requires-Python claims ${claimed[*]}; $below must be refused"
primary=$(python3 -c 'import sys; print("%d.%d" % sys.version_info[:2])')
checked=("$primary")
for version in "${claimed[@]}"; do
  [ "$version" = "$primary" ] && continue
  interpreter=$(find_python "$version")
  if [ -z "$interpreter" ]; then say "Python $version (claimed) is not on this machine: not checked"; continue; fi
  say "Python $version ($interpreter): install and smoke-run"
  install "$interpreter" "$work/venv$version"
  # set -e holds inside only outside an `||`: the status is taken with set +e around it
  set +e; (set -e; smoke "$work/venv$version" "$work/user/py$version") > "$work/user/py$version.log" 2>&1
  status=$?; set -e
  [ $status = 0 ] || { cat "$work/user/py$version.log"; say "Python $version: the smoke run failed"; exit 1; }
  checked+=("$version")
done
interpreter=$(find_python "$below")
if [ -n "$interpreter" ]; then
  "$interpreter" -m venv "$work/venv$below"
  if "$work/venv$below/bin/python" -m pip install -q --no-deps "$wheel" > "$work/below.log" 2>&1; then
    say "Python $below, below Requires-Python, installed the wheel"; exit 1
  fi
  grep -q "requires a different Python" "$work/below.log" \
    || { cat "$work/below.log"; say "Python $below: not refused for Requires-Python"; exit 1; }
  say "Python $below: refused by Requires-Python, as it should"
fi
say "ok: the wheel installs, renders and tests outside the checkout on Python ${checked[*]}"
