"""glTF 2.0 files as pbrlab scenes: read -> validate -> Scene.

    result = load_gltf("model.glb", camera=None, environment=None)
    result.scene       # a pbrlab.scene.model.Scene: one mesh object per primitive and node
    result.warnings    # one line per extension or feature not honoured

``fields`` is the one typed reader every module reads the JSON through (type and range
of each field, refused by path), ``document`` reads the file and its buffers and checks
the top level, ``accessors`` checks every accessor against
its use, ``nodes`` walks the hierarchy, ``geometry`` turns primitives into vertex data
(``draco`` and ``meshopt`` decode compressed geometry, ``morph`` applies morph targets),
``animation`` samples animations at ``--time``, ``skin`` poses skinned meshes by their joints,
``materials`` is the one mapping of glTF's material into the default surface, ``lights``
converts KHR_lights_punctual units, ``cameras`` places the view (``extent``: where the
geometry lies, the vertices and bounds it frames). A malformed file raises
SceneError naming the object; nothing else escapes for a bad file.
"""

from __future__ import annotations

import copy
import re
import warnings
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from ...foundation.errors import SceneError
from ...foundation.file_identity import file_key
from ...scene.model import Camera, Environment, RenderSettings, Scene, SceneObject
from .cameras import framing_camera, gltf_camera
from .document import LIGHTS, read_document
from .extent import bounds
from . import animation as animations, draco, instancing, ktx2, meshopt, morph, points_lines, skin, webp
from .geometry import read_primitive
from .lights import punctual_light
from .materials import MaterialReader
from .nodes import check_float32, walk, world_matrices

SUFFIXES = (".gltf", ".glb")
# Extensions whose content reaches the image (what extensionsRequired may name).
HONOURED_EXTENSIONS = ("KHR_lights_punctual", "KHR_texture_transform", "KHR_materials_clearcoat",
                       "KHR_materials_emissive_strength", "KHR_materials_ior", "KHR_materials_specular",
                       "KHR_materials_variants", "KHR_materials_unlit", "KHR_materials_pbrSpecularGlossiness",
                       "KHR_materials_sheen", "KHR_mesh_quantization", "EXT_mesh_gpu_instancing",
                       "KHR_materials_anisotropy", "KHR_materials_iridescence", "KHR_materials_transmission",
                       "KHR_materials_volume")
# Extensions honoured through an optional decoder package: name -> its module (INSTALL, available()).
DECODED_EXTENSIONS = {module.EXTENSION: module for module in (draco, meshopt, ktx2, webp)}
# "<what> ignored in material "<name>"<detail>" and "... in node <n>": one line per what
# and detail in a file, naming where (a file once printed 27 lines for one extension).
_PER_PLACE = re.compile(r'^(?P<what>\S+) ignored in (?P<kind>material|node) (?P<place>"[^"]*"|\d+)(?P<detail>.*)$')
NAMED_PLACES = 3


class GltfWarning(UserWarning):
    """A glTF extension or feature pbrlab does not honour."""


@dataclass
class GltfScene:
    scene: Scene
    warnings: list[str] = field(default_factory=list)
    cameras: int = 0  # glTF cameras placed by a node


def is_gltf(path) -> bool:
    return Path(path).suffix.lower() in SUFFIXES


def honoured_extensions() -> tuple[str, ...]:
    """HONOURED_EXTENSIONS and the compression extensions whose decoder is installed."""
    return HONOURED_EXTENSIONS + tuple(name for name, m in DECODED_EXTENSIONS.items() if m.available())


