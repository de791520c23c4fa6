"""pbrlab.importers.loader, the loader above the scene model and the glTF importer."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from pbrlab.importers import gltf, loader as scene_files
from pbrlab.scene import model as scene
from pbrlab.foundation.errors import SceneError

ASSETS = Path(__file__).resolve().parents[2] / "scenes" / "gltf"


def test_gltf_suffixes_agree_with_the_importer():
    assert scene_files.GLTF_SUFFIXES == gltf.SUFFIXES


def test_the_scene_model_refuses_a_gltf_object_without_a_reader_and_names_the_field(tmp_path):
    data = {"camera": {"position": [0, 0, 3], "target": [0, 0, 0]},
            "objects": [{"gltf": str(ASSETS / "hierarchy_lights.glb")}]}
    with pytest.raises(SceneError, match=r"objects\[0\]\.gltf: a glTF object needs the glTF reader"):
        scene.parse_scene(data, "s.json")
    assert len(scene_files.parse_scene(data, "s.json").objects) > 0


def test_load_scene_picks_the_reader_by_the_file(tmp_path):
    glb = scene_files.load_scene(ASSETS / "hierarchy_lights.glb")
    path = tmp_path / "s.json"
    path.write_text(json.dumps({"objects": [{"gltf": str(ASSETS / "hierarchy_lights.glb")}]}))
    placed = scene_files.load_scene(path)
    assert len(placed.objects) == len(glb.objects)
