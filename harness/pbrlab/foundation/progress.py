"""A live line on stderr for a command stage that runs past two seconds (issue 27: one bench
stage ran 87 s without a word): the stage's name and the seconds it has run, redrawn each
second, replaced by its total time when it ends. Stages that end sooner print nothing.

Shown only where a person watches, stderr being a terminal, and never under ``-q``
(console.QUIET): logs, pipes and CI output stay as they were.

    with progress.stage("measuring the frame cost"):
        ...

    stages = progress.Stages()        # one stage after another (pbrlab bench's steps)
    stages.start("error: D_GGX")
    stages.start("time: 24 kernels")  # ends the one before
    stages.close()
"""

from __future__ import annotations

import sys
import threading
import time
from contextlib import contextmanager

from . import console

DELAY_S = 2.0     # a stage shorter than this prints nothing
INTERVAL_S = 1.0  # how often the line is redrawn


def shown(stream=None) -> bool:
    """Whether progress lines are shown: stderr (or ``stream``) is a terminal and not -q."""
    stream = stream or sys.stderr
    isatty = getattr(stream, "isatty", None)
    return console.level() >= console.NORMAL and bool(isatty and isatty())


class Stages:
    """One stage at a time, each with its own live line (module doc)."""

    def __init__(self, stream=None):
        self.stream = stream or sys.stderr
        self._label = None
        self._started = 0.0
        self._drawn = False
        self._drawn_second = -1
        self._wake = threading.Event()
        self._lock = threading.Lock()
        self._thread = None

    def start(self, label: str) -> None:
        """End the current stage (if any) and start ``label``."""
        self._end()
        if not shown(self.stream):
            return
        with self._lock:
            self._label, self._started, self._drawn = label, time.monotonic(), False
            self._drawn_second = -1
        if self._thread is None:
            self._thread = threading.Thread(target=self._run, name="pbrlab-progress", daemon=True)
            self._thread.start()

    def close(self) -> None:
        """End the current stage and stop redrawing."""
        self._end()
        if self._thread is not None:
            self._wake.set()
            self._thread.join()
            self._thread = None
            self._wake.clear()

    def _end(self) -> None:
        with self._lock:
            if self._label is not None and self._drawn:
                self._write(f"\r\x1b[K{self._label}: {time.monotonic() - self._started:.1f} s\n")
            self._label = None

    def _run(self) -> None:
        while not self._wake.wait(INTERVAL_S / 4):
            with self._lock:
                if self._label is None:
                    continue
                elapsed = time.monotonic() - self._started
                if elapsed >= DELAY_S and int(elapsed) != self._drawn_second:
                    self._write(f"\r\x1b[K{self._label} ... {elapsed:.0f} s")
                    self._drawn, self._drawn_second = True, int(elapsed)

    def _write(self, text: str) -> None:
        try:
            self.stream.write(text)
            self.stream.flush()
        except (OSError, ValueError):  # the terminal went away: progress is not worth an error
            pass


@contextmanager
def stage(label: str, stream=None):
    """One stage (module doc)."""
    stages = Stages(stream)
    stages.start(label)
    try:
        yield
    finally:
        stages.close()