def load_gltf(path, camera: int | None = None, environment: Environment | None = None,
              render: RenderSettings | None = None, size=None, emit_warnings: bool = True,
              variant: str | None = None, scene: int | None = None,
              weights: tuple | None = None, time: float | None = None,
              animation: str | None = None, allow_outside: bool = False) -> GltfScene:
    """The scene of a glTF 2.0 file. ``camera``: the index of a glTF camera (default: the
    first one a node places; a framing camera from the bounds when there is none).
    ``variant``: a KHR_materials_variants variant's name (default: the default materials).
    ``scene``: the index of the glTF scene drawn (default: the file's ``scene``, else 0).
    ``weights``: morph target weights for every mesh with targets (default: each node's
    or mesh's own, gltf.morph).
    ``time``: the animation time in seconds the nodes and morph weights are sampled at, and
    ``animation`` the index or name of the animation sampled, or "all" (default: the first,
    with a warning naming the others; without either the nodes as written, gltf.animation). Skinned meshes are
    posed by their joints either way (gltf.skin).
    ``allow_outside``: buffers and images may be files outside the glTF's folder (by
    default only files in it or below it are read: a downloaded model cannot read elsewhere).
    Warnings are returned and, with ``emit_warnings``, issued as GltfWarning."""
    doc = read_document(path, allow_outside)
    path = Path(path)
    messages: list[str] = []

    def warn(message: str):
        if message not in messages:
            messages.append(message)

    root = doc.root
    honoured = honoured_extensions()
    for name in root.strings("extensionsRequired"):
        if name in DECODED_EXTENSIONS and name not in honoured:
            doc.fail("extensionsRequired", f"{name} is required by the file and its decoder is not installed "
                                           f"({DECODED_EXTENSIONS[name].INSTALL})")
        if name not in honoured:
            doc.fail("extensionsRequired", f"{name} is required by the file and not supported "
                                           f"(supported: {', '.join(honoured)})")
    scenes = doc.items("scenes")
    if scene is not None and not 0 <= scene < len(scenes):
        doc.fail("scenes", f"--scene {scene}: the file has {len(scenes)} scene{'s' * (len(scenes) != 1)}"
                           + (f" (0 to {len(scenes) - 1})" if scenes else ""))
    pose = animations.sample(doc, time, animation, warn)
    worlds = None  # every node's world matrix, computed once a skin needs its joints'
    variant_index = None
    for name, spec in root.extensions():
        if name == "KHR_materials_variants":
            variant_index = _variant_index(doc, spec, variant)
        elif name != "KHR_lights_punctual":
            warn(f"{name} ignored (top level)")
    if variant is not None and variant_index is None:
        doc.fail("extensions", f"--variant {variant}: the file defines no KHR_materials_variants")

    key = file_key(path)
    reader = MaterialReader(doc, key, warn)
    # geometry depends on which decoders are installed too (a compressed primitive with an
    # uncompressed fallback): the key of its cached vertex buffers says so
    geometry_key = (*key, tuple(name for name, m in DECODED_EXTENSIONS.items() if m.available()))
    materials: dict = {}
    material_names: dict = {}
    objects, lights, placed_cameras = [], [], []
    geometries: dict = {}  # (mesh, primitive, winding, normal map UV set, weights) -> Geometry
    if weights is not None and not any(morph.target_count(m) for m in doc.items("meshes")):
        doc.fail("meshes", "--weights: the file has no morph targets")
    for node_index, world in walk(doc, scene, pose.trs):
        node = doc.items("nodes")[node_index]
        instances = None
        if node.has("name"):
            node.string("name")
        for ext, spec in node.extensions():
            if ext == "KHR_lights_punctual":
                light = spec.index("light", LIGHTS, required=True)
                lights.append(punctual_light(doc, light, world, node.path))
            elif ext == instancing.EXTENSION:
                instances = instancing.instance_matrices(doc, spec, node_index, warn)
            else:
                warn(f"{ext} ignored in node {node_index}")
        camera_index = node.index("camera", "cameras")
        if camera_index is not None:
            placed_cameras.append((camera_index, world, f"{node.path}.camera"))
        skin_index = node.index("skin", "skins")
        mesh_index = node.index("mesh", "meshes")
        if mesh_index is None:
            if skin_index is not None:
                warn(f"skin ignored in node {node_index} (the node has no mesh)")
            continue
        mesh = doc.items("meshes")[mesh_index]
        primitives = mesh.objects("primitives", min_items=1)
        mesh_weights = morph.weights(mesh_index, mesh, node, weights, pose.weights.get(node_index))
        skinning = None
        if skin_index is not None:
            if worlds is None:
                worlds = world_matrices(doc, pose.trs)
            matrices = skin.joint_matrices(doc, skin_index, worlds)
            check_float32(matrices.reshape(-1, 4), node, f"a joint matrix of skins[{skin_index}]")
            skinning = (skin.posing(doc, skin_index, matrices), ("skin", skin.pose_key(matrices)),
                        skin.mirrors(matrices))
            world = np.eye(4)  # 3.7.3.1: the skinned mesh node's transform MUST be ignored
        placements = [world] if instances is None else [world @ m for m in instances]
        for i, placed in enumerate(placements if instances is not None else []):
            check_float32(placed, node, f"the world matrix of its instance {i} "
                                        f"({instancing.EXTENSION})")
        for placed in placements:
            placed_objects = _placed_primitives(doc, reader, geometry_key, mesh_index, primitives, placed,
                                                node_index, variant_index, materials, material_names, geometries,
                                                warn, mesh_weights, skinning)
            for obj in placed_objects if instances is not None else []:
                obj.instance_group = (str(doc.path), node_index)
            objects += placed_objects
            if len(objects) > instancing.MAX_PLACED_OBJECTS:
                doc.fail(node.path, f"the file places over {instancing.MAX_PLACED_OBJECTS} objects (primitives of "
                                    "every node and instance), over the limit (instancing.MAX_PLACED_OBJECTS: "
                                    "about a minute of rendering)")
    for name in root.strings("extensionsUsed"):  # used where nothing above looked
        if name not in honoured and not any(m.startswith(f"{name} ") for m in messages):
            warn(f"{name} ignored (listed in extensionsUsed)")
    if not objects:
        raise SceneError(f"{path}: the scene has no triangle to draw")
    by_name = {m.name: m for m in materials.values()}
    scene = Scene(camera=None, lights=lights, environment=environment, materials=by_name,
                  objects=objects, render=render or RenderSettings(), source=str(path),
                  read_files=doc.declared_files())
    scene.camera = _choose_camera(doc, scene, placed_cameras, camera, size)
    messages = collapse_warnings(messages)
    if emit_warnings:
        for message in messages:
            warnings.warn(f"{path.name}: {message}", GltfWarning, stacklevel=2)
    return GltfScene(scene, messages, len(placed_cameras))


