"""pbrlab.foundation.disk_cache: entries by key, whole or absent, damaged ones dropped; and its users
(meshes, the prefiltered environment) give the same data from the cache as without it."""

from __future__ import annotations

import numpy as np
import pytest

from pbrlab.foundation import disk_cache
from pbrlab.scene import meshes
from pbrlab.scene import parse_scene


@pytest.fixture
def cache(tmp_path, monkeypatch):
    monkeypatch.setenv(disk_cache.ENV_VAR, str(tmp_path / "cache"))
    return tmp_path / "cache"


def test_store_then_load(cache):
    name = disk_cache.key("test", b"\x00\x01", 3, ("a", 1.5))
    assert disk_cache.load("test", name) is None
    assert disk_cache.store("test", name, b"payload")
    assert disk_cache.load("test", name) == b"payload"
    assert not [p for p in cache.rglob(".*")]  # no temporary file left beside it


def test_keys_differ_when_any_part_does():
    base = disk_cache.key("mesh", b"abc", "1.0")
    assert base != disk_cache.key("mesh", b"abd", "1.0")
    assert base != disk_cache.key("mesh", b"abc", "1.1")
    assert disk_cache.key("ab", "c") != disk_cache.key("a", "bc")  # parts are length-prefixed


@pytest.mark.parametrize("damage", ["truncate", "flip", "foreign"])
def test_a_damaged_entry_reads_as_missing_and_is_removed(cache, damage):
    name = disk_cache.key("test", "damaged")
    disk_cache.store("test", name, b"x" * 100)
    path = next(p for p in cache.rglob(name))
    data = path.read_bytes()
    path.write_bytes({"truncate": data[:-10], "flip": data[:-1] + b"y", "foreign": b"not a cache entry"}[damage])
    assert disk_cache.load("test", name) is None
    assert not path.exists()


def test_off_and_unwritable(tmp_path, monkeypatch):
    monkeypatch.setenv(disk_cache.ENV_VAR, disk_cache.OFF)
    assert disk_cache.cache_dir() is None
    assert not disk_cache.store("test", "ab", b"x") and disk_cache.load("test", "ab") is None
    blocker = tmp_path / "file"
    blocker.write_text("a file where the folder would go")
    monkeypatch.setenv(disk_cache.ENV_VAR, str(blocker))
    assert not disk_cache.store("test", "ab", b"x")  # nothing kept, no error


def _scene(mesh):
    return parse_scene({"camera": {"position": [0, 0, 4], "target": [0, 0, 0]}, "materials": {"m": {}},
                        "objects": [{"mesh": mesh, "material": "m"}]}, base=".")


@pytest.mark.parametrize("mesh", [{"primitive": "torus", "minor_radius": 0.2}, {"primitive": "icosphere"}])
def test_mesh_arrays_from_the_cache_equal_those_from_trimesh(cache, mesh):
    obj = _scene(mesh).objects[0]
    made = meshes._prepared_mesh(obj)      # through trimesh, then kept
    kept = meshes._prepared_mesh(obj)      # from the disk cache
    assert any(cache.rglob("*"))
    assert made[1] == kept[1]
    for a, b in zip(made[0], kept[0], strict=True):
        assert a.dtype == b.dtype and np.array_equal(a, b)


def test_an_edited_mesh_file_is_read_again(cache, tmp_path):
    path = tmp_path / "tri.obj"
    path.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
    obj = _scene(str(path)).objects[0]
    first = meshes._prepared_mesh(obj)
    path.write_text("v 0 0 0\nv 2 0 0\nv 0 1 0\nf 1 2 3\n")
    second = meshes._prepared_mesh(obj)
    assert first[0][0][1, 0] == 1.0 and second[0][0][1, 0] == 2.0
