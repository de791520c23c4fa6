"""Results kept on disk between processes, so a command's start-up does not redo what an
earlier run already did with the same inputs (issue 25: reading the lit example's meshes
through trimesh cost 1.1 s of a 2 s render, most of it importing trimesh and scipy).

An entry is found by a key that names everything its value was made from (the caller hashes
the file contents, the code and the library versions into it), so an entry is never stale:
changed inputs make another key. The store is safe to share:

* writers never collide: each writes a temporary file beside the entry and renames it into
  place (``os.replace`` is atomic on POSIX), so a reader sees a whole entry or none;
* nothing comes from the store that was not written by this version for this key: the
  entry's header (its kind, its key, the package version and the entry format) is inside
  the SHA-256 checksum with the payload, so a truncated file, flipped bits, another
  program's file, an entry of an older version or one copied under another key or kind (a
  mesh's entry where an environment's is looked for) fails the check;
* only a regular file of at most MAX_ENTRY_BYTES is read, opened without blocking: a FIFO,
  a device or a folder put where an entry belongs reads as missing, without hanging;
* a payload that passes the check but does not decode into what the caller expects (the
  caller's ``decode`` raises ValueError, TypeError, KeyError, IndexError or EOFError:
  garbage written with a valid checksum) is reported as a BadCacheEntryWarning naming the
  file;
* a bad entry, whatever its fault, is removed and reads as missing, and the caller builds
  the value again;
* the cache is optional: a folder that cannot be made or written (a read-only home) only
  means nothing is kept.

Where: ``$PBRLAB_CACHE_DIR``, else ``$XDG_CACHE_HOME/pbrlab``, else ``~/.cache/pbrlab``;
``PBRLAB_CACHE_DIR=off`` turns the cache off. Entries are small (a mesh's vertex arrays);
deleting the folder at any time is safe.
"""

from __future__ import annotations

import hashlib
import io
import json
import os
import stat
import tempfile
import warnings
from pathlib import Path

from .version import __version__

ENV_VAR = "PBRLAB_CACHE_DIR"
OFF = "off"
# The entry format: this line, the SHA-256 digest of everything after it, one line of JSON
# naming the entry (kind, key, version), then the payload.
_MAGIC = b"pbrlab-cache/2\n"
_DIGEST_SIZE = hashlib.sha256().digest_size
# The largest entry read back. The store's largest kind is a prefiltered environment:
# 6 faces x 4 float32 x (256^2 + 128^2 + 64^2 + 32^2 + 16^2) texels = 8.4 MB (gpu/ibl.py);
# a mesh is 60 bytes a vertex (meshes.vertex_arrays: 3+3+2+4 float32 and 12 bytes of indices
# for about one triangle a vertex), so 256 MiB holds a mesh of 4.4 million vertices, and
# bounds what one hostile entry makes this process read (256 MiB of a memory budget of
# 2 GiB per render).
MAX_ENTRY_BYTES = 256 * 1024 * 1024
# What a caller's decode raises on bytes that are not what it wrote (numpy's .npy reader:
# ValueError, EOFError; json: ValueError; a wrong structure: TypeError, KeyError, IndexError).
DECODE_ERRORS = (ValueError, TypeError, KeyError, IndexError, EOFError)


class BadCacheEntryWarning(UserWarning):
    """A cache entry was damaged, foreign or did not decode; it was removed and its value is
    being computed again."""


def cache_dir() -> Path | None:
    """The cache folder (not necessarily existing yet); None when turned off."""
    configured = os.environ.get(ENV_VAR)
    if configured == OFF:
        return None
    if configured:
        return Path(configured)
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return Path(base) / "pbrlab"


def key(*parts) -> str:
    """A hex key naming ``parts`` (strings, bytes, numbers, tuples of them)."""
    digest = hashlib.sha256()
    for part in parts:
        data = part if isinstance(part, bytes) else repr(part).encode("utf-8")
        digest.update(len(data).to_bytes(8, "little"))  # no two part lists hash the same bytes
        digest.update(data)
    return digest.hexdigest()


def _entry_path(kind: str, name: str) -> Path | None:
    root = cache_dir()
    return None if root is None else root / kind / name[:2] / name


def _header(kind: str, name: str) -> bytes:
    """The line that names an entry: what it is, for which key, written by which version."""
    return json.dumps({"kind": kind, "key": name, "version": __version__,
                       "format": _MAGIC.decode().strip()}, sort_keys=True).encode("utf-8") + b"\n"


