"""Skins (glTF 2.0, 3.7.3 "Skins"), applied on the CPU before upload: the mesh is drawn
as its joints place it, in world space.

    joint matrix_j  = world(joint_j) . inverseBindMatrix_j                 (3.7.3.1)
    skin matrix     = sum over the vertex's influences of weight_i . joint matrix_(JOINTS[i])
    position        = skin matrix . (x, y, z, 1)                          (3.7.3.3)

over every JOINTS_n / WEIGHTS_n set (3.7.3.3: "more than four joints" use further sets).
"Only the joint transforms are applied to the skinned mesh; the transform of the skinned
mesh node MUST be ignored" (3.7.3.1): the object is placed with the identity. A normal
goes by the inverse transpose of the skin matrix's 3x3 (the transform that keeps it
perpendicular to the surface under non-uniform scale), a tangent by the 3x3 itself
(it lies in the surface), both renormalised; a tangent keeps its handedness w.

Without ``--time`` the joints' world matrices are the nodes' own translation, rotation
and scale: the pose the file is written in (the Sample Viewer draws the same with no
animation playing). The inverse bind matrices default to the identity (3.7.3.1).
"""

from __future__ import annotations

import hashlib

import numpy as np

from .accessors import read_accessor
from .document import Document


def joint_matrices(doc: Document, skin_index: int, worlds: dict) -> np.ndarray:
    """(J, 4, 4): world(joint_j) . inverseBindMatrix_j for the skin's joints;
    ``worlds``: node index -> world matrix (gltf.nodes.world_matrices)."""
    skin = doc.items("skins")[skin_index]
    joints = skin.indices("joints", "nodes")
    if not joints:
        skin.fail("joints: a skin needs at least one joint (spec 3.7.3)")
    ibm_index = skin.index("inverseBindMatrices", "accessors")
    if ibm_index is None:
        inverse_bind = np.tile(np.eye(4), (len(joints), 1, 1))
    else:
        values = read_accessor(doc, ibm_index, f"{skin.path}.inverseBindMatrices", "INVERSE_BIND_MATRICES",
                               len(joints))
        inverse_bind = values.reshape(-1, 4, 4).transpose(0, 2, 1)  # column-major
    return np.stack([worlds[j] for j in joints]) @ inverse_bind


def influences(doc: Document, attributes, count: int, joint_count: int, where: str, decoded: dict | None = None):
    """(joints (count, 4k) int, weights (count, 4k)) of every JOINTS_n / WEIGHTS_n pair.
    ``decoded``: glTF semantic -> values a compression extension decoded (gltf.draco); an
    attribute it lists is read from them, not from its accessor's buffer view (which a
    KHR_draco_mesh_compression primitive leaves out: the spec's zeros would weigh every
    vertex 0 and collapse the mesh to a point)."""
    decoded = decoded or {}
    joints, weights = [], []
    n = 0
    while attributes.has(f"JOINTS_{n}") or attributes.has(f"WEIGHTS_{n}"):
        for name in (f"JOINTS_{n}", f"WEIGHTS_{n}"):
            if not attributes.has(name):
                attributes.fail(f"has {f'JOINTS_{n}' if name.startswith('W') else f'WEIGHTS_{n}'} "
                                f"without {name} (spec 3.7.3.3: they come in pairs)")
        j = read_accessor(doc, attributes.index(f"JOINTS_{n}", "accessors"), f"{attributes.path}.JOINTS_{n}",
                          "JOINTS", count, decoded=decoded.get(f"JOINTS_{n}")).astype(np.int64)
        w = read_accessor(doc, attributes.index(f"WEIGHTS_{n}", "accessors"), f"{attributes.path}.WEIGHTS_{n}",
                          "WEIGHTS", count, decoded=decoded.get(f"WEIGHTS_{n}"))
        bad = np.flatnonzero((j >= joint_count).any(axis=1) & (w > 0).any(axis=1))
        if len(bad):
            attributes.fail(f"JOINTS_{n}: vertex {int(bad[0])} names joint {int(j[bad[0]].max())}; "
                            f"{where} has {joint_count} joints")
        joints.append(np.minimum(j, joint_count - 1))  # a joint index beyond them weighs 0 (checked above)
        weights.append(w)
        n += 1
    if n == 0:
        attributes.fail(f"has no JOINTS_0 / WEIGHTS_0, and {where} skins it (spec 3.7.3.3)")
    return np.concatenate(joints, axis=1), np.concatenate(weights, axis=1)


def skin_matrices(joints: np.ndarray, weights: np.ndarray, matrices: np.ndarray) -> np.ndarray:
    """(count, 4, 4): each vertex's weighted sum of its joints' matrices, one influence
    column at a time (gathering every column's matrices at once made a (count, 4k, 4, 4)
    array: 16 times the joints' own size, k JOINTS_n sets deep)."""
    out = np.zeros((len(joints), 4, 4))
    for i in range(joints.shape[1]):
        out += weights[:, i, None, None] * matrices[joints[:, i]]
    return out


def pose_vertices(skin: np.ndarray, positions, normals, tangents):
    """Positions, normals and tangents through each vertex's skin matrix (module doc)."""
    linear = skin[:, :3, :3]
    posed = np.einsum("vij,vj->vi", linear, positions) + skin[:, :3, 3]
    out_normals = out_tangents = None
    if normals is not None:
        # the inverse transpose times det: the cofactor matrix, whose columns are the
        # crosses of the 3x3's columns (a1 x a2, a2 x a0, a0 x a1); the sign of det keeps the
        # direction, and it stays defined where the weights sum to a singular matrix
        a0, a1, a2 = linear[:, :, 0], linear[:, :, 1], linear[:, :, 2]
        cofactor = np.stack([np.cross(a1, a2), np.cross(a2, a0), np.cross(a0, a1)], axis=2)
        sign = np.where(np.linalg.det(linear) < 0, -1.0, 1.0)[:, None]
        out_normals = _unit(np.einsum("vij,vj->vi", cofactor, normals) * sign, normals)
    if tangents is not None:
        t = _unit(np.einsum("vij,vj->vi", linear, tangents[:, :3]), tangents[:, :3])
        out_tangents = np.concatenate([t, tangents[:, 3:]], axis=1)
    return posed, out_normals, out_tangents


def _unit(v: np.ndarray, fallback: np.ndarray) -> np.ndarray:
    length = np.linalg.norm(v, axis=1, keepdims=True)
    return np.where(length > 0, v / np.maximum(length, 1e-300), fallback)


def pose_key(matrices: np.ndarray) -> str:
    """A short digest of the joint matrices: the geometry cache tells poses apart by it."""
    return hashlib.sha1(np.ascontiguousarray(matrices, np.float64).tobytes()).hexdigest()[:16]


def mirrors(matrices: np.ndarray) -> bool:
    """Whether the joints mirror the mesh (most joint matrices with a negative determinant):
    its triangles' winding turns round, as a mirroring node transform's does."""
    return bool(np.sum(np.linalg.det(matrices[:, :3, :3]) < 0) * 2 > len(matrices))


def posing(doc: Document, skin_index: int, matrices: np.ndarray):
    """The ``posing`` step gltf.geometry runs on a primitive the skin deforms."""
    def pose(attributes, count, positions, normals, tangents, decoded=None):
        joints, weights = influences(doc, attributes, count, len(matrices), f"skins[{skin_index}]", decoded)
        return pose_vertices(skin_matrices(joints, weights, matrices), positions, normals, tangents)
    return pose
