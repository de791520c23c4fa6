"""Tangents for glTF primitives that have a normal map but no TANGENT attribute.

glTF 2.0 (3.7.2.1) asks for MikkTSpace tangents (Mikkelsen 2008, "Simulation of Wrinkled
Surfaces Revisited"; the reference is mikktspace.c). No MikkTSpace binding installs here:
``pymikktspace`` 0.3.0, the one on PyPI, fails to build (its Cython sources no longer
compile with Cython 3). This is MikkTSpace's tangent written in numpy from that paper and
mikktspace.c's description:

* per triangle, the UV gradient direction dP/ds (``vOs`` in mikktspace.c, normalised,
  pointing along increasing s whatever the triangle's UV orientation), and whether the
  triangle preserves orientation (signed UV area > 0);
* per corner, that direction projected into the plane of the corner's vertex normal and
  normalised, weighted by the corner's angle measured in that plane;
* per vertex, the weighted sum projected again and normalised; w = +1 where the vertex's
  triangles (by angle weight) preserve orientation, else -1.

What it leaves out: mikktspace.c splits a vertex whose corners fall into different
groups (opposite UV orientation, or tangents far apart); glTF primitives are indexed, so
such corners share one vertex here and get their angle-weighted mean. On meshes whose
UVs are continuous and consistently oriented the two agree.
"""

from __future__ import annotations

import numpy as np

_EPSILON = 1e-20  # below this a length or area counts as zero (mikktspace.c NotZero uses FLT_MIN)


def _normalise(v: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    length = np.linalg.norm(v, axis=-1, keepdims=True)
    ok = length[..., 0] > _EPSILON
    return np.where(length > _EPSILON, v / np.maximum(length, _EPSILON), 0.0), ok


def _project(v: np.ndarray, n: np.ndarray) -> np.ndarray:
    return v - n * np.sum(n * v, axis=-1, keepdims=True)


def mikktspace_tangents(positions, normals, uvs, triangles) -> np.ndarray:
    """Per-vertex (x, y, z, w) tangents of a triangle list (float64 arrays; triangles
    n x 3 indices). Vertices without usable UVs get any unit vector orthogonal to n."""
    positions, normals, uvs = (np.asarray(a, np.float64) for a in (positions, normals, uvs))
    triangles = np.asarray(triangles, np.int64).reshape(-1, 3)
    p = positions[triangles]
    t = uvs[triangles]
    d1, d2 = p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]
    t21, t31 = t[:, 1] - t[:, 0], t[:, 2] - t[:, 0]
    signed_area = t21[:, 0] * t31[:, 1] - t21[:, 1] * t31[:, 0]
    preserving = signed_area > 0
    v_os = t31[:, 1:2] * d1 - t21[:, 1:2] * d2
    v_os *= np.where(preserving, 1.0, -1.0)[:, None]
    v_os, face_ok = _normalise(v_os)
    face_ok &= np.abs(signed_area) > _EPSILON

    total = np.zeros_like(positions)
    orientation = np.zeros(len(positions))
    for corner in range(3):
        vertex = triangles[:, corner]
        n = normals[vertex]
        direction, ok = _normalise(_project(v_os, n))
        e1, ok1 = _normalise(_project(p[:, (corner + 1) % 3] - p[:, corner], n))
        e2, ok2 = _normalise(_project(p[:, (corner + 2) % 3] - p[:, corner], n))
        angle = np.arccos(np.clip(np.sum(e1 * e2, axis=1), -1.0, 1.0))
        weight = np.where(face_ok & ok & ok1 & ok2, angle, 0.0)
        np.add.at(total, vertex, direction * weight[:, None])
        np.add.at(orientation, vertex, np.where(preserving, weight, -weight))
    tangent, ok = _normalise(_project(total, normals))
    helper = np.where(np.abs(normals[:, :1]) < 0.9, [[1.0, 0.0, 0.0]], [[0.0, 1.0, 0.0]])
    fallback, _ = _normalise(np.cross(normals, helper))
    tangent = np.where(ok[:, None], tangent, fallback)
    w = np.where(orientation < 0, -1.0, 1.0)
    return np.concatenate([tangent, w[:, None]], axis=1)
