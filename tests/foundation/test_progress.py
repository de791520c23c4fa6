"""pbrlab.foundation.progress: a live line for a stage past its delay, on a terminal only, never under -q."""

from __future__ import annotations

import io
import time

import pytest

from pbrlab.foundation import console, progress


class Terminal(io.StringIO):
    def isatty(self):
        return True


@pytest.fixture
def quick(monkeypatch):
    """Delays in tenths of a second, so the test takes under one."""
    monkeypatch.setattr(progress, "DELAY_S", 0.2)
    monkeypatch.setattr(progress, "INTERVAL_S", 0.1)
    monkeypatch.setattr(console, "_level", console.NORMAL)


def test_a_long_stage_shows_its_seconds_then_its_total(quick):
    out = Terminal()
    with progress.stage("measuring", stream=out):
        time.sleep(0.5)
    text = out.getvalue()
    assert "measuring ... 0 s" in text
    assert text.endswith("\n") and text.rsplit("\r\x1b[K", 1)[1].startswith("measuring: 0.")


def test_a_short_stage_prints_nothing(quick):
    out = Terminal()
    with progress.stage("quick", stream=out):
        pass
    assert out.getvalue() == ""


def test_silent_when_not_a_terminal_or_quiet(quick, monkeypatch):
    pipe = io.StringIO()
    with progress.stage("measuring", stream=pipe):
        time.sleep(0.4)
    assert pipe.getvalue() == ""
    monkeypatch.setattr(console, "_level", console.QUIET)
    out = Terminal()
    with progress.stage("measuring", stream=out):
        time.sleep(0.4)
    assert out.getvalue() == ""


def test_stages_end_one_another(quick):
    out = Terminal()
    stages = progress.Stages(out)
    stages.start("first")
    time.sleep(0.4)
    stages.start("second")  # ends the first: its total on a line of its own
    stages.close()
    text = out.getvalue()
    assert "first: 0." in text and "second" not in text  # the second ended before its delay
