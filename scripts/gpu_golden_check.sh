#!/usr/bin/env bash
# Renders every golden scene on the current GL (e.g. NVIDIA's EGL on a GPU machine), runs the
# golden tests there, and times frames; everything lands in the folder given ($1).
#   PBRLAB_TOLERANCE_PROFILE=gpu bash scripts/gpu_golden_check.sh OUT
# pbrlab and its Python dependencies must be importable (PYTHONPATH=harness works).
set -uo pipefail
out=${1:?usage: gpu_golden_check.sh OUT}
mkdir -p "$out/renders"
python3 - <<'PY' | tee "$out/context.json"
import json
from pbrlab.gpu import gl
print(json.dumps(gl.context_info(gl.shared_context())))
PY
python3 -m pbrlab.checking.golden_scenes "$out/renders/glsl" >/dev/null
python3 -m pbrlab.checking.golden_scenes --language hlsl "$out/renders/hlsl" >/dev/null
for language in glsl hlsl; do
  tar -C "$out/renders" -czf "$out/renders_$language.tar.gz" "$language"
done
rm -rf "$out/renders"
# The plugin comes from pbrlab's pytest11 entry point when pbrlab is installed; name it otherwise.
plugin=$(python3 -c 'import importlib.metadata as m; print("" if any(e.name == "pbrlab" for e in m.entry_points(group="pytest11")) else "-p pbrlab.checking.pytest_plugin")')
python3 -m pytest $plugin -p no:cacheprovider -q -n 8 \
    tests/render/test_chart_goldens.py tests/render/test_lit_scene_tiers.py \
    tests/render/test_torture_chart.py tests/gpu/hlsl/test_scene_renders.py \
    --pbrlab-output "$out/golden-failures" > "$out/golden_tests.txt" 2>&1
tail -3 "$out/golden_tests.txt"
tar -C "$out" -czf "$out/golden-failures.tar.gz" golden-failures 2>/dev/null && rm -rf "$out/golden-failures"
python3 benchmarks/frame_time.py --size 1024 chart_metallic lit_scene_high torture_chart | tee "$out/frame_time.txt"
python3 benchmarks/evaluator_throughput.py --samples 1000000 --repeats 5 | tee "$out/evaluator.txt"
