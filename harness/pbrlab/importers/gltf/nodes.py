"""The node hierarchy of a glTF scene: world matrices (spec 3.5.2 "Transformations":
a matrix, or translation x rotation x scale), walked from the scene's roots; cycles and
nodes with two parents are refused by name, and so are a matrix that is not affine (its
last row not 0, 0, 0, 1: spec 3.5.3, a node matrix decomposes to TRS) and a world matrix
that is finite in float64 but not in float32 (a product of huge scales: the GPU would
draw nothing, or NaN)."""

from __future__ import annotations

import numpy as np

from ...foundation.json_input import FLOAT32_MAX
from .document import Document
from .fields import FieldReader


def quaternion_matrix(q: np.ndarray) -> np.ndarray:
    """Rotation matrix of a unit quaternion (x, y, z, w), glTF's order."""
    x, y, z, w = q / np.linalg.norm(q)
    return np.array([
        [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
        [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
        [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])


def local_matrix(node: FieldReader, animated: dict | None = None) -> np.ndarray:
    """The node's matrix; ``animated``: the translation, rotation or scale an animation
    time gives it (gltf.animation), which replace the node's own."""
    if node.has("matrix"):
        if any(node.has(key) for key in ("translation", "rotation", "scale")):
            node.fail("has both matrix and translation/rotation/scale")
        m = node.numbers("matrix", 16).reshape(4, 4).T  # column-major
        if not np.array_equal(m[3], [0, 0, 0, 1]):
            node.fail(f"matrix is not affine: its last row is {_row(m[3])}, glTF requires "
                      "[0, 0, 0, 1] (a node matrix is translation x rotation x scale, spec 3.5.3)")
        return m
    t = node.numbers("translation", 3, [0, 0, 0])
    q = node.numbers("rotation", 4, [0, 0, 0, 1], -1.0, 1.0)  # spec 5.25: unit quaternion components
    s = node.numbers("scale", 3, [1, 1, 1])
    if animated:
        t, q, s = (animated.get(k, v) for k, v in (("translation", t), ("rotation", q), ("scale", s)))
    if not np.linalg.norm(q) > 0:
        node.fail("rotation is the zero quaternion")
    m = np.eye(4)
    m[:3, :3] = quaternion_matrix(q) @ np.diag(s)
    m[:3, 3] = t
    return m


def _row(values) -> str:
    return "[" + ", ".join(f"{v:g}" for v in values) + "]"


def check_float32(world: np.ndarray, node: FieldReader, what: str = "its world matrix") -> None:
    """Refuse (naming the node) a world matrix the GPU cannot hold: an entry finite in
    float64 but beyond float32's range."""
    if not np.all(np.isfinite(world)):
        node.fail(f"{what} overflows (a product of huge scales or translations)")
    largest = float(np.abs(world).max())
    if largest > FLOAT32_MAX:
        node.fail(f"{what} has an entry of {largest:.3g}: finite in float64, not in float32 "
                  f"(|x| <= {FLOAT32_MAX:.8g}), which the GPU computes in (a product of huge "
                  "scales or translations)")


def world_matrices(doc: Document, animated: dict | None = None) -> dict:
    """node index -> world matrix for every node of the file (in a scene or not): the
    joints of a skin (gltf.skin). ``animated``: node -> its animated TRS."""
    nodes = doc.items("nodes")
    parent = {}
    for i, node in enumerate(nodes):
        for c in node.indices("children", "nodes"):
            if c in parent:
                doc.fail(f"nodes[{c}]", "appears twice in the hierarchy (a cycle, or two parents)")
            parent[c] = i
    out: dict = {}

    def world(i: int, depth: int = 0) -> np.ndarray:
        if i not in out:
            if depth > len(nodes):
                doc.fail(f"nodes[{i}]", "is its own ancestor (a cycle)")
            local = local_matrix(nodes[i], (animated or {}).get(i))
            with np.errstate(over="ignore", invalid="ignore"):
                out[i] = local if i not in parent else world(parent[i], depth + 1) @ local
        return out[i]

    for i in range(len(nodes)):
        world(i)
    return out


def walk(doc: Document, scene_index: int | None, animated: dict | None = None):
    """(node index, world matrix) of every node of the scene, parents first.
    ``animated``: node -> its animated translation, rotation, scale (gltf.animation)."""
    nodes = doc.items("nodes")
    scenes = doc.items("scenes")
    if scenes:
        if scene_index is None:
            scene_index = doc.root.index("scene", "scenes")
        index = 0 if scene_index is None else doc.check_index("scenes", scene_index, "scene")
        roots = scenes[index].indices("nodes", "nodes")
    else:  # no scenes: every node that is nobody's child (spec 3.5.1 allows scene-less files)
        children = {c for n in nodes for c in n.indices("children", "nodes")}
        roots = [i for i in range(len(nodes)) if i not in children]
    seen: set[int] = set()
    stack = [(r, np.eye(4)) for r in reversed(roots)]
    while stack:
        index, parent = stack.pop()
        node = nodes[index]
        if index in seen:
            doc.fail(f"nodes[{index}]", "appears twice in the hierarchy (a cycle, or two parents)")
        seen.add(index)
        with np.errstate(over="ignore", invalid="ignore"):  # refused just below, by name
            world = parent @ local_matrix(node, (animated or {}).get(index))
        check_float32(world, node)
        yield index, world
        children = node.indices("children", "nodes")
        stack.extend((c, world) for c in reversed(children))
