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



# The answers kept per process under a digest of texts or a file's state (session 46's per-pass
# cost work): what a test's replaced function would have computed differently.
_KEPT_ANSWERS = (("pbrlab.importers.unity.port", "_PORTED"),
                 ("pbrlab.importers.unity.user_definitions", "_TEXT_DEFINES"),
                 ("pbrlab.gpu.source_limits", "_SCANNED"),
                 ("pbrlab.gpu.hlsl", "_INCLUDED_FILES"),
                 ("pbrlab.gpu.shaders", "_RESOLVED_INCLUDES"),
                 ("pbrlab.foundation.file_identity", "_FILE_INCLUDES"))


def _forget_kept_answers():
    import sys
    for module, name in _KEPT_ANSWERS:
        if module in sys.modules:
            getattr(sys.modules[module], name).clear()


class _MonkeyPatchForgettingAnswers(pytest.MonkeyPatch):
    """pytest's monkeypatch, which also forgets the answers kept per process (_KEPT_ANSWERS: the
    Unity port's under a digest of the texts it is made from, the limit scans', the include
    resolutions') whenever it replaces something: a test's control that replaces one of the
    functions behind them must compute again, as must the test after it once that is undone."""

    def setattr(self, *args, **kwargs):
        super().setattr(*args, **kwargs)
        _forget_kept_answers()

    def undo(self):
        super().undo()
        _forget_kept_answers()


@pytest.fixture
def monkeypatch():
    patch = _MonkeyPatchForgettingAnswers()
    yield patch
    patch.undo()
