"""glTF mesh primitives (spec 3.7.2) as pbrlab Geometry: attributes read and checked,
triangle strips and fans turned into lists, flat normals where NORMAL is absent (spec
3.7.2.1), MikkTSpace tangents where a normal map needs them and TANGENT is absent; points
and lines as GL_POINTS and GL_LINES lists (gltf/points_lines.py)."""

from __future__ import annotations

import numpy as np

from ...scene.meshes import Geometry
from . import draco, morph, points_lines
from .accessors import read_accessor
from .document import Document
from .fields import FieldReader
from .tangents import mikktspace_tangents

TRIANGLES, TRIANGLE_STRIP, TRIANGLE_FAN = 4, 5, 6  # spec 3.7.2.1 "mode"
MODES = {TRIANGLES: "TRIANGLES", TRIANGLE_STRIP: "TRIANGLE_STRIP", TRIANGLE_FAN: "TRIANGLE_FAN"}
MODE_NAMES = points_lines.MODES


def _triangle_list(indices: np.ndarray, mode: int) -> np.ndarray:
    if mode == TRIANGLES:
        return indices[: len(indices) // 3 * 3].reshape(-1, 3)
    n = len(indices) - 2
    if n < 1:
        return np.zeros((0, 3), np.int64)
    i = np.arange(n)
    if mode == TRIANGLE_STRIP:  # spec: even triangles (i, i+1, i+2), odd (i+1, i, i+2)... keep winding
        a = np.where(i % 2 == 0, indices[i], indices[i + 1])
        b = np.where(i % 2 == 0, indices[i + 1], indices[i])
        return np.stack([a, b, indices[i + 2]], axis=1)
    return np.stack([np.full(n, indices[0]), indices[i + 1], indices[i + 2]], axis=1)  # fan


def read_primitive(doc: Document, mesh: int, prim_index: int, primitive: FieldReader, needs_tangents_from,
                   warn, flip_winding: bool, key: tuple, weights: tuple = (), posing=None) -> Geometry | None:
    """The primitive's Geometry (its ``topology``: triangles, lines or points).
    ``needs_tangents_from``: (UV set, the 2x2 linear part of its KHR_texture_transform as a
    flat tuple or None) of the material's normal map, or None.
    ``weights``: its mesh's morph target weights (gltf.morph). ``posing``: a skin's
    (attributes, count, positions, normals, tangents, decoded attributes) -> the posed three
    (gltf.skin)."""
    where = primitive.path
    mode = primitive.enum("mode", tuple(range(7)), TRIANGLES, {**MODE_NAMES, **MODES})
    attributes = primitive.object("attributes")
    if not attributes.has("POSITION"):
        attributes.fail("has no POSITION")
    attr_where = attributes.path
    compressed = None
    for ext, spec in primitive.extensions():
        if ext == draco.EXTENSION and draco.available():
            if mode not in (TRIANGLES, TRIANGLE_STRIP):
                primitive.fail(f"mode {({**MODE_NAMES, **MODES})[mode]}: {draco.EXTENSION} holds TRIANGLES or "
                               "TRIANGLE_STRIP only")
            compressed = draco.decode(doc, spec, attributes)
    decoded = {} if compressed is None else compressed.attributes
    positions = read_accessor(doc, attributes.index("POSITION", "accessors"), f"{attr_where}.POSITION", "POSITION",
                              decoded=decoded.get("POSITION"))
    count = len(positions)

    def optional(name, use):
        index = attributes.index(name, "accessors")
        return None if index is None else read_accessor(doc, index, f"{attr_where}.{name}", use, count,
                                                        decoded=decoded.get(name))

    normals = optional("NORMAL", "NORMAL")
    tangents = optional("TANGENT", "TANGENT")
    uv0 = optional("TEXCOORD_0", "TEXCOORD")
    uv1 = optional("TEXCOORD_1", "TEXCOORD")
    colors = optional("COLOR_0", "COLOR")
    for name in sorted(attributes.data):
        skinning = posing is not None and name.startswith(("JOINTS_", "WEIGHTS_"))
        if name not in ("POSITION", "NORMAL", "TANGENT", "TEXCOORD_0", "TEXCOORD_1", "COLOR_0") and not skinning:
            attributes.index(name, "accessors")
            warn(f"attribute {name} ignored in mesh {mesh} primitive {prim_index}")
    targets = primitive.objects("targets")
    if len(targets) != len(weights):
        primitive.fail(f"has {len(targets)} morph targets; its mesh's other primitives or weights have "
                       f"{len(weights)}")
    if targets:
        displaced = morph.displace(doc, primitive, weights, {"POSITION": positions, "NORMAL": normals,
                                                             "TANGENT": tangents}, count, warn, mesh, prim_index)
        positions, normals, tangents = displaced["POSITION"], displaced["NORMAL"], displaced["TANGENT"]
    if posing is not None:  # a skin poses the morphed mesh (3.7.3.3: morph targets first)
        positions, normals, tangents = posing(attributes, count, positions, normals, tangents, decoded)
    for ext, _ in primitive.extensions():
        if ext == draco.EXTENSION and compressed is None:
            warn(f"{ext} ignored in mesh {mesh} primitive {prim_index} ({draco.PACKAGE} is not installed: "
                 f"{draco.INSTALL}; the uncompressed fallback is drawn)")
        elif ext not in ("KHR_materials_variants", draco.EXTENSION):  # variants: gltf/__init__.py
            warn(f"{ext} ignored in mesh {mesh} primitive {prim_index}")

    index_accessor = primitive.index("indices", "accessors")
    if compressed is not None:
        if index_accessor is not None and mode == TRIANGLES:
            indices = read_accessor(doc, index_accessor, f"{where}.indices", "indices",
                                    decoded=compressed.indices.reshape(-1, 1))
        else:  # a strip's faces, or faces without an indices accessor: Draco's list as it is
            indices = compressed.indices
        mode = TRIANGLES
    elif index_accessor is not None:
        indices = read_accessor(doc, index_accessor, f"{where}.indices", "indices")
    else:
        indices = np.arange(count, dtype=np.int64)
    bad = np.flatnonzero((indices < 0) | (indices >= count))
    if len(bad):
        doc.fail(f"{where}.indices", f"index {int(indices[bad[0]])} at position {int(bad[0])} is out of "
                                     f"range (the primitive has {count} vertices)")
    uv0 = np.zeros((count, 2)) if uv0 is None else uv0
    uv1 = uv0 if uv1 is None else uv1
    colors = np.ones((count, 4)) if colors is None else colors
    if colors.shape[1] == 3:
        colors = np.concatenate([colors, np.ones((count, 1))], axis=1)
    if mode in MODE_NAMES:
        return _points_or_lines(key, mode, indices, positions, normals, tangents, uv0, uv1, colors,
                                lambda message: doc.fail(where, message))
    if mode == TRIANGLES and len(indices) % 3:
        doc.fail(where, f"a triangle list needs a multiple of 3 vertices, got {len(indices)}")
    triangles = _triangle_list(indices, mode)
    if len(triangles) == 0:
        doc.fail(where, "has no triangle")
    if flip_winding:  # a mirroring node transform (determinant < 0) turns front faces round
        triangles = triangles[:, ::-1]

    if normals is None:  # flat shading: every triangle its own three vertices
        corners = triangles.reshape(-1)
        positions, uv0, uv1, colors = positions[corners], uv0[corners], uv1[corners], colors[corners]
        tangents = None if tangents is None else tangents[corners]
        p = positions.reshape(-1, 3, 3)
        face = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
        if flip_winding:
            face = -face
        length = np.linalg.norm(face, axis=1, keepdims=True)
        face = np.where(length > 0, face / np.maximum(length, 1e-300), [[0.0, 0.0, 1.0]])
        normals = np.repeat(face, 3, axis=0)
        triangles = np.arange(len(corners)).reshape(-1, 3)
    uv0_gl, uv1_gl = _uv_gl(uv0), _uv_gl(uv1)
    if tangents is None:
        if needs_tangents_from is None:
            tangents = np.tile([1.0, 0.0, 0.0, 1.0], (len(positions), 1))
        else:
            # with v up the image: the bitangent cross(n, t) w then points up the image, the
            # normal map's +Y (spec 3.9.3: "+X is right and +Y is up")
            uv_set, linear = needs_tangents_from
            uv = tangent_uvs(uv1_gl if uv_set == 1 else uv0_gl, linear)
            positions, normals, uv0_gl, uv1_gl, colors, triangles, uv = split_mirrored_corners(
                triangles, uv, positions, normals, uv0_gl, uv1_gl, colors, uv)
            tangents = mikktspace_tangents(positions, normals, uv, triangles)
    return _geometry(key, positions, normals, uv0_gl, tangents, uv1_gl, colors, triangles.reshape(-1), "triangles")


def tangent_uvs(uv: np.ndarray, linear) -> np.ndarray:
    """The UVs the normal map is read with, up to an offset: ``linear`` (the 2x2 rotation and
    scale of its KHR_texture_transform in GL UV space, flat, or None) applied. MikkTSpace's
    tangent is dP/ds of the texture's own s: a rotated or mirrored normal-map tile needs the
    tangent of the transformed UVs (the extension: the transform applies to "the texture
    coordinates" the texture is sampled with; three.js and the Sample Viewer take the
    tangent frame of the transformed UVs)."""
    if linear is None:
        return uv
    return uv @ np.asarray(linear, np.float64).reshape(2, 2).T


def split_mirrored_corners(triangles, orientation_uv, *attributes):
    """mikktspace.c's split of a vertex whose triangles disagree in UV orientation (a mirror
    seam that shares its vertices): the vertex is copied for the triangles of the
    orientation its other triangles lack (here: the clockwise ones), so each copy gets the
    tangent and the sign of its own side instead of their mean. Returns the attributes
    (every per-vertex array, copies appended) and the re-indexed triangles in the order
    ``*attributes[:-1], triangles, attributes[-1]``."""
    t = orientation_uv[triangles]
    area = (t[:, 1, 0] - t[:, 0, 0]) * (t[:, 2, 1] - t[:, 0, 1]) - (t[:, 1, 1] - t[:, 0, 1]) * (t[:, 2, 0] - t[:, 0, 0])
    count = len(orientation_uv)
    positive = np.zeros(count, bool)
    negative = np.zeros(count, bool)
    positive[triangles[area > 0].reshape(-1)] = True
    negative[triangles[area < 0].reshape(-1)] = True
    shared = np.flatnonzero(positive & negative)
    if shared.size == 0:
        return (*attributes[:-1], triangles, attributes[-1])
    copy_of = np.full(count, -1)
    copy_of[shared] = count + np.arange(shared.size)
    triangles = triangles.copy()
    flipped = area < 0
    corners = triangles[flipped]
    triangles[flipped] = np.where(copy_of[corners] >= 0, copy_of[corners], corners)
    extended = [np.concatenate([a, a[shared]], axis=0) for a in attributes]
    return (*extended[:-1], triangles, extended[-1])


def _uv_gl(uv: np.ndarray) -> np.ndarray:
    """glTF's v runs down the image; pbrlab's textures put the image's last row at v = 0."""
    return np.stack([uv[:, 0], 1.0 - uv[:, 1]], axis=1)


def _geometry(key, positions, normals, uv, tangents, uv1, colors, indices, topology) -> Geometry:
    f32 = lambda a: np.ascontiguousarray(a, np.float32)  # noqa: E731
    return Geometry(key=key, positions=f32(positions), normals=f32(normals), uv=f32(uv), tangents=f32(tangents),
                    uv1=f32(uv1), colors=f32(colors), indices=np.ascontiguousarray(indices, np.int32),
                    topology=topology)


def _points_or_lines(key, mode, indices, positions, normals, tangents, uv0, uv1, colors, fail) -> Geometry:
    """A POINTS or LINES-family primitive: its index list; without NORMAL a placeholder +Z
    (the material is then unlit: points_lines.shaded_material), without TANGENT +X (no
    MikkTSpace without triangles)."""
    count = len(positions)
    normals = np.tile([0.0, 0.0, 1.0], (count, 1)) if normals is None else normals
    tangents = np.tile([1.0, 0.0, 0.0, 1.0], (count, 1)) if tangents is None else tangents
    return _geometry(key, positions, normals, _uv_gl(uv0), tangents, _uv_gl(uv1), colors,
                     points_lines.index_list(indices, mode, fail), points_lines.TOPOLOGY[mode])
