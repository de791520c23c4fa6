"""Instanced draws: the objects one EXT_mesh_gpu_instancing node places, drawn in one call.

The importer places every instance as an object of its own (its world matrix in
``transform``), so bounds, depth range, draw order and the cross-checks see each one. The
renderer gathers the objects that share ``instance_group``, geometry and material into one
batch and draws it once with ``instances=N``; each instance's model and normal matrices
are per-instance vertex attributes (templates/mesh.vert, PBRLAB_INSTANCED), the same
float32 values the one-object draw sets as uniforms. OpenGL 4.6 core, section 10.5: an
instanced draw behaves as the N single draws in instance order, so depth ties resolve as
before. Blended objects are drawn one by one, sorted far to near (their order is per
object), and so are objects of a Unity shader (their programs read the model uniform).
"""

from __future__ import annotations

import numpy as np

INSTANCED_DEFINE = "PBRLAB_INSTANCED"


def batches(ordered: list, instanceable) -> list[list]:
    """``ordered`` objects -> batches in draw order: a batch is drawn where its first object
    stood. ``instanceable(obj)``: whether the object's material may be batched."""
    out: list[list] = []
    open_batches: dict = {}
    for obj in ordered:
        if obj.instance_group is None or obj.geometry is None or not instanceable(obj):
            out.append([obj])
            continue
        key = (obj.instance_group, id(obj.geometry), obj.material)
        if key in open_batches:
            open_batches[key].append(obj)
        else:
            open_batches[key] = [obj]
            out.append(open_batches[key])
    return out


def model_matrix(transform: np.ndarray) -> np.ndarray:
    """u_model / in_model: the world matrix, column-major (GLSL's mat4 order)."""
    return np.asarray(transform, np.float64).T.reshape(-1)


def normal_matrix(transform: np.ndarray) -> np.ndarray:
    """u_normal_matrix / in_normal_matrix: inverse-transpose of the upper 3x3, column-major."""
    inverse_transpose = np.linalg.inv(np.asarray(transform, np.float64)[:3, :3]).T
    return inverse_transpose.T.reshape(-1)


def instance_data(objects: list) -> np.ndarray:
    """Per-instance attribute bytes: each object's model (16 floats) and normal matrix (9)."""
    return np.stack([np.concatenate([model_matrix(o.transform), normal_matrix(o.transform)])
                     for o in objects]).astype(np.float32)
