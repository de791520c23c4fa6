"""Meshes for the rasteriser: files read with trimesh, primitives made in numpy (primitives.py), and the
per-vertex attributes the mesh program needs (positions, normals, UVs, tangents)."""

from __future__ import annotations

import importlib.util
import io
import json
import os
import re
from collections import OrderedDict
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ..foundation import disk_cache
from ..foundation.errors import SceneError
from ..foundation.file_identity import file_key
from . import primitives

_PRIMITIVE_DEFAULTS = {
    "box": {"size": 1.0},
    "icosphere": {"radius": 1.0, "subdivisions": 3},
    "uv_sphere": {"radius": 1.0},
    "cylinder": {"radius": 0.5, "height": 1.0},
    "plane": {"size": 1.0},
    "torus": {"major_radius": 1.0, "minor_radius": 0.25},
}
PRIMITIVE_PARAMETERS = _PRIMITIVE_DEFAULTS  # what a scene's {"primitive": ...} may set (scene.py checks)
# Integer parameters: (smallest, largest). 8 subdivisions: 655,362 vertices (each level x4).
INTEGER_PARAMETERS = {"subdivisions": (0, 8)}


def _primitive(spec: dict) -> primitives.Primitive:
    kind = spec["primitive"]
    params = dict(_PRIMITIVE_DEFAULTS[kind])
    for key, value in spec.items():
        if key == "primitive":
            continue
        if key not in params:
            raise SceneError(f"mesh primitive {kind}: unknown parameter {key}; "
                             f"use {', '.join(params) or 'none'}")
        params[key] = value
    return primitives.make(kind, params)


def _load_obj(path, trimesh):
    """An OBJ file read as text here: UTF-8, else Latin-1 (every byte is a Latin-1 character;
    OBJ keywords and numbers are ASCII either way, only names and comments differ), so trimesh
    never guesses an encoding (its guess needs charset_normalizer, which pbrlab does not
    install). Material libraries beside it are still found through the resolver."""
    data = Path(path).read_bytes()
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError:
        text = data.decode("latin-1")
    resolver = trimesh.resolvers.FilePathResolver(str(path))
    return trimesh.load(io.StringIO(text), file_type="obj", force="mesh", process=False, resolver=resolver)


def load_mesh(obj):
    """The mesh of a scene object: a primitives.Primitive (made in numpy, no trimesh
    import) or a file's trimesh.Trimesh."""
    if obj.primitive is not None:
        return _primitive(obj.primitive)
    import trimesh

    try:
        if Path(obj.mesh_path).suffix.lower() == ".obj":
            mesh = _load_obj(obj.mesh_path, trimesh)
        else:
            mesh = trimesh.load(obj.mesh_path, force="mesh", process=False)
    except SceneError:
        raise
    except Exception as exc:  # trimesh raises many types for unreadable files
        raise SceneError(f"{obj.mesh_path}: trimesh cannot read this mesh ({exc})") from None
    if len(mesh.faces) == 0:
        raise SceneError(f"{obj.mesh_path}: the mesh has no triangles")
    bad = ~np.isfinite(np.asarray(mesh.vertices, dtype=np.float64)).all(axis=1)
    if bad.any():
        raise SceneError(f"{obj.mesh_path}: {int(bad.sum())} vertex position(s) are NaN or "
                         f"infinite (first: vertex {int(np.argmax(bad)) + 1})")
    if np.abs(np.asarray(mesh.vertices)).max() > FLOAT32_MAX:
        raise SceneError(f"{obj.mesh_path}: vertex positions exceed the float32 range "
                         f"(|x| <= {FLOAT32_MAX:.4g})")
    return mesh


@dataclass(frozen=True)
class MeshData:
    """What the renderer needs of a mesh: ``vertex_arrays`` and the largest vertex norm
    (from ``centre``, the origin for files and primitives)."""
    arrays: tuple
    max_vertex_norm: float
    centre: tuple = (0.0, 0.0, 0.0)


@dataclass(frozen=True, eq=False)
class Geometry:
    """Vertex data held in memory (a glTF primitive), ready for the mesh program: float32
    positions, normals, uv, tangents (xyz, w sign), uv1, colours (RGBA) and int32 indices
    of a triangle list (or of a line or point list: ``topology``, glTF's POINTS and LINES
    modes). ``key`` identifies it in the mesh cache."""
    key: tuple
    positions: np.ndarray
    normals: np.ndarray
    uv: np.ndarray
    tangents: np.ndarray
    uv1: np.ndarray
    colors: np.ndarray
    indices: np.ndarray
    topology: str = "triangles"  # "triangles", "lines" or "points"


