"""The HLSL-port tests: the measured GLSL-vs-HLSL agreement table (helpers: hlsl_helpers.py).

``test_function_agreement.py`` records, per library function signature and configuration,
the worst distance between the GLSL function and its HLSL twin on the same inputs, printed
at the end of a run without xdist (``pytest tests/gpu/hlsl -p no:xdist``): "pbrlab HLSL ports".
"""

from __future__ import annotations

import pytest

from hlsl_helpers import AGREEMENT


def pytest_terminal_summary(terminalreporter):
    if not AGREEMENT:
        return
    terminalreporter.section("pbrlab HLSL ports: GLSL vs HLSL on the same inputs (float32 ulps)")
    for label in sorted(AGREEMENT):
        ulps, rel, count = AGREEMENT[label]
        terminalreporter.write_line(f"{label[:100]:100s} max {ulps:3d} ulp  max rel {rel:8.2g}  ({count} values)")


@pytest.fixture(scope="session")
def hlsl_wrappers(tmp_path_factory):
    """tests/gpu/hlsl/wrappers ported to HLSL by pbrlab.gpu.port_hlsl (a directory for include_dirs)."""
    import agreement
    return agreement.hlsl_wrappers_dir(tmp_path_factory.mktemp("hlsl_wrappers"))
