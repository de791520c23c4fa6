"""Results kept on disk between processes, so a command's start-up does not redo what an
earlier run already did with the same inputs (issue 25: reading the lit example's meshes
through trimesh cost 1.1 s of a 2 s render, most of it importing trimesh and scipy).

An entry is found by a key that names everything its value was made from (the caller hashes
the file contents, the code and the library versions into it), so an entry is never stale:
changed inputs make another key. The store is safe to share:

* writers never collide: each writes a temporary file beside the entry and renames it into
  place (``os.replace`` is atomic on POSIX), so a reader sees a whole entry or none;
* a damaged entry (a truncated file, flipped bits, another program's file) fails its
  SHA-256 check, is removed and reads as missing, and the caller builds the value again;
* the cache is optional: a folder that cannot be made or written (a read-only home) only
  means nothing is kept.

Where: ``$PBRLAB_CACHE_DIR``, else ``$XDG_CACHE_HOME/pbrlab``, else ``~/.cache/pbrlab``;
``PBRLAB_CACHE_DIR=off`` turns the cache off. Entries are small (a mesh's vertex arrays);
deleting the folder at any time is safe.
"""

from __future__ import annotations

import hashlib
import io
import os
import tempfile
from pathlib import Path

ENV_VAR = "PBRLAB_CACHE_DIR"
OFF = "off"
# The entry format: this line, then the SHA-256 digest of the payload, then the payload.
_MAGIC = b"pbrlab-cache/1\n"
_DIGEST_SIZE = hashlib.sha256().digest_size


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


def load(kind: str, name: str) -> bytes | None:
    """The payload stored under (``kind``, ``name``), or None when there is none or it was
    damaged (a damaged entry is removed)."""
    path = _entry_path(kind, name)
    if path is None:
        return None
    try:
        data = path.read_bytes()
    except OSError:
        return None
    head = len(_MAGIC) + _DIGEST_SIZE
    payload = data[head:]
    if data[:len(_MAGIC)] == _MAGIC and data[len(_MAGIC):head] == hashlib.sha256(payload).digest():
        return payload
    try:
        path.unlink()
    except OSError:
        pass
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
        with os.fdopen(handle, "wb") as out:
            out.write(_MAGIC + hashlib.sha256(payload).digest() + payload)
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
    """The arrays of ``pack_arrays``, in order."""
    import numpy as np

    buffer = io.BytesIO(payload)
    arrays = []
    while buffer.tell() < len(payload):
        arrays.append(np.lib.format.read_array(buffer, allow_pickle=False))
    return arrays
