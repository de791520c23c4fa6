"""A lone Unity ``.shader`` as a scene: the shader on the default sphere.

``pbrlab render X.shader -o x.png`` draws X on one unit sphere at the origin, seen from +Z,
lit by one white directional light from the upper right front and a dim grey environment, with
the shader's ``Properties`` at their defaults; the scene (PREVIEW_SCENE, as JSON) is what a
scene file naming the shader as a material's ``surface`` would say, so a user who wants other
lights or property values copies it. The loader (loader.py) picks this reader by the suffix.
"""

from __future__ import annotations

import copy
from pathlib import Path

SUFFIX = ".shader"

# The scene a lone shader is drawn in; "surface" is filled in with the shader's file name.
PREVIEW_SCENE = {
    "camera": {"position": [0.0, 0.0, 4.0], "target": [0.0, 0.0, 0.0], "fov_y_deg": 35, "size": [256, 256]},
    "lights": [{"type": "directional", "direction": [-0.4, -0.5, -0.75], "color": [1.0, 1.0, 1.0],
                "intensity": 1.0}],
    "environment": {"color": [0.1, 0.1, 0.1]},
    "materials": {"shader": {"surface": None}},
    "objects": [{"sphere": {"center": [0.0, 0.0, 0.0], "radius": 1.0}, "material": "shader"}],
    "render": {"tonemap": "none"},
}


def is_lone_shader(path) -> bool:
    """A Unity shader file named where a scene file was expected."""
    return Path(path).suffix.lower() == SUFFIX


def preview_scene_data(path) -> dict:
    """The default-sphere scene as JSON data, its material's surface the shader's file name
    (relative to the shader's folder, the scene's base)."""
    data = copy.deepcopy(PREVIEW_SCENE)
    data["materials"]["shader"]["surface"] = Path(path).name
    return data
