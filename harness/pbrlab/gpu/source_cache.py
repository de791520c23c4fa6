"""Expanded harness shaders kept on disk between processes, checked by file identity.

A render expands a dozen templates, each through some thirty library files (issue 25: 0.35 s
of a 2 s start-up before the expander got faster, still 0.05 s after). ``expand`` keeps
each expansion in the disk cache (pbrlab.foundation.disk_cache) under a key naming the template's text,
its name, the include path and this code; the entry lists the identity (file_identity) of
every file the expansion read and of every place an include was looked for, found or not.
An entry is used only when every one of them is unchanged, so editing a library file,
adding one that shadows another, or deleting one gives a new expansion: never a stale one.
An input modified in the two seconds before it was read is not kept (a write may still be
under way, and coarse file clocks may not move).
"""

from __future__ import annotations

import json
import time
from pathlib import Path

from ..foundation import disk_cache
from . import shaders
from ..foundation.file_identity import file_key

KIND = "expanded-source"
SETTLED_NS = 2_000_000_000  # an input younger than this is not trusted to have its final text
_CODE = (Path(shaders.__file__).read_bytes(), Path(__file__).read_bytes())


def _decode_entry(payload: bytes) -> dict:
    """An entry as ``expand`` wrote it (JSON: text, files, paths, inputs); ValueError or
    TypeError when the payload is anything else."""
    entry = json.loads(payload)
    if not (isinstance(entry, dict) and isinstance(entry.get("text"), str)
            and all(isinstance(entry.get(name), list) and all(isinstance(item, str) for item in entry[name])
                    for name in ("files", "paths"))
            and isinstance(entry.get("inputs"), list)
            and all(isinstance(item, list) and len(item) == 2 and isinstance(item[0], str)
                    and isinstance(item[1], list) for item in entry["inputs"])):
        raise ValueError("not an expanded-source entry (text, files, paths, inputs)")
    return entry


def expand(text: str, name: str, include_dirs=()) -> shaders.Source:
    """``shaders.expand(text, name, include_dirs)``, from the disk cache when still valid."""
    search = [str(d) for d in shaders.include_path(include_dirs)]
    key = disk_cache.key(KIND, text, name, search, *_CODE)
    entry = disk_cache.load(KIND, key, _decode_entry)
    if entry is not None:
        if all(list(file_key(path)) == identity for path, identity in entry["inputs"]):
            return shaders.Source(entry["text"], entry["files"], [Path(p) for p in entry["paths"]])
    source = shaders.expand(text, name, include_dirs=include_dirs)
    inputs = [(path, file_key(path)) for path in dict.fromkeys(map(str, [*source.paths, *source.probed]))]
    now = time.time_ns()
    if all(identity[1] is None or now - identity[2] > SETTLED_NS for _, identity in inputs):
        disk_cache.store(KIND, key, json.dumps({
            "text": source.text, "files": source.files, "paths": [str(p) for p in source.paths],
            "inputs": [[path, list(identity)] for path, identity in inputs]}).encode("utf-8"))
    return source
