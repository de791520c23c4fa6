"""What an output path names, decided before any work: a regular file to replace (the
transaction's temporary-and-rename), a stream to write through, or a refusal.

An output is replaced by renaming a temporary over it. That is right for a regular file and
destroys anything else: as root, ``-o /dev/null`` renamed a regular file over the device node,
and a rename over a symbolic link replaces the link, not what it names. So (docs/faults.md,
"Outputs that are not regular files"):

* a **regular file** (or a new name): replaced by rename, as before;
* a **symbolic link to a regular file** (or to a name not yet there) in the link's own folder
  or below it: the file the link names is replaced, the link stays a link; a link that leads
  out of the output's folder is refused (an unpacked archive's ``out.png -> /etc/...``);
* **this process's own streams** (``/dev/stdout``, ``/dev/stderr``, ``/dev/fd/N``,
  ``/proc/self/fd/N``): written through to the open descriptor, at its position, as a
  program's printing is, whatever it points at (a terminal, a pipe, a file the shell opened);
* **character devices that take any bytes**: ``/dev/null``, ``/dev/zero``, ``/dev/full`` (which
  answers "no space left", reported as such) and terminals: written through, never replaced;
* a **FIFO**: written through when a process reads it (opened before any work, so a FIFO
  with no reader is refused at once rather than blocking);
* every other kind, refused by name: a block device (a disk), a socket, a directory, any
  other character device (what a write to ``/dev/mem``, a watchdog or a raw disk would do is
  no output's business), standard input.

A stream is written after every file of the command passed its checks, from the same checked
temporary (kept in the system's temporary folder); it cannot be all-or-nothing with the
files, and a reader may already have consumed part of it when a later write fails.
"""

from __future__ import annotations

import errno
import os
import re
import stat
from dataclasses import dataclass
from pathlib import Path

from .errors import PbrlabError
from .safe_paths import is_within

# This process's descriptors by name (Linux's /dev/fd and /proc/self/fd; /dev/stdout and
# /dev/stderr are links into them).
_STREAM_NAME = re.compile(r"^(?:/dev/std(?P<std>in|out|err)|/dev/fd/(?P<fd>\d+)|/proc/self/fd/(?P<pfd>\d+))$")

# Character devices (Linux major, minor; None: every minor) that take any bytes without harm:
# Documentation/admin-guide/devices.txt: 1/3 null, 1/5 zero, 1/7 full; 4 virtual consoles and
# serial terminals (tty0..63, ttyS*), 5/0 the current tty, 5/1 the console, 136-143 the
# pseudo-terminal slaves (/dev/pts/N).
SAFE_CHARACTER_DEVICES = {(1, 3), (1, 5), (1, 7), (4, None), (5, 0), (5, 1),
                          *((major, None) for major in range(136, 144))}


@dataclass
class OutputTarget:
    written: Path              # the path as the user named it (every message says this one)
    file: Path | None = None   # the regular file a rename replaces (a link's target, for a link)
    fd: int | None = None      # a stream: this process's descriptor, or one opened for it
    owned: bool = False        # whether ``fd`` was opened here (closed when done)

    @property
    def is_stream(self) -> bool:
        return self.file is None


def _refuse(path, why: str):
    raise PbrlabError(f"refusing to write {path}: {why}")


def _safe_device(st: os.stat_result) -> bool:
    major, minor = os.major(st.st_rdev), os.minor(st.st_rdev)
    return (major, minor) in SAFE_CHARACTER_DEVICES or (major, None) in SAFE_CHARACTER_DEVICES


def _own_stream(path: Path, text: str) -> OutputTarget:
    m = _STREAM_NAME.match(text)
    fd = {"in": 0, "out": 1, "err": 2}[m["std"]] if m["std"] else int(m["fd"] or m["pfd"])
    if fd == 0:
        _refuse(path, "it is standard input")
    try:
        os.fstat(fd)
    except OSError:
        _refuse(path, f"descriptor {fd} is not open in this process")
    return OutputTarget(Path(path), fd=fd)