def _placed_primitives(doc, reader, key, mesh_index, primitives, world, node_index, variant_index,
                       materials, material_names, geometries, warn, weights=(), skinning=None) -> list[SceneObject]:
    """The objects of one placement of a node's mesh: one per primitive, its material read
    once per (material, COLOR_0) and its geometry once per winding. ``skinning``: (posing
    step, pose key, whether the joints mirror) for a skinned mesh (gltf.skin)."""
    out = []
    posing, pose_key, flip = skinning or (None, (), bool(np.linalg.det(world[:3, :3]) < 0))
    if abs(np.linalg.det(world[:3, :3])) < 1e-30:
        warn(f"node {node_index} ignored (its transform has zero scale)")
        return out
    for p, primitive in enumerate(primitives):
        material_index = _variant_material(primitive, variant_index)
        has_colour = primitive.object("attributes").has("COLOR_0")
        mkey = (material_index, has_colour)
        if mkey not in materials:
            material = reader.material(material_index, has_colour)
            name = material.name
            taken = set(material_names.values())
            if name in taken:
                name = f"{name} [{material_index}{', COLOR_0' if has_colour else ''}]"
            material.name = name
            material_names[mkey] = name
            materials[mkey] = material
        material = materials[mkey]
        material = _scaled_volume(material, world, mkey, materials, material_names)
        for slot, uv_set in sorted(material.texture_uv_set.items()):
            if not primitive.object("attributes").has(f"TEXCOORD_{uv_set}"):
                primitive.fail(f"material \"{material.name}\" reads TEXCOORD_{uv_set} ({slot} texture), "
                               "which the primitive lacks")
        mapped = [slot for slot in ("normal", "clearcoat_normal") if slot in material.textures]
        # tangents from the UVs the normal map is read with: its UV set, through its
        # KHR_texture_transform (geometry.tangent_uvs)
        tangent_slot = mapped[0] if mapped else None
        if tangent_slot is None and material.anisotropy_strength > 0.0:
            # KHR_materials_anisotropy lies along the tangent: MikkTSpace from its map's UV set
            # (TEXCOORD_0 without a map) where the primitive has no TANGENT
            tangent_slot = "anisotropy"
        normal_uv = None if tangent_slot is None else (
            material.texture_uv_set.get(tangent_slot, 0),
            _linear_part(material.texture_transform.get(tangent_slot)))
        gkey = (mesh_index, p, flip, normal_uv, weights, *pose_key)
        if gkey not in geometries:
            geometries[gkey] = read_primitive(doc, mesh_index, p, primitive, normal_uv, warn, flip,
                                              (*key, mesh_index, p, flip, weights, *pose_key), weights, posing)
        if geometries[gkey] is not None and geometries[gkey].topology != "triangles":
            material = points_lines.shaded_material(material, primitive.object("attributes").has("NORMAL"), mkey,
                                                    materials, material_names)
        if geometries[gkey] is not None:
            out.append(SceneObject(material=material.name, transform=world.copy(), geometry=geometries[gkey],
                                   where=f"{doc.path}: nodes[{node_index}] (mesh {mesh_index}, primitive {p})"))
    return out


