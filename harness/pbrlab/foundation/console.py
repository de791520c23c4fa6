"""How much the `pbrlab` command says, set once by ``-q`` / ``-v`` (pbrlab.commands.cli).

  -q  results and errors only (tables, metrics, JSON, golden verdicts, exit status);
      no progress or "wrote ..." lines;
      (default) results plus progress and the files written;
  -v  also details (the renderer).

Results are printed with ``print``; everything else goes through ``note`` or ``detail``.
"""

from __future__ import annotations

import sys

QUIET, NORMAL, VERBOSE = 0, 1, 2
_level = NORMAL


def set_level(level: int) -> None:
    global _level
    _level = level


def level() -> int:
    return _level


def note(message: str, *, stream=None) -> None:
    """Progress and files written: shown unless -q."""
    if _level >= NORMAL:
        print(message, file=stream or sys.stdout, flush=True)


def detail(message: str, *, stream=None) -> None:
    """Details: shown under -v only."""
    if _level >= VERBOSE:
        print(message, file=stream or sys.stdout, flush=True)
