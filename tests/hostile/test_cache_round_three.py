"""Issue 39 (round three), the disk cache trusts nothing (pbrlab.foundation.disk_cache).

Each case puts a hostile entry exactly where a user of the cache looks (the mesh reader,
the expanded-source cache, the prefiltered environment) and then asks that user for its
value. Allowed outcomes: the right value, with the bad entry removed and a
BadCacheEntryWarning naming it ("handled"). A traceback, a hang or a wrong value fails.

Before the fix (main at d2cf9f0), every case here failed: garbage under a valid checksum
raised from numpy's or json's reader, a mesh entry under an environment's key raised
TypeError, an older format's entry was believed, and a FIFO entry blocked the reader until
the test's time limit.
"""

from __future__ import annotations

import hashlib
import os
import shutil
import subprocess
import sys
import textwrap
import warnings
from pathlib import Path

import numpy as np
import pytest

from hostile_common import base_scene
from pbrlab.foundation import disk_cache
from pbrlab.gpu import source_cache
from pbrlab.scene import meshes, parse_scene

HARNESS = Path(__file__).resolve().parents[2] / "harness"
# A reader that does not hang returns in well under a second; a hung one waits for ever.
# 60 s is the time a cold interpreter needs to import pbrlab and numpy on a loaded 2-core
# machine (measured 3 to 8 s) with room, not a measure of the read.
SUBPROCESS_LIMIT_S = 60


@pytest.fixture
def cache(tmp_path, monkeypatch):
    monkeypatch.setenv(disk_cache.ENV_VAR, str(tmp_path / "cache"))
    return tmp_path / "cache"


def _box():
    return parse_scene({"camera": {"position": [0, 0, 4], "target": [0, 0, 0]}, "materials": {"m": {}},
                        "objects": [{"mesh": {"primitive": "box", "size": 1.0}, "material": "m"}]},
                       base=".").objects[0]


def _only_entry(cache: Path, kind: str) -> Path:
    entries = [p for p in (cache / kind).rglob("*") if p.is_file() and not p.name.startswith(".")]
    assert len(entries) == 1, entries
    return entries[0]


# main before issue 39 had no such warning: a stand-in no warning is, so the before run fails there
BAD_ENTRY = getattr(disk_cache, "BadCacheEntryWarning", type("NoSuchWarning", (UserWarning,), {}))


