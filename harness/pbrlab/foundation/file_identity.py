"""What a cached result was made from, so a cache can tell when it went stale.

A file's identity is (resolved path, size, modification time in ns, inode): rewriting a
file in place changes size or mtime, replacing it by a rename changes the inode (even
within one mtime tick on a coarse-clock file system). ``FileCache`` is the one LRU the
harness's caches use: each entry remembers the identities of every file it was built
from (a shader and all its includes, an image, a mesh) and is rebuilt when any of them
changed, so editing an input between two renders in one process gives the new result.
"""

from __future__ import annotations

import os
import re
from collections import OrderedDict
from pathlib import Path
from typing import Callable, Iterable

from . import safe_paths

_INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)


def file_key(path) -> tuple:
    """(resolved path, size, mtime_ns, inode); (resolved path, None) when it cannot be stat'ed."""
    resolved = os.path.realpath(path)
    try:
        st = os.stat(resolved)
    except OSError:
        return (resolved, None)
    return (resolved, st.st_size, st.st_mtime_ns, st.st_ino)


def followed_key(path) -> tuple | None:
    """(device, inode, size, mtime_ns) of the file or folder ``path`` leads to, None when it
    cannot be stat'ed: file_key without resolving the path first (ten times cheaper; a link
    retargeted still leads to another inode), for caches that check hundreds of paths a use."""
    try:
        st = os.stat(path)
    except OSError:
        return None
    return (st.st_dev, st.st_ino, st.st_size, st.st_mtime_ns)


def fingerprint(paths: Iterable, identity: Callable = file_key) -> tuple:
    return tuple(identity(p) for p in paths)


def include_closure(text: str, search_dirs: Iterable, here: Path | None = None) -> list[Path]:
    """Every file reachable through ``#include "..."`` from ``text`` (an over-approximation:
    includes inside inactive ``#if`` blocks count too), resolved like glslang and our
    expander: the including file's folder, then ``search_dirs`` in order."""
    search = tuple(Path(d) for d in search_dirs)
    found: list[Path] = []
    pending = [_resolved_includes(text.removeprefix("\ufeff"), here, search)]
    while pending:
        for resolved in pending.pop():
            if resolved not in found:
                found.append(resolved)
                pending.append(_file_includes(resolved, search))
    return found


def _resolved_includes(body: str, folder: Path | None, search: tuple) -> list[Path]:
    """The resolved file of each ``#include`` of ``body`` that names a file, in order: from the
    first folder of ``folder`` then ``search`` that holds it, read through links that stay in
    that folder only (safe_paths)."""
    out = []
    for name in _INCLUDE.findall(body):
        for directory in ([folder] if folder else []) + list(search):
            if (directory / name).is_file():
                resolved = safe_paths.inside(directory, name, f'#include "{name}" (searched in {directory})',
                                             climb=True)
                out.append(resolved)
                break
    return out


def _file_includes(path: Path, search: tuple) -> list[Path]:
    """_resolved_includes of the file ``path`` (from its folder), kept per process
    (``_FILE_INCLUDES``) and found again when the file or a folder it was looked for in
    changed: each pass of a many-pass shader reaches the same include files (a 256-pass Amplify
    preview: ~0.27 s a stage to resolve them all again, over two minutes a render)."""
    key = (str(path), tuple(map(str, search)), safe_paths.reading_rules())

    def build():
        try:
            # a leading byte-order mark would hide a first-line #include
            body = path.read_text(encoding="utf-8", errors="replace").removeprefix("\ufeff")
        except OSError:
            return [], [path]  # (found, and read no further)
        names = _INCLUDE.findall(body)
        looked = [(directory / name).parent for name in names for directory in (path.parent, *search)]
        return _resolved_includes(body, path.parent, search), [path, *looked]

    return _FILE_INCLUDES.get(key, build)


class FileCache:
    """An LRU of at most ``size`` entries, each rebuilt when a file it depends on changed.

    ``get(key, build)``: ``build()`` returns ``(value, paths)`` (paths None: the value is not
    kept); ``evict(value)`` runs for
    every entry dropped (by age or because it went stale); ``identity`` tells a path's state
    (file_key, or followed_key).
    """

    def __init__(self, size: int, evict: Callable | None = None, identity: Callable = file_key):
        self.size, self.evict, self.identity = size, evict, identity
        self.entries: OrderedDict = OrderedDict()
        self.builds = 0  # how many times an entry was made (first use or stale)

    def __len__(self):
        return len(self.entries)

    def get(self, key, build):
        entry = self.entries.get(key)
        if entry is not None:
            value, paths, stamp = entry
            if fingerprint(paths, self.identity) == stamp:
                self.entries.move_to_end(key)
                return value
            self._drop(key)
        value, paths = build()
        self.builds += 1
        if paths is None:  # an answer not to keep
            return value
        paths = tuple(dict.fromkeys(paths))  # a file included twice is checked once
        self.entries[key] = (value, paths, fingerprint(paths, self.identity))
        while len(self.entries) > self.size:
            self._drop(next(iter(self.entries)))
        return value

    def _drop(self, key):
        value = self.entries.pop(key)[0]
        if self.evict is not None:
            self.evict(value)

    def items(self):
        """(key, value) of every entry, oldest first."""
        return [(key, entry[0]) for key, entry in self.entries.items()]

    def clear(self):
        for key in list(self.entries):
            self._drop(key)


# _file_includes' answers, one per include file and search path (a URP program reaches ~100
# files): a few paths each.
FILE_INCLUDES_CACHED = 1024
_FILE_INCLUDES = FileCache(FILE_INCLUDES_CACHED, identity=followed_key)
