"""Output files that survive faults: all-or-nothing, checked to the last byte, never an input.

    with outputs.transaction([png, exr], inputs=[scene_file, texture]) as tx:
        images.encode_png(tx.temp(png), pixels)   # any writer, into the temporary path
        tx.verify(png, lambda tmp: ...)           # optional: check what landed on disk
    # here every target holds its new content, or (an exception) every target is untouched

Rules, each answering a fault seen on earlier versions (issue 14):

* **Checked to the last byte.** After the writer closes a temporary file it is fsync'ed
  (a full disk or an I/O error surfaces here, not after the rename) and its size must be
  non-zero; callers that can (images.py) also read it back and compare. A write that
  fails leaves the target as it was and raises PbrlabError naming the target.
* **All or nothing.** Every temporary file of a transaction is written and checked before
  the first rename; renames are ``os.replace`` (atomic per file on POSIX) and the folder
  is fsync'ed afterwards. The renames themselves cannot run out of space; a rename that
  still fails (the folder vanished) is reported with the targets already replaced.
* **Never an input.** A target that is the same file as an input of the command
  (resolved path, or device and inode for hard links) is refused before any work.
* **Only regular files are renamed over** (issue 39). What a target names is decided first
  (output_targets): a link to a file in its folder has that file replaced (the link stays),
  a link out of the folder is refused; /dev/null, terminals, this process's /dev/stdout and
  FIFOs with a reader are written through from the checked temporary after every file
  passed; other devices and sockets are refused. A rename over /dev/null once replaced it.
* **No litter.** Temporary files are named ``.NAME.PID-RANDOM.tmpSUFFIX`` beside their
  target (same file system, so the rename is atomic; the suffix keeps OpenImageIO's
  format choice). ``signal_cleanup`` makes SIGTERM, SIGHUP and SIGINT unwind
  through the cleanup (the CLI installs it); a process killed outright (SIGKILL) leaves its
  temporaries, and the next transaction writing to that folder removes every one whose
  process no longer runs.
"""

from __future__ import annotations

import contextlib
import os
import re
import secrets
import signal
import tempfile
from pathlib import Path
from typing import Callable, Iterable, Iterator

from . import output_targets
from .errors import PbrlabError

_TEMP_NAME = re.compile(r"^\.(?P<name>.+)\.(?P<pid>\d+)-[0-9a-f]{8}\.tmp(?P<suffix>\.[^.]*)?$")
_LIVE: set[Path] = set()  # temporaries of this process not yet renamed or removed


def extension(path: Path) -> str:
    """The file's extension, as a writer picks its format by: ``path.suffix``, and for a name
    that is only an extension (``.png``, which Python reads as a hidden file with none) that name."""
    name = Path(path).name
    if not Path(path).suffix and name.startswith(".") and name.count(".") == 1 and len(name) > 1:
        return name
    return Path(path).suffix


def temp_name(path: Path, folder: Path | None = None) -> Path:
    """The temporary of ``path``, beside it (or in ``folder``), with its extension."""
    name = f".{path.name}.{os.getpid()}-{secrets.token_hex(4)}.tmp{extension(path)}"
    return (path.parent if folder is None else folder) / name


def _pid_alive(pid: int) -> bool:
    if pid == os.getpid():
        return True
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:  # another user's process: alive
        return True
    return True


def remove_stale_temps(folder: Path) -> list[Path]:
    """Remove our temporaries in ``folder`` left by processes that no longer run."""
    removed = []
    try:
        entries = list(os.scandir(folder))
    except OSError:
        return removed
    for entry in entries:
        m = _TEMP_NAME.match(entry.name)
        if m and entry.is_file(follow_symlinks=False) and not _pid_alive(int(m.group("pid"))):
            with contextlib.suppress(OSError):
                os.unlink(entry.path)
                removed.append(Path(entry.path))
    return removed


def check_writable_target(path: Path) -> None:
    """Raise PbrlabError when ``path`` cannot be written: a regular file (or a link to one in its
    folder) whose folder is writable, or a stream pbrlab writes through (output_targets)."""
    target = output_targets.classify(path, open_streams=False)
    if target.file is not None:
        _check_writable_file(Path(target.file))


def _check_writable_file(path: Path) -> None:
    parent = path.parent
    if not parent.exists():
        raise PbrlabError(f"cannot write {path}: directory {parent} does not exist")
    if not parent.is_dir():
        raise PbrlabError(f"cannot write {path}: {parent} is not a directory")
    if not os.access(parent, os.W_OK | os.X_OK):
        raise PbrlabError(f"cannot write {path}: directory {parent} is not writable")
    if path.is_dir():
        raise PbrlabError(f"cannot write {path}: it is a directory")