def _stream_of_kind(path: Path, st: os.stat_result, shown: str, open_it: bool = True) -> OutputTarget:
    """A non-regular file: written through (a safe device, a FIFO with a reader) or refused."""
    mode = st.st_mode
    if stat.S_ISDIR(mode):
        _refuse(path, f"{shown}is a directory")
    if stat.S_ISCHR(mode):
        if not _safe_device(st):
            _refuse(path, f"{shown}is a character device other than /dev/null, /dev/zero, /dev/full or a "
                          f"terminal ({os.major(st.st_rdev)}, {os.minor(st.st_rdev)}); pbrlab writes "
                          "regular files and writes through only to those")
        flags = os.O_WRONLY | os.O_NOCTTY
    elif stat.S_ISFIFO(mode):
        flags = os.O_WRONLY | os.O_NONBLOCK  # no reader: ENXIO now, not a hang
    elif stat.S_ISBLK(mode):
        _refuse(path, f"{shown}is a block device (a disk or a partition); pbrlab writes regular files")
    elif stat.S_ISSOCK(mode):
        _refuse(path, f"{shown}is a socket; pbrlab writes regular files")
    else:
        _refuse(path, f"{shown}is not a regular file (mode {oct(mode)})")
    if not open_it:  # a check ahead of the work: opening and closing a FIFO would end its reader's read
        return OutputTarget(Path(path))
    try:
        fd = os.open(path, flags)
    except OSError as exc:
        if exc.errno == errno.ENXIO and stat.S_ISFIFO(mode):
            _refuse(path, f"{shown}is a FIFO that no process reads")
        _refuse(path, f"cannot open it for writing: {exc.strerror or exc}")
    if stat.S_ISFIFO(mode):
        os.set_blocking(fd, True)
    return OutputTarget(Path(path), fd=fd, owned=True)


def classify(path, open_streams: bool = True) -> OutputTarget:
    """The output ``path`` names (module docstring), or a PbrlabError naming it. A device or
    FIFO is opened for writing here (a FIFO without a reader refused now), unless
    ``open_streams`` is false (a check ahead of the work; the transaction opens it later)."""
    path = Path(path)
    text = os.fspath(path)
    if _STREAM_NAME.match(text):
        return _own_stream(path, text)
    try:
        lst = os.lstat(path)
    except (FileNotFoundError, NotADirectoryError):
        return OutputTarget(path, file=path)  # a new file; its folder is checked by the caller
    except OSError as exc:  # a component that is a file, a name too long, no permission
        _refuse(path, exc.strerror or str(exc))
    if not stat.S_ISLNK(lst.st_mode):
        if stat.S_ISREG(lst.st_mode):
            return OutputTarget(path, file=path)
        return _stream_of_kind(path, lst, "it ", open_streams)
    lead = os.readlink(path)
    real = Path(os.path.realpath(path))
    try:
        st = os.stat(path)
    except FileNotFoundError:
        st = None  # a link to a name not there yet: the file is created where it points
    except OSError as exc:  # a loop
        _refuse(path, f"it is a symbolic link that cannot be followed ({exc.strerror or exc})")
    if st is not None and not stat.S_ISREG(st.st_mode):
        return _stream_of_kind(path, st, f"it is a symbolic link to {lead}, which ", open_streams)
    folder = os.path.realpath(path.parent)
    if not is_within(real, folder):
        _refuse(path, f"it is a symbolic link to {lead}, which leads outside {path.parent or '.'} "
                      f"(to {real}); write to that file by its own name")
    return OutputTarget(path, file=real)


def names_a_stream(path) -> bool:
    """Whether ``path`` names something written through, not a file (this process's streams, a
    device, a FIFO): a command then keeps its "wrote ..." note off a stream it may share."""
    if _STREAM_NAME.match(os.fspath(path)):
        return True
    try:
        return not stat.S_ISREG(os.stat(path).st_mode)
    except OSError:
        return False


def close(target: OutputTarget) -> None:
    if target.owned and target.fd is not None:
        try:
            os.close(target.fd)
        except OSError:
            pass
        target.fd = None


def write_through(target: OutputTarget, temp: Path) -> None:
    """Copy the checked temporary ``temp`` to the stream ``target``; errors name the target."""
    try:
        with open(temp, "rb") as f:
            while chunk := f.read(1 << 20):
                view = memoryview(chunk)
                while view:
                    view = view[os.write(target.fd, view):]
    except OSError as exc:
        raise PbrlabError(f"cannot write {target.written}: {exc.strerror or exc}") from None
    finally:
        close(target)
