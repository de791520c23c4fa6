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


def fingerprint(paths: Iterable) -> tuple:
    return tuple(file_key(p) for p in paths)


def include_closure(text: str, search_dirs: Iterable, here: Path | None = None) -> list[Path]:
    """Every file reachable through ``#include "..."`` from ``text`` (an over-approximation:
    includes inside inactive ``#if`` blocks count too), resolved like glslang and our
    expander: the including file's folder, then ``search_dirs`` in order."""
    search = [Path(d) for d in search_dirs]
    found: list[Path] = []
    pending = [(text.removeprefix("\ufeff"), here)]
    while pending:
        body, folder = pending.pop()
        for name in _INCLUDE.findall(body):
            for directory in ([folder] if folder else []) + search:
                candidate = directory / name
                if candidate.is_file():  # through links that stay in its folder only (safe_paths)
                    resolved = safe_paths.inside(directory, name, f'#include "{name}" (searched in {directory})',
                                                 climb=True)
                    if resolved not in found:
                        found.append(resolved)
                        try:
                            body = resolved.read_text(encoding="utf-8", errors="replace")
                            # a leading byte-order mark would hide a first-line #include
                            pending.append((body.removeprefix("\ufeff"), resolved.parent))
                        except OSError:
                            pass
                    break
    return found


class FileCache:
    """An LRU of at most ``size`` entries, each rebuilt when a file it depends on changed.

    ``get(key, build)``: ``build()`` returns ``(value, paths)``; ``evict(value)`` runs for
    every entry dropped (by age or because it went stale).
    """

    def __init__(self, size: int, evict: Callable | None = None):
        self.size, self.evict = size, evict
        self.entries: OrderedDict = OrderedDict()
        self.builds = 0  # how many times an entry was made (first use or stale)

    def __len__(self):
        return len(self.entries)

    def get(self, key, build):
        entry = self.entries.get(key)
        if entry is not None:
            value, paths, stamp = entry
            if fingerprint(paths) == stamp:
                self.entries.move_to_end(key)
                return value
            self._drop(key)
        value, paths = build()
        self.builds += 1
        paths = tuple(dict.fromkeys(paths))  # a file included twice is checked once
        self.entries[key] = (value, paths, fingerprint(paths))
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