def _identity(path: Path):
    """(resolved path, (device, inode) or None) of ``path``."""
    try:
        resolved = Path(os.path.realpath(path))
    except (OSError, RuntimeError, ValueError):
        resolved = Path(os.path.abspath(path))
    try:
        st = os.stat(resolved)
        return resolved, (st.st_dev, st.st_ino)
    except (OSError, ValueError):
        return resolved, None


def refuse_inputs(targets: Iterable, inputs: Iterable) -> None:
    """Raise PbrlabError when a target is the same file as one of ``inputs``.

    ``inputs`` holds paths or (path, what) pairs; ``what`` names the input's role in the
    message ("the scene's albedo texture").
    """
    known = []
    for item in inputs:
        path, what = item if isinstance(item, tuple) else (item, "an input")
        if path is not None:
            known.append((*_identity(Path(path)), Path(path), what))
    for target in targets:
        resolved, ident = _identity(Path(target))
        for in_resolved, in_ident, shown, what in known:
            if resolved == in_resolved or (ident is not None and ident == in_ident):
                raise PbrlabError(f"refusing to write {target}: it is also an input of this command "
                                  f"({what}: {shown}); choose another output name")


def refuse_duplicates(targets: list[Path]) -> None:
    seen = {}
    for target in targets:
        resolved, _ = _identity(target)
        if resolved in seen:
            raise PbrlabError(f"{seen[resolved]} and {target} name the same output file")
        seen[resolved] = target


def fsync_file(path: Path, target: Path) -> int:
    """fsync ``path`` and return its size; a failure names ``target``."""
    try:
        fd = os.open(path, os.O_RDONLY)
        try:
            os.fsync(fd)
            return os.fstat(fd).st_size
        finally:
            os.close(fd)
    except OSError as exc:
        raise PbrlabError(f"cannot write {target}: {exc.strerror or exc}") from None


def write_bytes_checked(path: Path, data: bytes, target: Path) -> None:
    """Write ``data`` to ``path``, flush and fsync, and check the size on disk."""
    try:
        with open(path, "wb") as f:
            f.write(data)
            f.flush()
            os.fsync(f.fileno())
    except OSError as exc:
        raise PbrlabError(f"cannot write {target}: {exc.strerror or exc}") from None
    size = os.stat(path).st_size
    if size != len(data):
        raise PbrlabError(f"cannot write {target}: {size} of {len(data)} bytes reached the disk")


# A PNG ends with its IEND chunk: length 0, type "IEND", CRC AE 42 60 82 (PNG spec 11.2.5).
# libpng reads a file truncated inside it without complaint, so the trailer is checked.
PNG_TRAILER = b"\x00\x00\x00\x00IEND\xaeB`\x82"


def check_png_complete(tmp: Path, target: Path) -> None:
    """Raise PbrlabError naming ``target`` when the PNG at ``tmp`` lacks its end marker."""
    with open(tmp, "rb") as f:
        f.seek(max(0, f.seek(0, 2) - len(PNG_TRAILER)))
        if f.read() != PNG_TRAILER:
            raise PbrlabError(f"cannot write {target}: the file written is cut short (no PNG "
                              "end marker), the disk may be full; the old file is kept")


