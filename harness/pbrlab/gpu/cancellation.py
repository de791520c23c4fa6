"""Stopping on SIGINT, SIGTERM and SIGHUP while the driver runs a long call (issue 39).

Python runs a signal handler only between bytecodes, so a compile inside Mesa (one C call
that can take tens of seconds: 4,000 statements took llvmpipe 38 s, issue 26) used to
delay Ctrl-C and SIGTERM until it returned. ``dies_on_signal`` gives these signals their
default action (POSIX: terminate the process) for the length of such a call: the kernel
ends the process within the signal's delivery, with the status a shell reports as 128 +
the signal (130 for Ctrl-C, 143 for SIGTERM), and no traceback. Nothing half-written can
be left: pbrlab's outputs are written to hidden temporaries and renamed into place only
when whole (foundation/outputs.py), and no output is written during a compile; a
temporary left by a killed process is removed by the next write into its folder. Outside
such calls the handlers pbrlab installs (outputs.signal_cleanup) run as before.

Only the main thread of the main interpreter can change signal actions; elsewhere (a
worker thread) the call runs with the process's handlers unchanged.
"""

from __future__ import annotations

import contextlib
import signal
import threading
from typing import Iterator

SIGNALS = tuple(getattr(signal, name) for name in ("SIGINT", "SIGTERM", "SIGHUP") if hasattr(signal, name))


@contextlib.contextmanager
def dies_on_signal() -> Iterator[None]:
    """Within the block, SIGINT/SIGTERM/SIGHUP terminate the process at once (module doc)."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    previous = {}
    try:
        for signum in SIGNALS:
            previous[signum] = signal.signal(signum, signal.SIG_DFL)
        yield
    finally:
        for signum, handler in previous.items():
            signal.signal(signum, handler if handler is not None else signal.SIG_DFL)
