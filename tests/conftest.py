# The pbrlab plugin itself (fixtures gl_context and golden, --update-goldens, the report
# header) is loaded through its pytest11 entry point; pytester runs it in the harness's
# own tests (tests/checking/test_plugin.py).
from pathlib import Path

import pytest

from slow_modules import SLOW_MODULES, TESTS

pytest_plugins = ["pytester"]


# make check: tests/slow_modules.py
def pytest_collection_modifyitems(config, items):
    for item in items:
        path = Path(item.path).resolve()
        if path.is_relative_to(TESTS) and path.relative_to(TESTS).as_posix() in SLOW_MODULES:
            item.add_marker(pytest.mark.slow)