class Transaction:
    """Temporaries for a set of targets, renamed onto them together by ``commit``."""

    def __init__(self, targets: Iterable, inputs: Iterable = ()):
        self.targets = [Path(t) for t in targets]
        refuse_duplicates(self.targets)
        refuse_inputs(self.targets, inputs)
        self.kinds: dict[Path, output_targets.OutputTarget] = {}
        try:
            for target in self.targets:  # a file, a link in its folder, or a stream (output_targets)
                self.kinds[target] = kind = output_targets.classify(target)
                if kind.file is not None:
                    _check_writable_file(kind.file)
        except BaseException:
            self._close_streams()
            raise
        # A file's temporary lies beside the file it replaces (a link's target, for a link); a
        # stream's in the system's temporary folder (never in /dev).
        folders = {t: (k.file.parent if k.file is not None else Path(tempfile.gettempdir()))
                   for t, k in self.kinds.items()}
        for folder in set(folders.values()):
            remove_stale_temps(folder)
        self.temps = {t: temp_name(t, folders[t]) for t in self.targets}
        self.checks: dict[Path, list[Callable[[Path], None]]] = {t: [] for t in self.targets}
        _LIVE.update(self.temps.values())

    def _close_streams(self) -> None:
        for kind in self.kinds.values():
            output_targets.close(kind)

    def temp(self, target) -> Path:
        return self.temps[Path(target)]

    def verify(self, target, check: Callable[[Path], None]) -> None:
        """Run ``check(temp)`` before commit (it raises PbrlabError on a bad file)."""
        self.checks[Path(target)].append(check)

    def write_text(self, target, text: str) -> None:
        self.write_bytes(target, text.encode("utf-8"))

    def write_bytes(self, target, data: bytes) -> None:
        target = Path(target)
        write_bytes_checked(self.temp(target), data, target)

    @contextlib.contextmanager
    def writing(self, target) -> Iterator[Path]:
        """The temporary path of ``target`` for a writer that takes a path (matplotlib's
        ``savefig``): an OSError it raises (a full disk, an I/O error) becomes a PbrlabError
        naming ``target``, and a PNG must end with its IEND trailer before the commit."""
        target = Path(target)
        tmp = self.temp(target)
        try:
            yield tmp
        except OSError as exc:  # the message names the target, never the temporary
            reason = str(exc.strerror or exc).replace(str(tmp), str(target))
            raise PbrlabError(f"cannot write {target}: {reason}") from None
        if extension(target).lower() == ".png":
            self.verify(target, lambda tmp: check_png_complete(tmp, target))

    def commit(self) -> None:
        for target, tmp in self.temps.items():
            if not tmp.exists():
                raise PbrlabError(f"cannot write {target}: the writer produced no file")
            if fsync_file(tmp, target) == 0:
                raise PbrlabError(f"cannot write {target}: the file written is empty")
            for check in self.checks[target]:
                check(tmp)
        for target, tmp in self.temps.items():  # streams first: they can still fail (EPIPE, ENOSPC)
            if self.kinds[target].is_stream:
                output_targets.write_through(self.kinds[target], tmp)
        done = []
        for target, tmp in self.temps.items():
            if self.kinds[target].is_stream:
                continue
            try:
                os.replace(tmp, self.kinds[target].file)
            except OSError as exc:
                already = f" ({', '.join(map(str, done))} already replaced)" if done else ""
                raise PbrlabError(f"cannot write {target}: {exc.strerror or exc}{already}") from None
            _LIVE.discard(tmp)
            done.append(target)
        for folder in {k.file.parent for k in self.kinds.values() if k.file is not None}:
            with contextlib.suppress(OSError):  # not every file system syncs folders
                fd = os.open(folder, os.O_RDONLY)
                try:
                    os.fsync(fd)
                finally:
                    os.close(fd)

    def abort(self) -> None:
        self._close_streams()
        for tmp in self.temps.values():
            with contextlib.suppress(OSError):
                tmp.unlink()
            _LIVE.discard(tmp)


@contextlib.contextmanager
def transaction(targets: Iterable, inputs: Iterable = ()) -> Iterator[Transaction]:
    """A Transaction committed when the block succeeds, aborted (temporaries removed,
    targets untouched) when it raises, including KeyboardInterrupt and SystemExit."""
    tx = Transaction(targets, inputs)
    try:
        yield tx
        tx.commit()
    finally:
        tx.abort()  # after a commit only temporaries that were never renamed remain


def write_file(target, data, inputs: Iterable = ()) -> None:
    """Write ``data`` (str as UTF-8, or bytes) to ``target`` as a one-file transaction."""
    with transaction([target], inputs) as tx:
        tx.write_bytes(target, data.encode("utf-8") if isinstance(data, str) else data)


def write_npy(target, array) -> None:
    """Save a NumPy array to ``target`` (.npy) as a one-file transaction."""
    import io

    import numpy as np
    buffer = io.BytesIO()
    np.save(buffer, array)
    write_file(target, buffer.getvalue())


def write_figure(target, figure, inputs: Iterable = (), **savefig) -> None:
    """Save a matplotlib figure to ``target`` as a one-file transaction, in the format of
    the target's extension (the temporary file's name would not say it to every backend)."""
    with transaction([target], inputs) as tx:
        write_figure_in(tx, target, figure, **savefig)


def write_figure_in(tx: Transaction, target, figure, **savefig) -> None:
    """Save a matplotlib figure to ``target`` inside the transaction ``tx``."""
    with tx.writing(target) as tmp:
        figure.savefig(tmp, format=extension(Path(target)).lstrip(".").lower() or None, **savefig)


def remove_live_temps() -> None:
    """Remove every temporary of this process (the signal handler's last act)."""
    for tmp in list(_LIVE):
        with contextlib.suppress(OSError):
            tmp.unlink()
        _LIVE.discard(tmp)


class Terminated(BaseException):
    """Raised in the main thread by SIGTERM/SIGHUP inside signal_cleanup()."""

    def __init__(self, signum: int):
        super().__init__(f"terminated by signal {signum}")
        self.signum = signum


def _on_signal(signum, frame):
    raise Terminated(signum)


@contextlib.contextmanager
def signal_cleanup() -> Iterator[None]:
    """Within the block, SIGTERM and SIGHUP raise ``Terminated`` (SIGINT already raises
    KeyboardInterrupt), so open transactions unwind and remove their temporaries; the
    previous handlers come back afterwards."""
    previous = {}
    for signum in (signal.SIGTERM, signal.SIGHUP):
        with contextlib.suppress(ValueError, OSError):  # not the main thread
            previous[signum] = signal.signal(signum, _on_signal)
    try:
        yield
    finally:
        for signum, handler in previous.items():
            signal.signal(signum, handler)
