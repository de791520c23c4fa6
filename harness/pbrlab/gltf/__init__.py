"""glTF 2.0 files as pbrlab scenes: read -> validate -> Scene.

    result = load_gltf("model.glb", camera=None, environment=None)
    result.scene       # a pbrlab.scene.Scene: one mesh object per primitive and node
    result.warnings    # one line per extension or feature not honoured

``document`` reads the file and its buffers, ``accessors`` checks every accessor against
its use, ``nodes`` walks the hierarchy, ``geometry`` turns primitives into vertex data,
``materials`` is the one mapping of glTF's material into the default surface, ``lights``
converts KHR_lights_punctual units, ``cameras`` places the view. A malformed file raises
SceneError naming the object; nothing else escapes for a bad file.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from ..errors import SceneError
from ..resource_cache import file_key
from ..scene import Camera, Environment, RenderSettings, Scene, SceneObject
from .cameras import framing_camera, gltf_camera
from .document import read_document
from .geometry import read_primitive
from .lights import punctual_light
from .materials import MaterialReader
from .nodes import walk

SUFFIXES = (".gltf", ".glb")
# Extensions whose content reaches the image (what extensionsRequired may name).
HONOURED_EXTENSIONS = ("KHR_lights_punctual", "KHR_texture_transform", "KHR_materials_emissive_strength",
                       "KHR_materials_ior", "KHR_materials_specular")


class GltfWarning(UserWarning):
    """A glTF extension or feature pbrlab does not honour."""


@dataclass
class GltfScene:
    scene: Scene
    warnings: list[str] = field(default_factory=list)
    cameras: int = 0  # glTF cameras placed by a node


def is_gltf(path) -> bool:
    return Path(path).suffix.lower() in SUFFIXES


def load_gltf(path, camera: int | None = None, environment: Environment | None = None,
              render: RenderSettings | None = None, size=None, emit_warnings: bool = True) -> GltfScene:
    """The scene of a glTF 2.0 file. ``camera``: the index of a glTF camera (default: the
    first one a node places; a framing camera from the bounds when there is none).
    Warnings are returned and, with ``emit_warnings``, issued as GltfWarning."""
    doc = read_document(path)
    path = Path(path)
    messages: list[str] = []

    def warn(message: str):
        if message not in messages:
            messages.append(message)

    for name in doc.json.get("extensionsRequired", []):
        if name not in HONOURED_EXTENSIONS:
            doc.fail("extensionsRequired", f"{name} is required by the file and not supported "
                                           f"(supported: {', '.join(HONOURED_EXTENSIONS)})")
    for key in ("animations", "skins"):
        if doc.json.get(key):
            warn(f"{key} ignored ({len(doc.json[key])}; the rest pose is drawn)")
    for name in doc.json.get("extensions", {}):
        if name != "KHR_lights_punctual":
            warn(f"{name} ignored (top level)")

    key = file_key(path)
    reader = MaterialReader(doc, key, warn)
    materials: dict = {}
    material_names: dict = {}
    objects, lights, placed_cameras = [], [], []
    for node_index, world in walk(doc, None):
        node = doc.json["nodes"][node_index]
        where = f"nodes[{node_index}]"
        for ext, spec in node.get("extensions", {}).items():
            if ext == "KHR_lights_punctual":
                lights.append(punctual_light(doc, spec.get("light") if isinstance(spec, dict) else None,
                                             world, f"{where}.extensions.KHR_lights_punctual.light"))
            else:
                warn(f"{ext} ignored in node {node_index}")
        if "camera" in node:
            placed_cameras.append((node["camera"], world, f"{where}.camera"))
        if "skin" in node:
            warn(f"skin ignored in node {node_index}")
        if "mesh" not in node:
            continue
        mesh_index = node["mesh"]
        mesh = doc.get("meshes", mesh_index, f"{where}.mesh")
        primitives = mesh.get("primitives")
        if not isinstance(primitives, list) or not primitives:
            doc.fail(f"meshes[{mesh_index}]", "needs a non-empty list of primitives")
        flip = bool(np.linalg.det(world[:3, :3]) < 0)
        if abs(np.linalg.det(world[:3, :3])) < 1e-30:
            warn(f"node {node_index} ignored (its transform has zero scale)")
            continue
        for p, primitive in enumerate(primitives):
            pwhere = f"meshes[{mesh_index}].primitives[{p}]"
            if not isinstance(primitive, dict):
                doc.fail(pwhere, "expected an object")
            material_index = primitive.get("material")
            has_colour = "COLOR_0" in primitive.get("attributes", {})
            mkey = (material_index, has_colour)
            if mkey not in materials:
                if material_index is not None:
                    doc.get("materials", material_index, f"{pwhere}.material")
                material = reader.material(material_index, has_colour)
                name = material.name
                taken = set(material_names.values())
                if name in taken:
                    name = f"{name} [{material_index}{', COLOR_0' if has_colour else ''}]"
                material.name = name
                material_names[mkey] = name
                materials[mkey] = material
            material = materials[mkey]
            for slot, uv_set in sorted(material.texture_uv_set.items()):
                if f"TEXCOORD_{uv_set}" not in primitive.get("attributes", {}):
                    doc.fail(pwhere, f"material \"{material.name}\" reads TEXCOORD_{uv_set} ({slot} texture), "
                                     "which the primitive lacks")
            normal_uv = material.texture_uv_set.get("normal", 0) if "normal" in material.textures else None
            geometry = read_primitive(doc, mesh_index, p, primitive, normal_uv, warn, flip,
                                      (*key, mesh_index, p, flip))
            if geometry is None:
                continue
            objects.append(SceneObject(material=material.name, transform=world.copy(), geometry=geometry))
    for name in doc.json.get("extensionsUsed", []):  # used where nothing above looked
        if name not in HONOURED_EXTENSIONS and not any(m.startswith(f"{name} ") for m in messages):
            warn(f"{name} ignored (listed in extensionsUsed)")
    if not objects:
        raise SceneError(f"{path}: the scene has no triangle to draw")
    by_name = {m.name: m for m in materials.values()}
    scene = Scene(camera=None, lights=lights, environment=environment, materials=by_name,
                  objects=objects, render=render or RenderSettings(), source=str(path))
    scene.camera = _choose_camera(doc, scene, placed_cameras, camera, size)
    if emit_warnings:
        for message in messages:
            warnings.warn(f"{path.name}: {message}", GltfWarning, stacklevel=2)
    return GltfScene(scene, messages, len(placed_cameras))


def _choose_camera(doc, scene: Scene, placed, index: int | None, size) -> Camera:
    if index is not None:
        for camera_index, world, where in placed:
            if camera_index == index:
                return gltf_camera(doc, camera_index, world, where, scene, size)
        doc.fail("cameras", f"--camera {index}: no node places camera {index} "
                            f"(placed: {sorted({c for c, _, _ in placed}) or 'none'})")
    if placed:
        camera_index, world, where = placed[0]
        return gltf_camera(doc, camera_index, world, where, scene, size)
    return framing_camera(scene, size)


def bounds(scene: Scene) -> tuple[np.ndarray, np.ndarray]:
    """World-space axis-aligned bounds of every mesh object."""
    lo, hi = np.full(3, math.inf), np.full(3, -math.inf)
    for obj in scene.objects:
        p = obj.geometry.positions.astype(np.float64) @ obj.transform[:3, :3].T + obj.transform[:3, 3]
        lo, hi = np.minimum(lo, p.min(axis=0)), np.maximum(hi, p.max(axis=0))
    return lo, hi
