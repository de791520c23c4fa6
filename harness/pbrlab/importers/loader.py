"""Scene files of every format, read by the one loader that sits above the scene model and
the importers (docs/layers.md): a JSON scene (pbrlab.scene.model), whose objects may take in
whole glTF files and whose materials may name Unity shaders, or a glTF 2.0 file itself
(pbrlab.importers.gltf). The scene model never imports an importer; this module hands it the
glTF reader and the Unity shader reader, and loads each only when a file needs it.

    scene = load_scene("scenes/unity_example/scene.json")   # or "model.glb", or "X.shader" (on a sphere)
    scene = parse_scene({...}, base=folder)                  # JSON data, glTF objects and Unity shaders allowed
"""

from __future__ import annotations

from pathlib import Path

from ..foundation import safe_paths
from ..foundation.errors import SceneError
from ..scene import model as scene_model

# The suffixes of glTF files (gltf.SUFFIXES; tests/importers/test_loader.py checks both agree),
# here so that choosing the reader does not import the glTF importer.
GLTF_SUFFIXES = (".gltf", ".glb")


def is_gltf(path) -> bool:
    """A glTF 2.0 file (.gltf or .glb), by its name."""
    return Path(path).suffix.lower() in GLTF_SUFFIXES


def read_gltf(path, **options):
    """``gltf.load_gltf(path, time=, animation=)``: what a JSON scene's ``{"gltf": ...}``
    object takes in."""
    from .gltf import load_gltf
    return load_gltf(path, **options)


def _may_be_unity(path: Path) -> bool:
    """False when ``path`` cannot be a Unity shader (a ``.shader`` file or a ``#pragma surface``
    line): a GLSL surface without the word "pragma" is told apart without the Unity reader."""
    try:
        return path.suffix == ".shader" or b"pragma" in path.read_bytes()
    except OSError:
        return True  # let the reader say what is wrong


class _ShaderMaterials:
    """The scene model's reader of materials whose surface is another engine's shader: a Unity
    shader for the Universal Render Pipeline (importers/urp/) or the built-in one
    (importers/unity/), loaded only when a surface file may be one."""

    def reads(self, path: Path) -> bool:
        return _may_be_unity(path) and self._unity().reads(path)

    def read_material(self, reader, material, base: Path) -> None:
        from .urp import material as urp
        if urp.reads(material.surface):  # a Universal Render Pipeline shader (importers/urp/)
            urp.read_material(reader, material, base)
        else:  # Unity's built-in pipeline (importers/unity/)
            self._unity().read_material(reader, material, base)

    def check_objects(self, objects, materials, origin: str) -> None:
        if any(m.source is not None for m in materials.values()):
            self._unity().check_objects(objects, materials, origin)

    @staticmethod
    def _unity():
        from .unity import material
        return material


SHADER_MATERIALS = _ShaderMaterials()


def parse_scene(data, origin: str = "<scene>", base: Path | None = None) -> scene_model.Scene:
    """``scene.model.parse_scene`` with glTF objects and Unity shaders read."""
    return scene_model.parse_scene(data, origin, base, read_gltf=read_gltf, shaders=SHADER_MATERIALS)


def _refuse_what_is_no_json_scene(path: Path) -> None:
    """A file not named .json whose text does not open with ``{`` (a GLSL surface, an HLSL
    file, an image) is no scene: say what is, rather than the JSON parser's "Expecting value"."""
    if path.suffix.lower() == ".json":
        return
    try:
        head = path.read_bytes()[:4096].lstrip()
    except OSError:
        return  # the JSON reader says what is wrong with the file
    if not head.startswith(b"{"):
        raise SceneError(f"{path}: not a scene file: a scene is a JSON file (.json), a glTF file (.gltf, .glb) "
                         f"or a Unity .shader (drawn on the default sphere); a GLSL surface file is drawn by "
                         f"naming it as a material's \"surface\" in a JSON scene")


def load_scene(path) -> scene_model.Scene:
    """A scene file: glTF by its suffix (its default scene and camera, the environment and
    render settings of its ``<model>.pbrlab.json`` beside it, as ``pbrlab render`` reads
    it), a lone Unity ``.shader`` on the default sphere (shader_preview.py), else a JSON scene."""
    from .shader_preview import is_lone_shader, preview_scene_data

    try:  # a scene file that is a link out of its folder (an unpacked archive's) is refused (safe_paths)
        safe_paths.named_file(path)
    except safe_paths.OutsideFolderError as exc:
        raise SceneError(str(exc)) from None
    if is_lone_shader(path):
        path = Path(path)
        return parse_scene(preview_scene_data(path), str(path), path.parent)
    if is_gltf(path):
        from .gltf import load_gltf
        from .gltf.settings import read_settings

        environment, render = read_settings(Path(path))
        return load_gltf(path, environment=environment, render=render).scene
    _refuse_what_is_no_json_scene(Path(path))
    return scene_model.load_scene(path, read_gltf=read_gltf, shaders=SHADER_MATERIALS)
