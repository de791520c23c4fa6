"""Generates the glTF test assets of how primitives are drawn (issue 24): instanced draws
and the point and line modes. Committed next to this script; run it again to rebuild them
byte for byte.

    instanced_cubes.glb  125 cubes, one mesh placed by EXT_mesh_gpu_instancing on a 5 x 5 x 5
                         grid, each instance with its own TRANSLATION, ROTATION and SCALE
                         (as Khronos' SimpleInstancing), under a directional light
    points_lines.gltf    an orthographic 64 x 64 view (xmag = ymag = 1: one pixel is 1/32)
                         of the four modes, vertices at pixel centres: POINTS with COLOR_0,
                         LINES, LINE_LOOP and LINE_STRIP without NORMAL (drawn unlit), and a
                         LINE_STRIP with NORMAL (lit), beside a quad of its material

    .venv/bin/python scenes/gltf/make_draw_assets.py
"""

from __future__ import annotations

import math

import numpy as np

from make_assets import HERE, Builder, _look_rotation, _quad, _quaternion, _rgba8

GRID = 5  # instances per axis
PIXELS = 64  # points_lines.gltf's intended image size; pixel i's centre is at -1 + (2i + 1) / PIXELS
POINTS, LINES, LINE_LOOP, LINE_STRIP = 0, 1, 2, 3


def _cube():
    """A unit cube, 24 vertices (flat faces), outward normals, counter-clockwise outside."""
    positions, normals, indices = [], [], []
    for axis in range(3):
        for sign in (1.0, -1.0):
            n = np.zeros(3)
            n[axis] = sign
            u = np.roll([0.0, 1.0, 0.0], axis)
            v = np.cross(n, u)
            base = len(positions)
            for du, dv in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
                positions.append(0.5 * (n + du * u + dv * v))
                normals.append(n)
            indices += [base, base + 1, base + 2, base, base + 2, base + 3]
    p, n = np.array(positions), np.array(normals)
    tri = np.array(indices).reshape(-1, 3)
    face = np.cross(p[tri[:, 1]] - p[tri[:, 0]], p[tri[:, 2]] - p[tri[:, 0]])
    flip = (face * n[tri[:, 0]]).sum(axis=1) < 0  # keep every face counter-clockwise seen from outside
    tri[flip] = tri[flip][:, ::-1]
    return p, n, tri.reshape(-1)


def _directional(b: Builder, direction) -> int:
    b.json["extensionsUsed"] = sorted(set(b.json.get("extensionsUsed", [])) | {"KHR_lights_punctual"})
    b.json.setdefault("extensions", {})["KHR_lights_punctual"] = {"lights": [{"type": "directional", "intensity": 3.0}]}
    return b.add("nodes", {"rotation": _look_rotation(direction), "extensions": {"KHR_lights_punctual": {"light": 0}}})


def instanced_cubes():
    b = Builder()
    b.json["asset"]["generator"] = "pbrlab scenes/gltf/make_draw_assets.py"
    b.json["materials"] = [{"name": "cube", "pbrMetallicRoughness": {"baseColorFactor": _rgba8(0.8, 0.45, 0.2, 1),
                                                                     "metallicFactor": 0.0, "roughnessFactor": 0.45}}]
    p, n, f = _cube()
    b.json["meshes"].append({"primitives": [b.primitive(p, n, None, f, 0)]})
    i, j, k = (a.reshape(-1) for a in np.meshgrid(*[np.arange(GRID)] * 3, indexing="ij"))
    translation = (np.stack([i, j, k], axis=1) - (GRID - 1) / 2) * 1.6
    rotation = np.array([_quaternion(np.array([1.0, 1.0 + a, 0.5]) / np.linalg.norm([1.0, 1.0 + a, 0.5]),
                                     0.37 * a) for a in range(GRID ** 3)])
    scale = np.stack([0.6 + 0.1 * (i % 3), 0.6 + 0.1 * (j % 2), 0.7 + 0.05 * k], axis=1)
    b.json["extensionsUsed"] = ["EXT_mesh_gpu_instancing"]
    attributes = {name: b.accessor(values, kind) for name, values, kind in
                  (("TRANSLATION", translation, "VEC3"), ("ROTATION", rotation, "VEC4"), ("SCALE", scale, "VEC3"))}
    cubes = b.add("nodes", {"mesh": 0, "extensions": {"EXT_mesh_gpu_instancing": {"attributes": attributes}}})
    light = _directional(b, [-0.4, -0.7, -0.6])
    b.json["cameras"] = [{"type": "perspective", "perspective": {"yfov": 0.8, "aspectRatio": 1.0, "znear": 0.1}}]
    camera = b.add("nodes", {"camera": 0, "translation": [7.0, 6.0, 12.0],
                             "rotation": _look_rotation([-7.0, -6.0, -12.0])})
    b.json["scenes"] = [{"nodes": [cubes, light, camera]}]
    b.json["scene"] = 0
    # the accessors of per-instance attributes are no vertex attributes: no bufferView target
    for accessor in attributes.values():
        b.json["bufferViews"][b.json["accessors"][accessor]["bufferView"]].pop("target", None)
    b.write_glb(HERE / "instanced_cubes.glb")


