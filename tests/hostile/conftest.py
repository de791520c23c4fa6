"""The hostile suite's census: each adversarial case is counted by outcome, and the counts
are printed at the end of the run (the table issue 14 asks for). A case that ends in a
traceback, a lost or changed file, or a silently wrong result fails its test; the census
only counts the outcomes that are allowed: "refused cleanly" (PbrlabError naming the
problem, files intact) and "handled" (a correct result)."""

from collections import Counter

import pytest

CENSUS: Counter = Counter()


@pytest.fixture
def census():
    return CENSUS


def pytest_terminal_summary(terminalreporter):
    if CENSUS:
        terminalreporter.write_sep("-", "hostile census (cases by outcome)")
        for (suite, outcome), count in sorted(CENSUS.items()):
            terminalreporter.write_line(f"{suite:<28} {outcome:<16} {count}")
