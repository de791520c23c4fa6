"""Geometry and tessellation-factor references, float64 (for Core RP's GeometricTools.hlsl and
Tessellation.hlsl names in pbrlab's Unity stand-ins). Sources: Rodrigues' rotation formula;
the quadratic formula; orthogonal projection on a plane; Phong tessellation (Boubekeur and
Alexa, "Phong Tessellation", SIGGRAPH Asia 2008); distance-adaptive edge factors (linear falloff
between a near and a far distance, as Unity documents its tessellation helpers)."""

from __future__ import annotations

import numpy as np


def rotation_matrix(axis, angle) -> np.ndarray:
    """c I + s [k]x + (1 - c) k k^T for the unit axis k."""
    k = np.asarray(axis, np.float64) / np.linalg.norm(axis)
    cross = np.array([[0.0, -k[2], k[1]], [k[2], 0.0, -k[0]], [-k[1], k[0], 0.0]])
    return np.cos(angle) * np.eye(3) + np.sin(angle) * cross + (1.0 - np.cos(angle)) * np.outer(k, k)


def rotate_about(pivot, position, axis, angle) -> np.ndarray:
    pivot = np.asarray(pivot, np.float64)
    return pivot + rotation_matrix(axis, angle) @ (np.asarray(position, np.float64) - pivot)


def quadratic_roots(a, b, c) -> np.ndarray:
    s = np.sqrt(b * b - 4.0 * a * c)
    return np.sort(np.array([(-b - s) / (2.0 * a), (-b + s) / (2.0 * a)]))


def project_on_plane(position, plane_point, unit_normal) -> np.ndarray:
    p, n = np.asarray(position, np.float64), np.asarray(unit_normal, np.float64)
    return p - np.dot(p - np.asarray(plane_point, np.float64), n) * n


def phong_tessellation(position, corners, normals, bary, shape) -> np.ndarray:
    phong = sum(w * project_on_plane(position, p, n) for w, p, n in zip(bary, corners, normals))
    return (1.0 - shape) * np.asarray(position, np.float64) + shape * phong


def distance_tess_factors(p0, p1, p2, camera, near, far) -> np.ndarray:
    """Edges facing p0, p1, p2: 1 - (|midpoint - camera| - near) / (far - near), clamped to [0, 1]."""
    p0, p1, p2, camera = (np.asarray(v, np.float64) for v in (p0, p1, p2, camera))
    mids = [(p1 + p2) / 2.0, (p0 + p2) / 2.0, (p0 + p1) / 2.0]
    d = np.array([np.linalg.norm(m - camera) for m in mids])
    return np.clip(1.0 - (d - near) / (far - near), 0.0, 1.0)
