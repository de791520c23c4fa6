"""Fixtures and the measured-error report of the shading-library tests (helpers: library_helpers.py).

Every GPU-vs-reference comparison goes through ``assert_close``: it checks
``|gpu - ref| <= atol + rtol * |ref|`` elementwise (units: those of the function's value),
requires the GPU value to be finite wherever the reference is, and records the measured
worst-case absolute and relative errors, printed in a table at the end of the run
(``pytest tests/library -rA`` or plain: see "pbrlab library: measured errors").
"""

from __future__ import annotations

import pytest

from library_helpers import MEASURED, seeded_rng


def pytest_terminal_summary(terminalreporter):
    if not MEASURED:
        return
    terminalreporter.section("pbrlab library: measured errors (GPU float32 vs float64 reference)")
    for label in sorted(MEASURED):
        m = MEASURED[label]
        terminalreporter.write_line(f"{label:58s} max abs {m.max_abs:9.3g}  max rel {m.max_rel:9.3g}  ({m.where})")


@pytest.fixture
def rng(request):
    """A generator seeded from the test's own name (reproducible whatever else runs)."""
    return seeded_rng(request.node.nodeid)
