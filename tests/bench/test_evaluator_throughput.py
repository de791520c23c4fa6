"""benchmarks/evaluator_throughput.py runs (CI checks that a benchmark runs, never its times),
prints a row per term with the numpy float32 comparison, and refuses to compare with a numpy
form that is not the GLSL's formula (control: a wrong form is caught before any timing)."""

from __future__ import annotations

import importlib.util
from pathlib import Path

import numpy as np
import pytest

SCRIPT = Path(__file__).resolve().parents[2] / "benchmarks" / "evaluator_throughput.py"


def _script():
    spec = importlib.util.spec_from_file_location("evaluator_throughput", SCRIPT)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_the_benchmark_prints_each_term_beside_numpy(capsys):
    script = _script()
    assert script.main(["--samples", "5000", "--repeats", "1"]) == 0
    rows = {line.split()[0]: line.split() for line in capsys.readouterr().out.splitlines()[2:]}
    assert set(rows) == set(script.TERMS)
    for cells in rows.values():
        assert len(cells) == 7 and all(float(c) > 0 for c in cells[1:])


def test_a_numpy_form_that_is_not_the_glsl_formula_is_refused(monkeypatch):
    script = _script()
    monkeypatch.setitem(script.NUMPY, "pbr_D_GGX", lambda NdotH, alpha: np.float32(1.01) * script._numpy_d_ggx(NdotH, alpha))
    with pytest.raises(SystemExit, match="pbr_D_GGX: the numpy form is not the GLSL's formula"):
        script.main(["--samples", "5000", "--repeats", "1"])