def _expect_recomputed(call, reference, same):
    """``call()`` warns BadCacheEntryWarning and returns what ``reference`` is."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        value = call()
    assert any(issubclass(w.category, BAD_ENTRY) for w in caught), \
        [str(w.message) for w in caught]
    assert same(value, reference)


def _same_mesh(a, b):
    return a[1] == b[1] and all(x.dtype == y.dtype and np.array_equal(x, y) for x, y in zip(a[0], b[0], strict=True))


def _forge(path: Path, kind: str, name: str, payload: bytes):
    """An entry with a valid checksum and the right header around ``payload``: what only a
    deliberate forger (or a bug in a writer) could make."""
    header = getattr(disk_cache, "_header", None)  # main before issue 39: no header (for the before run)
    body = (header(kind, name) if header else b"") + payload
    path.write_bytes(disk_cache._MAGIC + hashlib.sha256(body).digest() + body)


GARBAGE = {
    "not npy": b"\x00garbage" * 100,
    "npy header claiming 2^40 floats": disk_cache.pack_arrays([np.zeros(4, np.float32)]).replace(b"(4,)", b"(1099511627776,)"),
    "five arrays, not six": disk_cache.pack_arrays([np.zeros((3, 3), np.float32)] * 5),
    "indices past the vertices": disk_cache.pack_arrays(
        [np.zeros((3, 3), np.float32), np.zeros((3, 3), np.float32), np.zeros((3, 2), np.float32),
         np.zeros((3, 4), np.float32), np.array([0, 1, 7], np.int32), np.float64(1.0)]),
}


@pytest.mark.parametrize("garbage", GARBAGE, ids=list(GARBAGE))
def test_a_mesh_entry_of_garbage_under_a_valid_checksum_is_recomputed(cache, garbage, census):
    obj = _box()
    reference = meshes._prepared_mesh(obj)
    path = _only_entry(cache, "mesh")
    _forge(path, "mesh", path.name, GARBAGE[garbage])
    _expect_recomputed(lambda: meshes._prepared_mesh(obj), reference, _same_mesh)
    assert disk_cache.load("mesh", path.name) is not None  # the recomputed value was kept again
    census["cache round three", "handled"] += 1


def _expansion(tmp_path):
    folder = tmp_path / "inc"
    folder.mkdir(exist_ok=True)
    (folder / "a.glsl").write_text("float a() { return 1.0; }\n")
    os.utime(folder / "a.glsl", ns=(0, 0))  # settled: source_cache keeps it
    return lambda: source_cache.expand('#include "a.glsl"\nvoid main() {}\n', "entry.frag", [folder])


@pytest.mark.parametrize("payload", [b"\xff\xfe not json", b'{"text": 3}', b"[1, 2]",
                                     b'{"text": "", "files": [], "paths": [], "inputs": [[1]]}'])
def test_an_expanded_source_entry_of_garbage_is_recomputed(cache, tmp_path, payload, census):
    expand = _expansion(tmp_path)
    reference = expand()
    path = _only_entry(cache, source_cache.KIND)
    _forge(path, source_cache.KIND, path.name, payload)
    _expect_recomputed(expand, reference, lambda a, b: a.text == b.text and a.files == b.files)
    census["cache round three", "handled"] += 1


def test_a_mesh_entry_swapped_in_for_an_expanded_source_is_refused(cache, tmp_path, census):
    expand = _expansion(tmp_path)
    reference = expand()
    meshes._prepared_mesh(_box())
    shutil.copyfile(_only_entry(cache, "mesh"), _only_entry(cache, source_cache.KIND))
    _expect_recomputed(expand, reference, lambda a, b: a.text == b.text)
    census["cache round three", "handled"] += 1


def test_an_expanded_source_entry_swapped_in_for_a_mesh_is_refused(cache, tmp_path, census):
    obj = _box()
    reference = meshes._prepared_mesh(obj)
    _expansion(tmp_path)()
    shutil.copyfile(_only_entry(cache, source_cache.KIND), _only_entry(cache, "mesh"))
    _expect_recomputed(lambda: meshes._prepared_mesh(obj), reference, _same_mesh)
    census["cache round three", "handled"] += 1


def test_an_entry_of_one_key_copied_under_another_is_refused(cache, tmp_path, census):
    """Two meshes' entries, one copied over the other: same kind, valid checksum, the wrong
    key; main handed back the torus for the box (a silently wrong mesh)."""
    box = _box()
    reference = meshes._prepared_mesh(box)
    box_entry = _only_entry(cache, "mesh")
    torus = parse_scene({"camera": {"position": [0, 0, 4], "target": [0, 0, 0]}, "materials": {"m": {}},
                         "objects": [{"mesh": {"primitive": "torus"}, "material": "m"}]}, base=".").objects[0]
    meshes._prepared_mesh(torus)
    torus_entry = next(p for p in (cache / "mesh").rglob("*") if p.is_file() and p != box_entry)
    shutil.copyfile(torus_entry, box_entry)
    _expect_recomputed(lambda: meshes._prepared_mesh(box), reference, _same_mesh)
    census["cache round three", "handled"] += 1


def test_an_entry_of_the_older_format_is_not_believed(cache, census):
    """An entry as pbrlab-cache/1 wrote it (magic, digest, payload; no kind, key or
    version), holding a valid mesh that is not this one: never read as this key's."""
    obj = _box()
    reference = meshes._prepared_mesh(obj)
    path = _only_entry(cache, "mesh")
    wrong = disk_cache.pack_arrays([np.zeros((3, 3), np.float32), np.zeros((3, 3), np.float32),
                                    np.zeros((3, 2), np.float32), np.zeros((3, 4), np.float32),
                                    np.array([0, 1, 2], np.int32), np.float64(0.0)])
    path.write_bytes(b"pbrlab-cache/1\n" + hashlib.sha256(wrong).digest() + wrong)
    _expect_recomputed(lambda: meshes._prepared_mesh(obj), reference, _same_mesh)
    census["cache round three", "handled"] += 1


def test_an_entry_of_another_version_is_not_believed(cache, monkeypatch, census):
    obj = _box()
    reference = meshes._prepared_mesh(obj)
    path = _only_entry(cache, "mesh")
    with monkeypatch.context() as patch:
        patch.setattr(disk_cache, "__version__", "0.0.1-other")
        _forge(path, "mesh", path.name, disk_cache.pack_arrays([*reference[0], np.float64(reference[1] + 1)]))
    _expect_recomputed(lambda: meshes._prepared_mesh(obj), reference, _same_mesh)
    census["cache round three", "handled"] += 1


