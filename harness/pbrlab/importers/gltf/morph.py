"""Morph targets (glTF 2.0, 3.7.2.2 "Morph Targets"): a primitive's POSITION, NORMAL and
TANGENT displaced by its targets' deltas times the weights,

    position = base + sum_i w_i * target_i.POSITION        (likewise NORMAL, TANGENT.xyz)

the weights being ``node.weights`` where the node gives them, else ``mesh.weights``, else
zero (3.7.2.2: "node.weights ... overrides mesh.weights"), or the command line's
``--weights``. Displaced normals and tangents are renormalised; a tangent keeps its
handedness (w), which targets do not carry. Every primitive of a mesh has as many targets
as the weights have entries (3.7.2.2: "must have the same number of targets").
"""

from __future__ import annotations

import numpy as np

from .accessors import read_accessor
from .fields import FieldReader

DISPLACED = ("POSITION", "NORMAL", "TANGENT")


def target_count(mesh: FieldReader) -> int:
    """The number of morph targets of the mesh's primitives, refused when they differ."""
    counts = [len(p.objects("targets")) for p in mesh.objects("primitives", min_items=1)]
    if len(set(counts)) > 1:
        mesh.fail(f"its primitives have different numbers of morph targets ({counts}); "
                  "the specification requires the same number")
    return counts[0]


def weights(mesh_index: int, mesh: FieldReader, node: FieldReader, override: tuple | None,
            animated: tuple | None = None) -> tuple:
    """The weights the node's mesh is drawn with (empty for a mesh without targets):
    ``--weights``, else the node's animated weights at ``--time`` (gltf.animation), else
    its own, else its mesh's."""
    count = target_count(mesh)
    if override is not None and count:
        if len(override) != count:
            mesh.fail(f"--weights gives {len(override)} weight{'s' * (len(override) != 1)}; "
                      f"mesh {mesh_index} has {count} morph targets")
        return tuple(float(w) for w in override)
    if animated is not None and count:
        if len(animated) != count:
            node.fail(f"an animation gives it {len(animated)} morph weights; mesh {mesh_index} has {count} "
                      "targets (spec 3.11: one weight per target per keyframe)")
        return tuple(animated)
    for owner in (node, mesh):
        if owner.has("weights"):
            given = owner.numbers("weights", count)  # refuses a length other than count
            return tuple(float(w) for w in given)
    return (0.0,) * count


def displace(doc, primitive: FieldReader, mesh_weights: tuple, base: dict, count: int, warn,
             mesh_index: int, prim_index: int) -> dict:
    """``base`` ({"POSITION": ..., "NORMAL": ... or None, "TANGENT": ... or None}) with the
    primitive's targets applied by ``mesh_weights``; every target accessor is read and
    checked even when its weight is zero."""
    out = {k: None if v is None else v.copy() for k, v in base.items()}
    for t, target in enumerate(primitive.objects("targets")):
        w = mesh_weights[t]
        for name in sorted(target.data):
            index = target.index(name, "accessors")
            if name not in DISPLACED:
                warn(f"morph target attribute {name} ignored in mesh {mesh_index} primitive {prim_index}")
                continue
            delta = read_accessor(doc, index, f"{target.path}.{name}", f"TARGET_{name}", count)
            if out[name] is None:
                continue  # a delta for an attribute the primitive lacks displaces nothing
            out[name][:, :3] += w * delta
    for name in ("NORMAL", "TANGENT"):
        if out[name] is not None and any(mesh_weights):
            length = np.linalg.norm(out[name][:, :3], axis=1, keepdims=True)
            out[name][:, :3] = np.where(length > 0, out[name][:, :3] / np.maximum(length, 1e-300),
                                        base[name][:, :3])
    return out
