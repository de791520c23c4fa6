"""Where a glTF scene's geometry lies in world space: its vertices and their axis-aligned
bounds, which ``cameras`` frames (a framing camera fitted to the vertices, a glTF camera
aimed at the bounds' centre)."""

from __future__ import annotations

import math

import numpy as np

from ...scene.model import Scene


def world_points(scene: Scene) -> np.ndarray:
    """Every vertex of the scene's mesh objects in world space (float64)."""
    return np.concatenate([obj.geometry.positions.astype(np.float64) @ obj.transform[:3, :3].T
                           + obj.transform[:3, 3] for obj in scene.objects])


def bounds(scene: Scene) -> tuple[np.ndarray, np.ndarray]:
    """World-space axis-aligned bounds of every mesh object."""
    lo, hi = np.full(3, math.inf), np.full(3, -math.inf)
    for obj in scene.objects:
        p = obj.geometry.positions.astype(np.float64) @ obj.transform[:3, :3].T + obj.transform[:3, 3]
        lo, hi = np.minimum(lo, p.min(axis=0)), np.maximum(hi, p.max(axis=0))
    return lo, hi
