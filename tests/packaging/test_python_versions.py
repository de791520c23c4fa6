"""The wheel's Requires-Python is true of its dependencies (issue 36: it said >=3.10 while
numpy 2.4, the version its lower bound asks for, needs 3.11, so it failed to install on 3.10).

Offline: each dependency's own Requires-Python is read from the version installed here (the
pinned lock, requirements.txt, which the dependency lower bounds equal). Whether each claimed
version really installs and runs is scripts/check_wheel.sh's part (CI)."""

from __future__ import annotations

import importlib.metadata
import re
import subprocess
import sys
import tomllib
from pathlib import Path

from packaging.specifiers import SpecifierSet

ROOT = Path(__file__).resolve().parents[2]
PROJECT = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))["project"]
MINORS = [f"3.{minor}" for minor in range(6, 30)]


def claimed(requires_python: str) -> list[str]:
    spec = SpecifierSet(requires_python)
    return [version for version in MINORS if f"{version}.0" in spec]


def refusals(requires_python: str, requirements: list[str]) -> list[str]:
    """'numpy (>=3.11) refuses 3.10' for each claimed version a requirement's installed
    distribution does not admit."""
    found = []
    for requirement in requirements:
        name = re.match(r"[A-Za-z0-9_.-]+", requirement).group(0)
        theirs = importlib.metadata.metadata(name)["Requires-Python"]
        if theirs:
            found += [f"{name} ({theirs}) refuses {v}" for v in claimed(requires_python)
                      if f"{v}.0" not in SpecifierSet(theirs)]
    return found


def test_every_claimed_python_is_admitted_by_every_dependency():
    requirements = PROJECT["dependencies"] + PROJECT["optional-dependencies"]["test"]
    assert claimed(PROJECT["requires-python"]), "Requires-Python admits no Python"
    assert not refusals(PROJECT["requires-python"], requirements)


def test_the_check_finds_the_claim_of_issue_36():
    """Control: the old claim, >=3.10, is refused by numpy 2.4 (and scipy 1.17)."""
    found = refusals(">=3.10", PROJECT["dependencies"])
    assert any(line.startswith("numpy") and line.endswith("refuses 3.10") for line in found), found


def test_the_claim_names_this_python_and_an_upper_bound():
    """The test suite runs on a claimed Python, and the claim stops where check_wheel's
    knowledge does (a version not checked is not admitted)."""
    assert f"{sys.version_info.major}.{sys.version_info.minor}" in claimed(PROJECT["requires-python"])
    assert claimed(PROJECT["requires-python"])[-1] != MINORS[-1]


def test_the_test_extra_brings_pytest():
    """README "Test your own shader": pip install "pbrlab-...whl[test]" gives pytest."""
    assert any(re.match(r"pytest\b(?!-)", r) for r in PROJECT["optional-dependencies"]["test"])


def test_python_dash_m_pbrlab_is_the_pbrlab_command():
    ran = subprocess.run([sys.executable, "-m", "pbrlab", "--version"], capture_output=True, text=True,
                         cwd=ROOT, timeout=120)
    assert ran.returncode == 0, ran.stderr
    assert ran.stdout.startswith("pbrlab ")
