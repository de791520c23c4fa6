"""pbrlab.gpu.source_cache: an expansion from the disk cache equals a fresh one, and any change to
what it was made from (an included file edited, a file that now shadows it, a new file where
a missing include was looked for) gives a fresh expansion."""

from __future__ import annotations

import os

import pytest

from pbrlab.foundation import disk_cache
from pbrlab.gpu import shaders, source_cache

OLD_NS = 1_600_000_000 * 10**9  # a modification time long past: the inputs have settled


@pytest.fixture
def folders(tmp_path, monkeypatch):
    monkeypatch.setenv(disk_cache.ENV_VAR, str(tmp_path / "cache"))
    first, second = tmp_path / "first", tmp_path / "second"
    (second / "my").mkdir(parents=True)
    first.mkdir()
    write(second / "my" / "term.glsl", "float my_term() { return 1.0; }\n")
    return first, second


def write(path, text, age_ns=OLD_NS):
    path.write_text(text)
    os.utime(path, ns=(age_ns, age_ns))


ENTRY = '#version 330\n#include "my/term.glsl"\n#include "pbr/common/math.glsl"\nvoid main() {}\n'


def hits(monkeypatch) -> list:
    """Calls of shaders.expand from here on (a miss expands; a hit does not)."""
    calls = []
    real = shaders.expand
    monkeypatch.setattr(shaders, "expand", lambda *a, **k: calls.append(a) or real(*a, **k))
    return calls


def test_a_cached_expansion_equals_a_fresh_one(folders, monkeypatch):
    fresh = shaders.expand(ENTRY, "entry", include_dirs=folders)
    calls = hits(monkeypatch)
    first = source_cache.expand(ENTRY, "entry", folders)
    second = source_cache.expand(ENTRY, "entry", folders)
    assert len(calls) == 1  # the second came from the cache
    for got in (first, second):
        assert (got.text, got.files, got.paths) == (fresh.text, fresh.files, fresh.paths)


@pytest.mark.parametrize("change", ["edit the include", "shadow it in an earlier folder", "delete it"])
def test_a_changed_input_gives_a_fresh_expansion(folders, monkeypatch, change):
    first, second = folders
    source_cache.expand(ENTRY, "entry", folders)
    calls = hits(monkeypatch)
    if change == "edit the include":
        # the same size, in place (same inode): the modification time tells (file_identity)
        write(second / "my" / "term.glsl", "float my_term() { return 2.0; }\n", OLD_NS + 10**9)
    elif change == "shadow it in an earlier folder":
        (first / "my").mkdir()
        write(first / "my" / "term.glsl", "float my_term() { return 3.0; }\n")
    else:
        (second / "my" / "term.glsl").unlink()
    if change == "delete it":
        with pytest.raises(shaders.PbrlabError, match="cannot find include"):
            source_cache.expand(ENTRY, "entry", folders)
        return
    again = source_cache.expand(ENTRY, "entry", folders)
    assert len(calls) == 1
    assert again.text == shaders.expand(ENTRY, "entry", include_dirs=folders).text


def test_inputs_modified_moments_ago_are_not_kept(folders, monkeypatch):
    first, second = folders
    (second / "my" / "term.glsl").write_text("float my_term() { return 4.0; }\n")  # mtime: now
    source_cache.expand(ENTRY, "entry", folders)
    calls = hits(monkeypatch)
    source_cache.expand(ENTRY, "entry", folders)
    assert len(calls) == 1
