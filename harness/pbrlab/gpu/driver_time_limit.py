"""A time limit on one call into the GL driver: a compile, or the draw at which llvmpipe
compiles a program's machine code (issue 39).

Mesa compiles inside this process, in one C call that holds Python's interpreter lock
(measured: a Python thread ticking every 50 ms ticked twice during a 13 s compile and draw
of 1,500 statements), so neither a thread nor a signal handler of this process can stop
it: a program of tens of thousands of statements (4,000 took llvmpipe 38 s, issue 26)
would run for hours. The limit is kept by a watchdog child process instead, started at
the first armed call and fed "arm" and "disarm" lines through a pipe. When a call runs
past the limit, the watchdog prints the message (what was being compiled, the limit, the
variable that raises it) on pbrlab's standard error and sends the process SIGTERM, which
during a driver call has its default action (cancellation.dies_on_signal): the process
ends at once with status 143, as after ``kill``; SIGKILL follows 2 s later if it has
not. Nothing half-written can be left: outputs are renamed into place only when whole.
The watchdog ends when the pipe closes, that is when this process ends.

The limit is a command-line guard, kept while ``pbrlab``'s main runs a command (``enabled``):
a program using pbrlab as a library keeps its own process and sets its own timeouts.

LIMIT_S = 120 s: the slowest program pbrlab itself builds compiles in a few seconds, a
4,000-statement surface in 38 s (llvmpipe, issue 26); 120 s lets three times that through
on this machine class. ``PBRLAB_DRIVER_TIME_LIMIT_S`` sets another limit (0: none).
"""

from __future__ import annotations

import contextlib
import os
import subprocess
import sys
import threading
from typing import Iterator

LIMIT_S = 120.0
ENVIRONMENT_VARIABLE = "PBRLAB_DRIVER_TIME_LIMIT_S"

# The watchdog: waits on its standard input; "arm SECONDS MESSAGE" starts the clock,
# "disarm" stops it; at the deadline it prints MESSAGE and ends its parent.
_WATCHDOG = r"""
import os, select, signal, sys, time
parent = int(sys.argv[1])
deadline, message, pending = None, b"", b""
while True:
    wait = None if deadline is None else max(0.0, deadline - time.monotonic())
    ready, _, _ = select.select([0], [], [], wait)
    if not ready:
        if os.getppid() == parent:
            os.write(2, message + b"\n")
            os.kill(parent, signal.SIGTERM)
            time.sleep(2.0)
            if os.getppid() == parent:
                os.kill(parent, signal.SIGKILL)
        sys.exit(0)
    chunk = os.read(0, 65536)
    if not chunk:
        sys.exit(0)
    pending += chunk
    while b"\n" in pending:
        line, pending = pending.split(b"\n", 1)
        if line.startswith(b"arm "):
            seconds, _, message = line[4:].partition(b" ")
            deadline = time.monotonic() + float(seconds)
        else:
            deadline = None
"""

_state = threading.local()
_enabled = False
_watchdog: subprocess.Popen | None = None
_lock = threading.Lock()


@contextlib.contextmanager
def enabled() -> Iterator[None]:
    """Keep the limit on the driver calls within the block (pbrlab's main runs a command in
    it); after the outermost block the watchdog is ended, so a program that called main()
    in its own process (a test, a script) keeps no limit and no child."""
    global _enabled, _watchdog
    previous = _enabled
    _enabled = True
    try:
        yield
    finally:
        _enabled = previous
        if not previous and _watchdog is not None:
            watchdog, _watchdog = _watchdog, None
            if watchdog.stdin is not None:
                watchdog.stdin.close()  # end of input: the watchdog exits
            try:
                watchdog.wait(timeout=5)
            except subprocess.TimeoutExpired:
                watchdog.kill()
                watchdog.wait()


def limit_s() -> float:
    """The limit in seconds: PBRLAB_DRIVER_TIME_LIMIT_S, else LIMIT_S; 0 means none."""
    text = os.environ.get(ENVIRONMENT_VARIABLE, "").strip()
    if not text:
        return LIMIT_S
    try:
        value = float(text)
    except ValueError:
        return LIMIT_S
    return value if value >= 0.0 and value == value else LIMIT_S


def _send(line: str) -> None:
    """``line`` to the watchdog, started (again) where there is none or it has ended."""
    global _watchdog
    for _ in range(2):  # a watchdog killed from outside since the last line: start another once
        if _watchdog is None or _watchdog.poll() is not None:
            _watchdog = subprocess.Popen(
                [sys.executable, "-I", "-S", "-c", _WATCHDOG, str(os.getpid())],
                stdin=subprocess.PIPE, stdout=subprocess.DEVNULL, close_fds=True)
        try:
            assert _watchdog.stdin is not None
            _watchdog.stdin.write(line.encode("utf-8", "replace") + b"\n")
            _watchdog.stdin.flush()
            return
        except BrokenPipeError:
            _watchdog.wait()


@contextlib.contextmanager
def within_time_limit(what: str) -> Iterator[None]:
    """Within the block (one driver call), the process ends with a message naming ``what``
    once the call has run past the limit (module doc). Nested blocks keep the outer clock;
    other threads than the main one run without the limit (as cancellation.dies_on_signal)."""
    seconds = limit_s()
    if (not _enabled or seconds == 0.0 or getattr(_state, "armed", False)
            or threading.current_thread() is not threading.main_thread()):
        yield
        return
    message = (f"pbrlab: error: {what} ran over the driver time limit of {seconds:g} s "
               f"(Mesa compiles in this process and cannot be stopped otherwise; "
               f"{ENVIRONMENT_VARIABLE} sets another limit)").replace("\n", " ")
    with _lock:
        _send(f"arm {seconds!r} {message}")
    _state.armed = True
    try:
        yield
    finally:
        _state.armed = False
        with _lock:
            _send("disarm")
