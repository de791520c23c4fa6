"""The staging check's two models: a unit sphere that is a perfect mirror (metallic 1,
roughness 0) and one that is white and fully rough (metallic 0, roughness 1), written as
glTF files on demand. Under the same environment, every renderer's mirror sphere must show
the same sky in the same place at the same brightness, and its diffuse sphere the same
irradiance: that pins the environment's orientation and scale before any score means
anything (check_staging.py)."""

from __future__ import annotations

import base64
import json
from pathlib import Path

import numpy as np

LATITUDES, LONGITUDES = 96, 192  # vertex normals of a sphere this fine reflect within ~0.1 degree
SPHERES = {"mirror_sphere": {"metallicFactor": 1.0, "roughnessFactor": 0.0},
           "diffuse_sphere": {"metallicFactor": 0.0, "roughnessFactor": 1.0}}


def _unit_sphere():
    theta = np.linspace(0.0, np.pi, LATITUDES + 1)
    phi = np.linspace(0.0, 2 * np.pi, LONGITUDES + 1)
    t, p = np.meshgrid(theta, phi, indexing="ij")
    points = np.stack([np.sin(t) * np.sin(p), np.cos(t), np.sin(t) * np.cos(p)], -1).reshape(-1, 3)
    ring = LONGITUDES + 1
    a = (np.arange(LATITUDES)[:, None] * ring + np.arange(LONGITUDES)[None]).reshape(-1)
    b = a + ring
    triangles = np.stack([a, b, a + 1, a + 1, b, b + 1], -1).reshape(-1)  # counter-clockwise outside
    return points.astype(np.float32), triangles.astype(np.uint32)


def write_spheres(folder: Path) -> dict:
    """Write the two spheres' .gltf files into ``folder``; returns {name: path}."""
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    points, triangles = _unit_sphere()
    blob = points.tobytes() * 2 + triangles.tobytes()  # positions, normals (the same), indices
    n = points.nbytes
    paths = {}
    for name, factors in SPHERES.items():
        doc = {
            "asset": {"version": "2.0", "generator": "pbrlab.checking.fidelity.spheres"},
            "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0, "name": name}],
            "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1}, "indices": 2, "material": 0}]}],
            "materials": [{"name": name, "pbrMetallicRoughness": {"baseColorFactor": [1, 1, 1, 1], **factors}}],
            "buffers": [{"byteLength": len(blob),
                         "uri": "data:application/octet-stream;base64," + base64.b64encode(blob).decode()}],
            "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": n, "target": 34962},
                            {"buffer": 0, "byteOffset": n, "byteLength": n, "target": 34962},
                            {"buffer": 0, "byteOffset": 2 * n, "byteLength": triangles.nbytes, "target": 34963}],
            "accessors": [{"bufferView": 0, "componentType": 5126, "count": len(points), "type": "VEC3",
                           "min": [-1, -1, -1], "max": [1, 1, 1]},
                          {"bufferView": 1, "componentType": 5126, "count": len(points), "type": "VEC3"},
                          {"bufferView": 2, "componentType": 5125, "count": len(triangles), "type": "SCALAR"}]}
        path = folder / f"{name}.gltf"
        path.write_text(json.dumps(doc), encoding="utf-8")
        paths[name] = path
    return paths