def _mesh_key(obj) -> tuple:
    if getattr(obj, "geometry", None) is not None:
        return ("geometry", *obj.geometry.key)
    if obj.primitive is not None:
        return ("primitive", json.dumps(obj.primitive, sort_keys=True))
    return ("file", *file_key(obj.mesh_path))


FLOAT32_MAX = float(np.finfo(np.float32).max)
_MESH_DATA: OrderedDict = OrderedDict()
MESHES_KEPT = 32


def mesh_data(obj) -> MeshData:
    """``obj``'s mesh, read (or generated) and prepared once per file version or primitive
    (the last MESHES_KEPT are kept)."""
    key = _mesh_key(obj)
    if key in _MESH_DATA:
        _MESH_DATA.move_to_end(key)
    elif getattr(obj, "geometry", None) is not None:
        g = obj.geometry
        lo, hi = g.positions.min(axis=0).astype(np.float64), g.positions.max(axis=0).astype(np.float64)
        centre = (lo + hi) / 2
        norm = float(np.linalg.norm(g.positions - centre, axis=1).max())
        _MESH_DATA[key] = MeshData((g.positions, g.normals, g.uv, g.tangents, g.indices, g.uv1, g.colors),
                                   norm, tuple(float(c) for c in centre))
    else:
        arrays, norm = _prepared_mesh(obj)
        for array in arrays:
            array.flags.writeable = False  # shared by every render of this mesh
        _MESH_DATA[key] = MeshData(arrays, norm)
        while len(_MESH_DATA) > MESHES_KEPT:
            _MESH_DATA.popitem(last=False)
    return _MESH_DATA[key]


# Files whose geometry is the file alone (an OBJ's material libraries are hashed with it);
# others (a .gltf through trimesh reads its buffers) are read every time.
DISK_CACHED_SUFFIXES = (".obj", ".ply", ".stl", ".off")
_MTLLIB = re.compile(rb"^[ \t]*mtllib[ \t]+(.+?)[ \t]*$", re.M)


def _trimesh_identity() -> tuple:
    """trimesh's installed version, without importing it (0.7 s with scipy): the name of
    its dist-info folder and the identity of the RECORD file pip rewrites on every install."""
    spec = importlib.util.find_spec("trimesh")
    if spec is None or not spec.submodule_search_locations:
        return ("no trimesh",)
    site = Path(next(iter(spec.submodule_search_locations))).parent
    infos = sorted(p for p in os.listdir(site) if p.startswith("trimesh-") and p.endswith(".dist-info"))
    return (*infos, *(file_key(site / info / "RECORD") for info in infos))


def _mesh_inputs(obj) -> bytes | None:
    """Everything a file or primitive's vertex arrays are made from, as bytes; None when
    the disk cache does not keep this mesh (DISK_CACHED_SUFFIXES) or a file is unreadable."""
    if obj.primitive is not None:
        return json.dumps(obj.primitive, sort_keys=True).encode("utf-8")
    path = Path(obj.mesh_path)
    if path.suffix.lower() not in DISK_CACHED_SUFFIXES:
        return None
    try:
        data = path.read_bytes()
        parts = [data]
        if path.suffix.lower() == ".obj":
            for name in _MTLLIB.findall(data):
                library = path.parent / os.fsdecode(name)
                parts.append(library.read_bytes() if library.is_file() else b"missing")
    except OSError:
        return None  # load_mesh reports it
    return b"\0".join(parts)


def _prepared_mesh(obj) -> tuple[tuple, float]:
    """(vertex arrays, largest vertex norm) of a file or primitive: from the disk cache when
    an earlier process made them from the same bytes, this file's code and the same trimesh
    and numpy (disk_cache), else read through trimesh and kept there."""
    inputs = _mesh_inputs(obj)
    name = None
    if inputs is not None:
        # a primitive is made by primitives.py, a file read by trimesh
        maker = (Path(primitives.__file__).read_bytes() if obj.primitive is not None else _trimesh_identity())
        name = disk_cache.key("mesh", inputs, Path(__file__).read_bytes(), np.__version__, maker)
        cached = disk_cache.load("mesh", name, _decode_mesh_entry)
        if cached is not None:
            return cached
    mesh = load_mesh(obj)
    arrays = vertex_arrays(mesh)
    norm = float(np.linalg.norm(_surface(mesh)[0], axis=1).max())
    if name is not None:
        disk_cache.store("mesh", name, disk_cache.pack_arrays([*arrays, np.float64(norm)]))
    return arrays, norm


