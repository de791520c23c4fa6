#!/usr/bin/env bash
# The fidelity benchmark's path tracer: Blender's Cycles from PyPI's bpy, in .venv-bpy
# (pbrlab.checking.fidelity.renderers looks there, or at $PBRLAB_BPY_PYTHON). Needed only to
# render new Cycles references (`pbrlab fidelity --render cycles ...`); CI scores against the
# committed ones. bpy 5.0.1 needs CPython 3.11 (python3.11 on PATH) and numpy 1.26, which
# pbrlab's own environment (numpy 2.4) cannot share.
set -euo pipefail
cd "$(dirname "$0")/.."
python=${PYTHON311:-python3.11}
if ! command -v "$python" >/dev/null 2>&1; then
  echo "setup_cycles: $python is not on PATH (bpy 5.0.1 wheels are for CPython 3.11; set PYTHON311)" >&2
  exit 2
fi
[ -x .venv-bpy/bin/python ] || "$python" -m venv .venv-bpy
.venv-bpy/bin/pip install -q -r tools/cycles/requirements.txt
.venv-bpy/bin/python -c "import bpy; print('setup_cycles: Blender', bpy.app.version_string, 'with Cycles in .venv-bpy')"