def _scaled_volume(material, world, mkey, materials, material_names):
    """KHR_materials_volume: "thicknessFactor ... is given in the coordinate space of the mesh.
    Any transformations applied to the mesh's node will also be applied to the thickness" (the
    extension's README, "Properties"). A volume placed with a scale s != 1 gets its own copy of
    the material, thickness x s; s = |det(world 3x3)|^(1/3), the placement's geometric-mean
    scale (exact for a uniform scale; decided for a non-uniform one, where the Sample Renderer
    scales its refraction vector per axis)."""
    if material.transmission <= 0.0 or material.thickness <= 0.0:
        return material
    s = float(abs(np.linalg.det(world[:3, :3])) ** (1.0 / 3.0))
    if s == 1.0:
        return material
    skey = (*mkey, "volume scale", s)
    if skey not in materials:
        scaled = copy.deepcopy(material)
        scaled.thickness = material.thickness * s
        scaled.name = f"{material.name} [volume scale {s:.9g}]"
        material_names[skey] = scaled.name
        materials[skey] = scaled
    return materials[skey]


def _variant_index(doc, spec, name: str | None) -> int | None:
    """KHR_materials_variants: the index of the variant called ``name`` (None: no choice)."""
    names = [v.string("name") for v in spec.objects("variants", min_items=1)]
    if name is None:
        return None
    if name not in names:
        doc.fail("extensions.KHR_materials_variants", f"--variant {name!r} is not one of its variants: "
                 + ", ".join(repr(n) for n in names))
    return names.index(name)


def _variant_material(primitive, variant_index: int | None) -> int | None:
    """The primitive's material: its KHR_materials_variants mapping for the chosen variant,
    else its own (the extension's README: "If ... not mapped, the default material")."""
    default = primitive.index("material", "materials")
    for ext, spec in primitive.extensions():
        if ext != "KHR_materials_variants":
            continue
        for mapping in spec.objects("mappings"):
            material = mapping.index("material", "materials", required=True)
            variants = mapping.array("variants")
            if not all(isinstance(v, int) and not isinstance(v, bool) and v >= 0 for v in variants):
                mapping.fail(f"variants: expected indices of KHR_materials_variants' variants, got {variants}")
            if variant_index is not None and variant_index in variants:
                return material
    return default


def collapse_warnings(messages: list[str]) -> list[str]:
    """One line per unsupported extension (and detail) per file: the places it was found
    in are listed in the first one's position, the first NAMED_PLACES by name."""
    groups: dict = {}
    order = []
    for message in messages:
        m = _PER_PLACE.match(message)
        key = (m["what"], m["kind"], m["detail"]) if m else message
        if key not in groups:
            groups[key] = []
            order.append(key)
        if m:
            groups[key].append(m["place"])
    out = []
    for key in order:
        places = groups[key]
        if len(places) <= 1:
            out.append(key if isinstance(key, str) else f"{key[0]} ignored in {key[1]} {places[0]}{key[2]}")
            continue
        what, kind, detail = key
        named = ", ".join(places[:NAMED_PLACES]) + (f" and {len(places) - NAMED_PLACES} more"
                                                     if len(places) > NAMED_PLACES else "")
        out.append(f"{what} ignored in {len(places)} {kind}s ({named}){detail}")
    return out


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


def _linear_part(transform) -> tuple | None:
    """The 2x2 linear part (rotation, scale) of a slot's GL-space UV transform, as a
    hashable tuple (a geometry cache key), or None for none."""
    if transform is None:
        return None
    linear = np.asarray(transform, np.float64)[:2, :2]
    return None if np.array_equal(linear, np.eye(2)) else tuple(linear.reshape(-1).tolist())
