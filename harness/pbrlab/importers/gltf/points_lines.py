"""glTF POINTS, LINES, LINE_LOOP and LINE_STRIP primitives (spec 3.7.2.1, "mode"): index
lists for GL_POINTS and GL_LINES, and how they are shaded.

Index lists (spec 3.7.2.1, the primitive counts of each mode): LINES joins vertices 2i and
2i + 1, and needs an even count; LINE_STRIP joins i and i + 1; LINE_LOOP also joins the
last to the first; a strip or loop needs 2 vertices at least, POINTS 1.

Shading: the specification asks for flat normals where NORMAL is absent ("client
implementations MUST calculate flat normals", 3.7.2.1), which only a triangle has. Points
and lines with NORMAL are lit with it like any surface, and without it are drawn unlit:
the material's base colour (factor x texture x COLOR_0) and alpha as KHR_materials_unlit
draws them. This is what three.js's GLTFLoader does for points and lines (PointsMaterial,
LineBasicMaterial: no light) and X3D 4's rule for point and line sets without normals.
GL draws them 1 pixel wide (a core profile's only line width; the default point size).
"""

from __future__ import annotations

import copy

import numpy as np

POINTS, LINES, LINE_LOOP, LINE_STRIP = 0, 1, 2, 3
MODES = {POINTS: "POINTS", LINES: "LINES", LINE_LOOP: "LINE_LOOP", LINE_STRIP: "LINE_STRIP"}
TOPOLOGY = {POINTS: "points", LINES: "lines", LINE_LOOP: "lines", LINE_STRIP: "lines"}
MINIMUM = {POINTS: 1, LINES: 2, LINE_LOOP: 2, LINE_STRIP: 2}


def index_list(indices: np.ndarray, mode: int, fail) -> np.ndarray:
    """The primitive's vertex indices as a GL_POINTS or GL_LINES list; ``fail(message)``
    refuses a count the mode cannot draw."""
    if len(indices) < MINIMUM[mode]:
        fail(f"a {MODES[mode]} primitive needs {MINIMUM[mode]} vertices at least, got {len(indices)}")
    if mode == POINTS:
        return indices
    if mode == LINES:
        if len(indices) % 2:
            fail(f"a LINES primitive needs an even number of vertices, got {len(indices)}")
        return indices
    ends = np.roll(indices, -1) if mode == LINE_LOOP else indices[1:]
    return np.stack([indices[: len(ends)], ends], axis=1).reshape(-1)


def shaded_material(material, has_normals: bool, mkey, materials: dict, material_names: dict):
    """The material a point or line primitive is drawn with: its own when it has normals,
    else an unlit copy (module doc), made once per material."""
    if has_normals or material.unlit:
        return material
    ukey = (*mkey, "unlit points and lines")
    if ukey not in materials:
        unlit = copy.deepcopy(material)
        unlit.unlit = True
        unlit.name = f"{material.name} [unlit: points and lines without NORMAL]"
        material_names[ukey] = unlit.name
        materials[ukey] = unlit
    return materials[ukey]