def _decode_mesh_entry(payload: bytes) -> tuple[tuple, float]:
    """A mesh entry's (vertex arrays, largest vertex norm), as vertex_arrays and
    _prepared_mesh wrote them; ValueError when the payload is anything else."""
    arrays = disk_cache.unpack_arrays(payload)
    if len(arrays) != 6:
        raise ValueError(f"{len(arrays)} arrays, not 6")
    *vertex, norm = arrays
    count = len(vertex[0]) if vertex[0].ndim == 2 else -1
    for array, width in zip(vertex[:4], (3, 3, 2, 4)):  # positions, normals, uvs, tangents
        if array.dtype != np.float32 or array.shape != (count, width):
            raise ValueError(f"a vertex array of {array.dtype} {array.shape}, not float32 ({count}, {width})")
    indices = vertex[4]
    if indices.dtype != np.int32 or indices.ndim != 1 or len(indices) % 3:
        raise ValueError(f"indices of {indices.dtype} {indices.shape}")
    if len(indices) and (indices.min() < 0 or indices.max() >= count):
        raise ValueError(f"indices outside 0..{count - 1}")
    if norm.shape != () or not np.isfinite(norm):
        raise ValueError(f"a vertex norm of shape {norm.shape}")
    return tuple(vertex), float(norm)


def bounding_radius(obj) -> float:
    """A radius around ``local_centre(obj)`` (transformed) that holds the mesh."""
    if getattr(obj, "geometry", None) is not None:  # the largest stretch (singular value)
        scale = np.linalg.norm(obj.transform[:3, :3], ord=2)
    else:  # files and primitives: kept as their goldens were made (equal for rotation x uniform scale)
        scale = np.abs(np.linalg.eigvals(obj.transform[:3, :3])).max()
    return float(mesh_data(obj).max_vertex_norm * scale)


def local_centre(obj) -> np.ndarray:
    """The centre of the mesh's bounds in its own space (the origin for files and primitives)."""
    return np.asarray(mesh_data(obj).centre, np.float64)


def tangents(positions, normals, uvs, faces) -> np.ndarray:
    """Per-vertex tangents (xyz) with bitangent sign (w) from UVs.

    Lengyel 2001, "Computing Tangent Space Basis Vectors for an Arbitrary Mesh": sum the
    per-triangle UV gradients at each vertex, Gram-Schmidt against the normal, and store
    the handedness of (n, t, b). Vertices with degenerate UVs get any unit vector
    orthogonal to n.
    """
    p0, p1, p2 = (positions[faces[:, i]] for i in range(3))
    w0, w1, w2 = (uvs[faces[:, i]] for i in range(3))
    e1, e2 = p1 - p0, p2 - p0
    d1, d2 = w1 - w0, w2 - w0
    det = d1[:, 0] * d2[:, 1] - d2[:, 0] * d1[:, 1]
    r = np.where(np.abs(det) > 1e-20, 1.0 / np.where(det == 0, 1, det), 0.0)[:, None]
    sdir = (e1 * d2[:, 1:2] - e2 * d1[:, 1:2]) * r
    tdir = (e2 * d1[:, 0:1] - e1 * d2[:, 0:1]) * r
    tan1 = np.zeros_like(positions)
    tan2 = np.zeros_like(positions)
    for i in range(3):
        np.add.at(tan1, faces[:, i], sdir)
        np.add.at(tan2, faces[:, i], tdir)
    t = tan1 - normals * np.sum(normals * tan1, axis=1, keepdims=True)
    length = np.linalg.norm(t, axis=1, keepdims=True)
    # Degenerate UVs (or a zero normal at a collapsed pole): any unit vector orthogonal
    # to the normal, or +x when the normal itself is zero.
    fallback = np.cross(normals, np.where(np.abs(normals[:, :1]) < 0.9, [[1.0, 0, 0]], [[0, 1.0, 0]]))
    fallback_length = np.linalg.norm(fallback, axis=1, keepdims=True)
    fallback = np.where(fallback_length > 1e-12, fallback / np.maximum(fallback_length, 1e-30), [[1.0, 0, 0]])
    t = np.where(length > 1e-12, t / np.maximum(length, 1e-30), fallback)
    w = np.where(np.sum(np.cross(normals, t) * tan2, axis=1) < 0.0, -1.0, 1.0)
    return np.concatenate([t, w[:, None]], axis=1)


