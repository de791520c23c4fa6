"""Scene files of every format, read by the one loader that sits above the scene model and
the importers (docs/layers.md): a JSON scene (pbrlab.scene.model), whose objects may take in whole
glTF files, or a glTF 2.0 file itself (pbrlab.importers.gltf). The scene model never imports an
importer; this module hands ``scene`` the glTF reader, and loads it only when a file needs it.

    scene = load_scene("scenes/unity_example/scene.json")   # or "model.glb"
    scene = parse_scene({...}, base=folder)                  # JSON data, glTF objects allowed
"""

from __future__ import annotations

from pathlib import Path

from ..scene import model as scene_model

# The suffixes of glTF files (gltf.SUFFIXES; tests/harness/test_layers.py checks both agree),
# here so that choosing the reader does not import the glTF importer.
GLTF_SUFFIXES = (".gltf", ".glb")


def is_gltf(path) -> bool:
    """A glTF 2.0 file (.gltf or .glb), by its name."""
    return Path(path).suffix.lower() in GLTF_SUFFIXES


def read_gltf(path):
    """``gltf.load_gltf(path)``: what a JSON scene's ``{"gltf": ...}`` object takes in."""
    from .gltf import load_gltf
    return load_gltf(path)


def parse_scene(data, origin: str = "<scene>", base: Path | None = None) -> scene_model.Scene:
    """``scene.parse_scene`` with glTF objects read."""
    return scene_model.parse_scene(data, origin, base, read_gltf=read_gltf)


def load_scene(path) -> scene_model.Scene:
    """A scene file: glTF by its suffix (its default scene and camera, the environment and
    render settings of its ``<model>.pbrlab.json`` beside it, as ``pbrlab render`` reads
    it), else a JSON scene."""
    if is_gltf(path):
        from .gltf import load_gltf
        from .gltf.settings import read_settings

        environment, render = read_settings(Path(path))
        return load_gltf(path, environment=environment, render=render).scene
    return scene_model.load_scene(path, read_gltf=read_gltf)
