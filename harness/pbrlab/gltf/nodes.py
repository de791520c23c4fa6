"""The node hierarchy of a glTF scene: world matrices (spec 3.5.2 "Transformations":
a matrix, or translation x rotation x scale), walked from the scene's roots; cycles and
nodes with two parents are refused by name."""

from __future__ import annotations

import json

import numpy as np

from .document import Document


def _numbers(doc, node, key, n, where, default):
    value = node.get(key, default)
    if (not isinstance(value, list) or len(value) != n
            or not all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in value)):
        doc.fail(where, f"{key} must be {n} numbers, got {json.dumps(value)[:60]}")
    arr = np.array(value, np.float64)
    if not np.all(np.isfinite(arr)):
        doc.fail(where, f"{key} holds a non-finite value")
    return arr


def quaternion_matrix(q: np.ndarray) -> np.ndarray:
    """Rotation matrix of a unit quaternion (x, y, z, w), glTF's order."""
    x, y, z, w = q / np.linalg.norm(q)
    return np.array([
        [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
        [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
        [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])


def local_matrix(doc: Document, node: dict, where: str) -> np.ndarray:
    if "matrix" in node:
        if any(key in node for key in ("translation", "rotation", "scale")):
            doc.fail(where, "has both matrix and translation/rotation/scale")
        return _numbers(doc, node, "matrix", 16, where, None).reshape(4, 4).T  # column-major
    t = _numbers(doc, node, "translation", 3, where, [0, 0, 0])
    q = _numbers(doc, node, "rotation", 4, where, [0, 0, 0, 1])
    s = _numbers(doc, node, "scale", 3, where, [1, 1, 1])
    if not np.linalg.norm(q) > 0:
        doc.fail(where, "rotation is the zero quaternion")
    m = np.eye(4)
    m[:3, :3] = quaternion_matrix(q) @ np.diag(s)
    m[:3, 3] = t
    return m


def walk(doc: Document, scene_index: int | None):
    """(node index, world matrix) of every node of the scene, parents first."""
    nodes = doc.items("nodes")
    scenes = doc.items("scenes")
    if scenes:
        index = doc.json.get("scene", 0) if scene_index is None else scene_index
        scene = doc.get("scenes", index, "scene")
        roots = scene.get("nodes", [])
        roots_where = f"scenes[{index}].nodes"
    else:  # no scenes: every node that is nobody's child (spec 3.5.1 allows scene-less files)
        children = {c for n in nodes for c in n.get("children", []) if isinstance(c, int)}
        roots = [i for i in range(len(nodes)) if i not in children]
        roots_where = "nodes"
    if not isinstance(roots, list):
        doc.fail(roots_where, "expected a list of node indices")
    seen: set[int] = set()
    stack = [(r, np.eye(4), f"{roots_where}[{i}]") for i, r in enumerate(roots)][::-1]
    while stack:
        index, parent, where = stack.pop()
        node = doc.get("nodes", index, where)
        if index in seen:
            doc.fail(f"nodes[{index}]", "appears twice in the hierarchy (a cycle, or two parents)")
        seen.add(index)
        world = parent @ local_matrix(doc, node, f"nodes[{index}]")
        yield index, world
        children = node.get("children", [])
        if not isinstance(children, list):
            doc.fail(f"nodes[{index}].children", "expected a list of node indices")
        stack.extend((c, world, f"nodes[{index}].children[{i}]") for i, c in reversed(list(enumerate(children))))