def _read_regular_file(path: Path) -> bytes | None:
    """The bytes of ``path`` when it is a regular file of at most MAX_ENTRY_BYTES; None
    otherwise or when it cannot be read. Opened with O_NONBLOCK, so a FIFO does not wait for a
    writer (POSIX open(2)), and checked with fstat on the opened file, so nothing can be
    swapped in between the check and the read."""
    flags = os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_BINARY", 0)
    try:
        handle = os.open(path, flags)
    except OSError:
        return None
    try:
        info = os.fstat(handle)
        if not stat.S_ISREG(info.st_mode) or info.st_size > MAX_ENTRY_BYTES:
            return None
        with os.fdopen(os.dup(handle), "rb") as file:
            return file.read(MAX_ENTRY_BYTES + 1)
    except OSError:
        return None
    finally:
        os.close(handle)


def _discard(path: Path, why: str | None):
    """Remove a bad entry; ``why`` (when given) is told as a BadCacheEntryWarning."""
    if why is not None:
        warnings.warn(f"{path}: {why}; removed it and computing the value again",
                      BadCacheEntryWarning, stacklevel=3)
    try:
        if not path.is_dir():
            path.unlink()
    except OSError:
        pass


def load(kind: str, name: str, decode=None):
    """The payload stored under (``kind``, ``name``), passed through ``decode`` when given,
    or None when there is none or it was bad (a bad entry is removed; one that passed its
    checksum but failed ``decode`` is also reported as a BadCacheEntryWarning)."""
    path = _entry_path(kind, name)
    if path is None or not os.path.lexists(path):
        return None
    data = _read_regular_file(path)
    header = _header(kind, name)
    head = len(_MAGIC) + _DIGEST_SIZE
    if (data is None or data[:len(_MAGIC)] != _MAGIC or data[len(_MAGIC):head] != hashlib.sha256(data[head:]).digest()
            or data[head:head + len(header)] != header):
        _discard(path, "not a cache entry of this pbrlab version for this key (damaged, foreign, "
                       "of another version, or not a regular file)" if data is not None else
                       "not a regular file of at most MAX_ENTRY_BYTES")
        return None
    payload = data[head + len(header):]
    if decode is None:
        return payload
    try:
        return decode(payload)
    except DECODE_ERRORS as exc:
        _discard(path, f"its content does not decode as a {kind} entry ({type(exc).__name__}: {exc})")
        return None


def store(kind: str, name: str, payload: bytes) -> bool:
    """Keep ``payload`` under (``kind``, ``name``); False when it could not be written."""
    path = _entry_path(kind, name)
    if path is None:
        return False
    temporary = None
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        handle, temporary = tempfile.mkstemp(prefix=f".{name[:16]}-", dir=path.parent)
        body = _header(kind, name) + payload
        with os.fdopen(handle, "wb") as out:
            out.write(_MAGIC + hashlib.sha256(body).digest() + body)
        os.replace(temporary, path)
        return True
    except OSError:
        if temporary is not None:
            try:
                os.unlink(temporary)
            except OSError:
                pass
        return False


def pack_arrays(arrays) -> bytes:
    """numpy arrays as one payload: each in the .npy format, one after another (not an .npz,
    whose reader loads zipfile)."""
    import numpy as np

    buffer = io.BytesIO()
    for array in arrays:
        np.lib.format.write_array(buffer, np.asarray(array), allow_pickle=False)
    return buffer.getvalue()


def unpack_arrays(payload: bytes) -> list:
    """The arrays of ``pack_arrays``, in order. Each array's header is read first, and an
    array whose header claims more bytes than the payload holds is a ValueError before any
    memory is set aside for it (numpy's reader would allocate the claimed size first)."""
    import numpy as np

    fmt = np.lib.format
    buffer = io.BytesIO(payload)
    arrays = []
    while buffer.tell() < len(payload):
        version = fmt.read_magic(buffer)
        if version == (1, 0):
            shape, fortran, dtype = fmt.read_array_header_1_0(buffer)
        elif version == (2, 0):
            shape, fortran, dtype = fmt.read_array_header_2_0(buffer)
        else:  # pack_arrays writes 1.0 (2.0 for headers over 64 KiB); 3.0 is for unicode field names
            raise ValueError(f".npy format version {version}")
        if dtype.hasobject:
            raise ValueError("an array of Python objects")
        size = dtype.itemsize * int(np.prod(shape, dtype=object))
        if size > len(payload) - buffer.tell():
            raise ValueError(f"an array of {size} bytes in {len(payload) - buffer.tell()} left")
        flat = np.frombuffer(buffer.read(size), dtype=dtype)
        arrays.append(flat.reshape(shape[::-1]).transpose() if fortran else flat.reshape(shape))
    return arrays