def _centre(i):
    """The x (or, counted from the top, -y) of pixel i's centre in points_lines.gltf's view."""
    return -1.0 + (2 * np.asarray(i, np.float64) + 1) / PIXELS


def _lines_primitive(b: Builder, pixels, mode: int, material: int, normals=False, colors=None) -> dict:
    """A primitive through pixel centres ``pixels`` [(column, row from the top)], at z = 0."""
    cr = np.asarray(pixels, np.float64)
    positions = np.stack([_centre(cr[:, 0]), -_centre(cr[:, 1]), np.zeros(len(cr))], axis=1)
    extra = {} if colors is None else {"COLOR_0": (colors, "VEC4")}
    prim = b.primitive(positions, np.tile([0.0, 0.0, 1.0], (len(cr), 1)) if normals else None, None, None,
                       material, **extra)
    prim["mode"] = mode
    return prim


def points_lines():
    b = Builder()
    b.json["asset"]["generator"] = "pbrlab scenes/gltf/make_draw_assets.py"
    b.json["materials"] = [
        {"name": "white", "pbrMetallicRoughness": {"baseColorFactor": [1.0, 1.0, 1.0, 1.0], "metallicFactor": 0.0}},
        {"name": "orange", "pbrMetallicRoughness": {"baseColorFactor": _rgba8(0.9, 0.4, 0.1, 1), "metallicFactor": 0.0,
                                                    "roughnessFactor": 0.5}}]
    grid = [(c, r) for r in (4, 8, 12) for c in (4, 10, 16, 22, 28)]
    colours = np.array([[(c % 3 == 0) * 0.75 + 0.25, (r / 12), 1.0 - c / 32, 1.0] for c, r in grid])
    meshes = [
        [_lines_primitive(b, grid, POINTS, 0, colors=colours)],
        [_lines_primitive(b, [(36, 4), (60, 4), (36, 10), (60, 12)], LINES, 1)],
        [_lines_primitive(b, [(6, 20), (26, 20), (26, 34), (6, 34)], LINE_LOOP, 1)],
        [_lines_primitive(b, [(34, 20), (40, 30), (46, 20), (52, 30), (58, 20)], LINE_STRIP, 1)],
        [_lines_primitive(b, [(6, 44), (26, 44), (26, 58)], LINE_STRIP, 1, normals=True)],
    ]
    p, n, uv, f = _quad(0.5)  # the lit line's material on a quad, to the right of it
    meshes.append([b.primitive(p, n, None, f, 1)])
    b.json["meshes"] = [{"primitives": prims} for prims in meshes]
    nodes = [b.add("nodes", {"mesh": m}) for m in range(len(meshes) - 1)]
    nodes.append(b.add("nodes", {"mesh": len(meshes) - 1, "translation": [0.55, -0.6, 0.0]}))
    nodes.append(_directional(b, [0.2, -0.3, -1.0]))
    b.json["cameras"] = [{"type": "orthographic", "orthographic": {"xmag": 1.0, "ymag": 1.0, "znear": 0.1, "zfar": 10.0}}]
    nodes.append(b.add("nodes", {"camera": 0, "translation": [0.0, 0.0, 2.0]}))
    b.json["scenes"] = [{"nodes": nodes}]
    b.json["scene"] = 0
    b.write_gltf(HERE / "points_lines.gltf", external_bin=False)


def main():
    instanced_cubes()
    points_lines()


if __name__ == "__main__":
    main()