def test_a_mesh_entry_swapped_in_for_a_prefiltered_environment_is_refused(cache, gl_context, census):
    from pbrlab.gpu import ibl

    image = np.full((32, 64, 3), 0.5, np.float32)
    image[4:8, 10:14] = 20.0
    name = ibl._prefilter_cache_key(gl_context, image)
    reference = ibl._prefilter_levels(gl_context, image)
    meshes._prepared_mesh(_box())
    path = cache / "prefiltered-environment" / name[:2] / name
    path.parent.mkdir(parents=True)
    shutil.copyfile(_only_entry(cache, "mesh"), path)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        ibl.prefiltered_environment(gl_context, image).release()
    assert any(issubclass(w.category, BAD_ENTRY) for w in caught)
    levels = disk_cache.load("prefiltered-environment", name, ibl._decode_levels)
    assert levels is not None and all(np.array_equal(a, b) for a, b in zip(levels, reference, strict=True))
    census["cache round three", "handled"] += 1


def _read_in_subprocess(cache: Path, tmp_path: Path):
    """Expand a shader through the source cache in a fresh process (the entry already in
    place) and return (exit status, output); a hang is a TimeoutExpired."""
    script = textwrap.dedent(f"""
        import warnings
        warnings.simplefilter("always")
        from pbrlab.gpu import source_cache
        source = source_cache.expand('#include "a.glsl"\\nvoid main() {{}}\\n', "entry.frag", [{str(tmp_path / 'inc')!r}])
        print("EXPANDED", "float a()" in source.text)
    """)
    env = dict(os.environ, PYTHONPATH=str(HARNESS), **{disk_cache.ENV_VAR: str(cache)})

    def limit_memory():  # a reader of /dev/zero would otherwise take the machine's memory
        import resource
        resource.setrlimit(resource.RLIMIT_AS, (2 << 30, 2 << 30))

    proc = subprocess.run([sys.executable, "-c", script], env=env, capture_output=True, text=True,
                          timeout=SUBPROCESS_LIMIT_S, preexec_fn=limit_memory)
    return proc.returncode, proc.stdout + proc.stderr


@pytest.mark.parametrize("thing", ["fifo", "link to /dev/zero", "folder"])
def test_an_entry_that_is_not_a_regular_file_does_not_hang(cache, tmp_path, thing, census):
    _expansion(tmp_path)()
    path = _only_entry(cache, source_cache.KIND)
    path.unlink()
    if thing == "fifo":
        os.mkfifo(path)
    elif thing == "folder":
        path.mkdir()
    else:
        path.symlink_to("/dev/zero")
    try:
        status, output = _read_in_subprocess(cache, tmp_path)
    except subprocess.TimeoutExpired:
        pytest.fail(f"reading a {thing} cache entry hung for {SUBPROCESS_LIMIT_S} s")
    assert status == 0 and "EXPANDED True" in output, output
    assert "Traceback" not in output
    assert "BadCacheEntryWarning" in output, output
    census["cache round three", "handled"] += 1


def test_an_entry_over_the_size_limit_is_not_read(cache, tmp_path, monkeypatch, census):
    expand = _expansion(tmp_path)
    reference = expand()
    path = _only_entry(cache, source_cache.KIND)
    monkeypatch.setattr(disk_cache, "MAX_ENTRY_BYTES", path.stat().st_size - 1)
    _expect_recomputed(expand, reference, lambda a, b: a.text == b.text)
    census["cache round three", "handled"] += 1


def test_a_damaged_entry_in_a_render_only_warns(cache, tmp_path, gl_context, census):
    """End to end: a scene with a mesh rendered twice, the mesh's entry replaced by garbage
    under a valid checksum in between: the same image, and a warning."""
    from pbrlab.render.renderer import render_scene

    scene = base_scene()
    scene["camera"]["size"] = [16, 12]
    first = render_scene(parse_scene(scene, base=tmp_path), gl_context).linear
    path = _only_entry(cache, "mesh")
    _forge(path, "mesh", path.name, GARBAGE["not npy"])
    meshes._MESH_DATA.clear()  # the process's own copy would hide the disk entry
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        second = render_scene(parse_scene(scene, base=tmp_path), gl_context).linear
    assert any(issubclass(w.category, BAD_ENTRY) for w in caught)
    np.testing.assert_array_equal(first, second)
    census["cache round three", "handled"] += 1
