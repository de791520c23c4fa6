"""Renders share what they read: the environment's prefilter and SH9, material textures and
mesh data are made once per file version, and a rewritten file is read again."""

import os

import numpy as np
import pytest

from pbrlab.gpu import ibl
from pbrlab.foundation import images
from pbrlab.scene import meshes
from pbrlab.render import resource_cache
from pbrlab.render.renderer import render_scene
from pbrlab.scene import parse_scene

from render_scenes import one_sphere


def _count_calls(monkeypatch, module, name):
    calls = []
    original = getattr(module, name)

    def counted(*args, **kwargs):
        calls.append(args)
        return original(*args, **kwargs)
    monkeypatch.setattr(module, name, counted)
    return calls


def _textured_scene(tmp_path, albedo_png, environment_exr):
    scene = one_sphere({"albedo": [1, 1, 1], "smoothness": 0.5, "textures": {"albedo": str(albedo_png)}},
                       [{"type": "directional", "direction": [0, 0, -1]}], size=(24, 24),
                       environment={"path": str(environment_exr)})
    scene["objects"].append({"mesh": {"primitive": "box", "size": 0.5}, "material": "m",
                             "transform": {"translate": [1.2, 0, 1.2]}})
    return scene


def _write_inputs(tmp_path, albedo_level, sky_level):
    albedo = tmp_path / "albedo.png"
    sky = tmp_path / "sky.exr"
    images.write_png(albedo, np.full((4, 4, 4), albedo_level, np.uint8))
    images.write_exr(sky, np.full((8, 16, 3), sky_level, np.float32))
    return albedo, sky


def test_second_render_reads_and_prefilters_nothing(tmp_path, gl_context, monkeypatch):
    monkeypatch.setenv("PBRLAB_CACHE_DIR", str(tmp_path / "cache"))  # empty: no earlier process's meshes
    albedo, sky = _write_inputs(tmp_path, 200, 0.5)
    scene = _textured_scene(tmp_path, albedo, sky)
    reads = _count_calls(monkeypatch, resource_cache, "read_image")
    prefilters = _count_calls(monkeypatch, ibl, "prefiltered_environment")
    mesh_loads = _count_calls(monkeypatch, meshes, "load_mesh")
    first = render_scene(parse_scene(scene), gl_context)
    counts = (len(reads), len(prefilters), len(mesh_loads))
    assert counts == (1, 1, 1)  # the texture; the sky (read by environment.py); the box
    second = render_scene(parse_scene(scene), gl_context)
    assert (len(reads), len(prefilters), len(mesh_loads)) == counts
    np.testing.assert_array_equal(second.linear, first.linear)


def test_rewritten_files_are_read_again(tmp_path, gl_context):
    albedo, sky = _write_inputs(tmp_path, 200, 0.5)
    scene = _textured_scene(tmp_path, albedo, sky)
    before = render_scene(parse_scene(scene), gl_context).linear
    _write_inputs(tmp_path, 90, 2.0)
    for path in (albedo, sky):  # a rewrite within the clock's resolution still moves mtime
        stat = path.stat()
        os.utime(path, ns=(stat.st_atime_ns, stat.st_mtime_ns + 1_000_000))
    after = render_scene(parse_scene(scene), gl_context).linear
    assert not np.allclose(after, before)
    gl_context.extra.pop(resource_cache._EXTRA_KEY)  # nothing cached: everything read anew
    meshes._MESH_DATA.clear()
    np.testing.assert_array_equal(render_scene(parse_scene(scene), gl_context).linear, after)


def test_evicted_textures_are_released(gl_context, monkeypatch):
    monkeypatch.setattr(resource_cache, "TEXTURES_PER_CONTEXT", 2)
    cache = resource_cache.ContextCache(gl_context)
    textures = [cache.constant_texture((i, 0, 0, 1)) for i in range(3)]
    assert cache.constant_texture((2, 0, 0, 1)) is textures[2]
    with pytest.raises(AttributeError, match="InvalidObject"):
        textures[0].use(0)  # released: moderngl swapped its GL object for InvalidObject
    cache.constant_texture((1, 0, 0, 1)).use(0)


def test_mesh_data_is_read_only(gl_context):
    obj = parse_scene(_textured_scene_plain()).objects[1]
    positions = meshes.mesh_data(obj).arrays[0]
    with pytest.raises(ValueError):
        positions[0, 0] = 1.0


def _textured_scene_plain():
    scene = one_sphere({"albedo": [1, 1, 1]}, [])
    scene["objects"].append({"mesh": {"primitive": "box", "size": 0.5}, "material": "m"})
    return scene
