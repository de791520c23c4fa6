"""benchmarks/environment_read_cost.py runs, and its variants are what they say: the horizon
occlusion is compiled into a normal-mapped material's program only when render.horizon_occlusion
is on, the dominant read costs instructions over the mirror read it replaces, the production
program is smaller than the checking one (its NaN/Inf test), and DamagedHelmet's program
without the tangent fallback smaller than with it (the fallback on every mesh: the control)."""

import importlib.util
from pathlib import Path

import pytest

from pbrlab.bench import gpu

SCRIPT = Path(__file__).resolve().parents[2] / "benchmarks" / "environment_read_cost.py"


def test_environment_read_cost_variants():
    if (why := gpu.unavailable_reason()) is not None:
        pytest.fail(f"RADV null device unavailable (scripts/setup.sh installs it): {why}")
    spec = importlib.util.spec_from_file_location("environment_read_cost", SCRIPT)
    bench = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(bench)
    figures = bench.figures("DamagedHelmet", families=("rdna3",))
    shipped = figures["as shipped"]["rdna3"][0]
    assert figures["horizon occlusion off"]["rdna3"][0] < shipped
    assert figures["mirror read"]["rdna3"][0] < shipped
    assert figures["production"]["rdna3"][0] < shipped
    assert shipped < figures["fallback on every mesh"]["rdna3"][0]
