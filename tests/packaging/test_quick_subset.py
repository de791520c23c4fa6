"""`make check` (pytest -m "not slow"): the slow list names modules that exist, and the quick
subset keeps modules in every test folder, so it covers every layer (tests/README.md)."""

from __future__ import annotations

from pathlib import Path

from slow_modules import SLOW_MODULES, TESTS


def _test_modules(root: Path) -> list[str]:
    return sorted(p.relative_to(root).as_posix() for p in root.rglob("test_*.py"))


def folders_without_quick_tests(modules: list[str], slow: set[str]) -> list[str]:
    """The top-level test folders (layers) whose every module is slow."""
    folders = {m.split("/")[0] for m in modules if "/" in m}
    quick = {m.split("/")[0] for m in modules if "/" in m and m not in slow}
    return sorted(folders - quick)


def test_every_slow_module_exists():
    present = set(_test_modules(TESTS))
    assert not [m for m in SLOW_MODULES if m not in present], "tests/slow_modules.py names a missing file"


def test_the_quick_subset_covers_every_test_folder():
    assert folders_without_quick_tests(_test_modules(TESTS), set(SLOW_MODULES)) == []


def test_the_check_finds_a_folder_left_with_only_slow_modules():
    modules = ["render/test_a.py", "render/test_b.py", "maths/test_c.py"]
    assert folders_without_quick_tests(modules, {"render/test_a.py", "render/test_b.py"}) == ["render"]
    assert folders_without_quick_tests(modules, {"render/test_a.py"}) == []
