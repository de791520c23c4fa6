"""EXT_mesh_gpu_instancing: a node's mesh drawn once per instance, each placed by the
node's world matrix times the instance's TRANSLATION, ROTATION, SCALE (the extension's
README: "the instance transform is applied after the node's own", attributes absent mean
the identity part; every attribute has the same count)."""

from __future__ import annotations

import numpy as np

from .accessors import read_accessor
from .nodes import quaternion_matrix

EXTENSION = "EXT_mesh_gpu_instancing"
ATTRIBUTES = {"TRANSLATION": "INSTANCE_TRANSLATION", "ROTATION": "INSTANCE_ROTATION",
              "SCALE": "INSTANCE_SCALE"}
# Instances of one node: each becomes a placed object (its matrix, a check, the draw's row),
# measured at 130 us and 1.7 KiB an instance (20,000 in 2.6 s, +34 MiB; issue 39: a million
# zero-scale instances ran for minutes before "no triangle to draw"). An import budget of
# 10 s / 130 us = 77,000 instances; 2^16 = 65,536 is 8.5 s and 110 MiB.
MAX_INSTANCES = 1 << 16
# Placed objects of a whole file, over all its nodes and instances (a primitive placed once is
# one): the same budget, because each costs the render what an instance does (measured after
# the import too: 60,000 instances of one quad rendered in 50 s, peak RSS 250 MiB, on the
# loaded 2-core machine), whether one node holds them or a thousand nodes share them
# (before this limit, 1,000 nodes of 65,536 instances each were accepted: 65 million objects).
MAX_PLACED_OBJECTS = 1 << 16


def instance_matrices(doc, spec, node_index: int, warn) -> list[np.ndarray]:
    """The instances' local matrices (applied after the node's world matrix)."""
    attributes = spec.object("attributes")
    where = attributes.path
    read = {}
    count = None
    for name in sorted(attributes.data):
        index = attributes.index(name, "accessors")
        if name not in ATTRIBUTES:
            warn(f"{EXTENSION} attribute {name} ignored in node {node_index}")
            continue
        read[name] = read_accessor(doc, index, f"{where}.{name}", ATTRIBUTES[name], count)
        count = len(read[name])
    if count is None:
        attributes.fail("has none of TRANSLATION, ROTATION, SCALE")
    if count > MAX_INSTANCES:
        attributes.fail(f"{count} instances, over the limit of {MAX_INSTANCES} a node "
                        "(instancing.MAX_INSTANCES: about 10 s of import)")
    rotations = read.get("ROTATION")
    if rotations is not None:
        zero = np.flatnonzero(~(np.linalg.norm(rotations, axis=1) > 0))
        if len(zero):
            attributes.fail(f"ROTATION of instance {int(zero[0])} is the zero quaternion")
    matrices = []
    for i in range(count):
        m = np.eye(4)
        linear = np.eye(3) if rotations is None else quaternion_matrix(rotations[i])
        if "SCALE" in read:
            linear = linear @ np.diag(read["SCALE"][i])
        m[:3, :3] = linear
        if "TRANSLATION" in read:
            m[:3, 3] = read["TRANSLATION"][i]
        matrices.append(m)
    return matrices