def _surface(mesh) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """(positions, triangles, normals, uvs) of a primitives.Primitive or a trimesh.Trimesh
    (UVs zero where the file has none), float64 and int64."""
    if isinstance(mesh, primitives.Primitive):
        return mesh.positions, mesh.faces, mesh.normals, mesh.uv
    positions = np.asarray(mesh.vertices, np.float64)
    uv = getattr(mesh.visual, "uv", None)
    if uv is None or len(uv) != len(positions):
        uv = np.zeros((len(positions), 2))
    return (positions, np.asarray(mesh.faces, np.int64), np.asarray(mesh.vertex_normals, np.float64),
            np.asarray(uv, np.float64))


def as_trimesh(mesh):
    """``mesh`` as a trimesh.Trimesh (for pyrender's check): a primitive with its normals
    and UVs, a file's mesh as it is."""
    if not isinstance(mesh, primitives.Primitive):
        return mesh
    import trimesh

    return trimesh.Trimesh(mesh.positions, mesh.faces, vertex_normals=mesh.normals, process=False,
                           visual=trimesh.visual.TextureVisuals(uv=mesh.uv))


def vertex_arrays(mesh):
    """Flat float32 arrays (positions, normals, uvs, tangents) and int32 indices."""
    positions, faces, normals, uv = _surface(mesh)
    tan = tangents(positions, normals, uv, faces)
    return (positions.astype(np.float32), normals.astype(np.float32), uv.astype(np.float32),
            tan.astype(np.float32), faces.astype(np.int32).reshape(-1))


def vertex_array(ctx, program, obj, instances: np.ndarray | None = None):
    """A moderngl VertexArray for ``obj`` on ``program``, plus the buffers to release.
    Meshes without a second UV set read the first; without colours, white. ``instances``:
    per-instance rows of in_model (16 floats) and in_normal_matrix (9), instanced_draws."""
    arrays = mesh_data(obj).arrays
    positions, normals, uv, tan, indices = arrays[:5]
    uv1 = arrays[5] if len(arrays) > 5 else uv
    colors = arrays[6] if len(arrays) > 6 else np.ones((len(positions), 4), np.float32)
    data = np.concatenate([positions, normals, uv, tan, uv1, colors], axis=1).astype(np.float32)
    vbo = ctx.buffer(data.tobytes())
    ibo = ctx.buffer(indices.tobytes())
    layout = []
    names = [("in_position", "3f"), ("in_normal", "3f"), ("in_uv", "2f"), ("in_tangent", "4f"),
             ("in_uv1", "2f"), ("in_color", "4f")]
    fmt = []
    for name, f in names:
        if program.get(name, None) is not None:
            fmt.append(f)
            layout.append(name)
        else:
            fmt.append(f[0] + "x4")  # skip the attribute's bytes
    fmt_string = " ".join(fmt)
    # a vertex stage that reads no attribute (Unity's procedural passes: SV_VertexID alone)
    # still draws every index of the mesh; moderngl refuses a buffer that binds nothing
    content = [(vbo, fmt_string, *layout)] if layout else []
    buffers = [vbo, ibo]
    if instances is not None:
        buffers.append(ctx.buffer(np.ascontiguousarray(instances, np.float32).tobytes()))
        # a program that never reads the normal (an unlit pass, a scene without light) has
        # no in_normal_matrix: its bytes are skipped, as the vertex attributes' above
        instance_layout = [name for name in ("in_model", "in_normal_matrix") if program.get(name, None) is not None]
        instance_format = ("16f" if "in_model" in instance_layout else "16x4") + (
            " 9f/i" if "in_normal_matrix" in instance_layout else " 9x4/i")
        content.append((buffers[-1], instance_format, *instance_layout))
    vao = ctx.vertex_array(program, content, index_buffer=ibo)
    return vao, buffers
