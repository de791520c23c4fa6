"""The bench's check on its own instruction counts (issue 16: "make the x86 counts trustworthy").

callgrind counts instructions, so a count is exact once the draw it measures is: every kernel
is counted in more than one pass (``measure.COUNT_PASSES``, in a different order each pass),
and the figures of one kernel must agree. A count below zero, or two counts of one kernel
further apart than ``TOLERANCE``, means that something other than the kernel landed in a
measured draw (a garbage collection, a state change, a recompile); the bench then fails
instead of publishing the figure.
"""

from __future__ import annotations

from ..foundation.errors import InconsistentCountError

# Largest relative difference allowed between counts of one kernel: (max - min) / max |count|.
# Issue 16 asks for 1 %. Measured with the mechanism of measure.measure_instructions at
# 128x128: every variant's figures over 2 passes and 3 groupings of the kernels into worker
# processes agree within 7e-4 (most to the last digit); before it, at 32x32, a garbage
# collection in one draw moved a family's figures by 25 per evaluation.
TOLERANCE = 0.01
MIN_COUNTS = 2  # a kernel counted once cannot be checked


def count_problems(counts: dict, tolerance: float = TOLERANCE) -> list[str]:
    """One line per kernel whose counts (``{kernel: [count per pass]}``) cannot be trusted:
    fewer than MIN_COUNTS counts, a negative count, or a relative spread above ``tolerance``."""
    problems = []
    for name, values in counts.items():
        values = [float(v) for v in values]
        shown = ", ".join(f"{v:.5g}" for v in values)
        if len(values) < MIN_COUNTS:
            problems.append(f"{name}: counted {len(values)} time(s), the check needs {MIN_COUNTS} ({shown})")
            continue
        if min(values) < 0:
            problems.append(f"{name}: negative count ({shown})")
            continue
        scale = max(abs(v) for v in values)
        spread = (max(values) - min(values)) / scale if scale > 0 else 0.0
        if spread > tolerance:
            problems.append(f"{name}: counts disagree by {spread:.2%} (more than {tolerance:.0%}): {shown}")
    return problems


def check_counts(counts: dict, tolerance: float = TOLERANCE, unit: str = "") -> None:
    """Raise InconsistentCountError listing every problem of ``count_problems``."""
    problems = count_problems(counts, tolerance)
    if problems:
        raise InconsistentCountError(
            f"pbrlab bench: {len(problems)} instruction count(s) cannot be trusted "
            f"(each kernel is counted {MIN_COUNTS} or more times; counts{unit} must be >= 0 and "
            f"agree within {tolerance:.0%}):\n  " + "\n  ".join(problems)
            + "\nA count of a draw must not depend on what ran before it in the worker; "
              "see pbrlab.bench.measure.measure_instructions for what the mechanism excludes.")


def check_collected(draws: dict, functions) -> None:
    """Raise InconsistentCountError when a counted draw (``{(kernel, trips, pass): Ir}``)
    has no instructions: callgrind found none of ``functions`` (collection is on only inside
    them), e.g. a moderngl build without their symbols."""
    empty = sorted({key[0] for key, ir in draws.items() if ir <= 0})
    if empty:
        raise InconsistentCountError(
            f"pbrlab bench: callgrind collected no instructions inside {', '.join(functions)} "
            f"for {', '.join(empty)}: this moderngl build does not name them (stripped, or renamed "
            "since moderngl 5.13), so the bench cannot count its draws.")
