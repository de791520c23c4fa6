"""Generates the skinned and animated glTF test asset (issue 24). Committed next to this
script; run it again to rebuild it byte for byte.

    skinned_strip.gltf  a strip 0.5 wide and 2 tall standing on the origin (x in
                        [-0.25, 0.25], y in [0, 2], 9 rows), skinned to two joints: joint 0
                        at the origin, joint 1 its child at (0, 1, 0) (inverse bind matrices
                        the identity and a translation by (0, -1, 0)). Each vertex weighs
                        joint 1 by clip(y - 0.5, 0, 1) and joint 0 by the rest, so the rest
                        pose is the strip as built, and a rotation of joint 1 bends it about
                        (0, 1, 0). Beside it (x = 1.5) a quad with one morph target that
                        pushes its top edge up by 0.5. Four animations:
                          0 "bend"    joint 1 rotation, LINEAR: 0, 90, 0 degrees about +Z
                                      at 0, 1, 2 s
                          1 "slide"   joint 0 translation, STEP: (0,0,0) at 0 s, (1,0,0) at 1 s
                          2 "breathe" joint 0 scale, CUBICSPLINE: 1 at 0 s, 2 at 1 s, in- and
                                      out-tangents 0 then 3 (per second), all three axes
                          3 "morph"   the quad's morph weight, LINEAR: 0 at 0 s, 1 at 1 s
                        A directional light and a camera looking at the strip.

    .venv/bin/python scenes/gltf/make_animated_assets.py
"""

from __future__ import annotations

import math

import numpy as np

from make_assets import HERE, Builder, _look_rotation

ROWS = 9
WIDTH, HEIGHT = 0.5, 2.0
BEND_DEGREES = 90.0


def strip():
    """Positions, normals, faces, joints and weights of the strip (module doc)."""
    y = np.linspace(0.0, HEIGHT, ROWS)
    positions = np.array([[x, yy, 0.0] for yy in y for x in (-WIDTH / 2, WIDTH / 2)])
    normals = np.tile([0.0, 0.0, 1.0], (len(positions), 1))
    faces = np.array([[2 * r, 2 * r + 1, 2 * r + 3] for r in range(ROWS - 1)]
                     + [[2 * r, 2 * r + 3, 2 * r + 2] for r in range(ROWS - 1)])
    upper = np.clip(positions[:, 1] - 0.5, 0.0, 1.0)
    joints = np.zeros((len(positions), 4), np.int64)
    joints[:, 1] = upper > 0  # an unused slot names joint 0 (the validator: a zero weight, joint 0)
    weights = np.stack([1.0 - upper, upper, np.zeros_like(upper), np.zeros_like(upper)], axis=1)
    return positions, normals, faces, joints, weights


def _data(b: Builder, array, kind: str, bounds: bool = False) -> int:
    """A float accessor in a buffer view without a vertex target (animation data, matrices)."""
    array = np.ascontiguousarray(array, np.float32)
    acc = {"bufferView": b.view(array.tobytes()), "componentType": 5126, "count": len(array), "type": kind}
    if bounds:
        acc["min"] = array.min(axis=0).tolist()
        acc["max"] = array.max(axis=0).tolist()
    return b.add("accessors", acc)


def _animation(b: Builder, name: str, node: int, path: str, interpolation: str, times, values, kind: str) -> None:
    times = np.asarray(times, np.float64).reshape(-1, 1)
    sampler = {"input": _data(b, times, "SCALAR", bounds=True), "output": _data(b, values, kind),
               "interpolation": interpolation}
    b.add("animations", {"name": name, "samplers": [sampler],
                         "channels": [{"sampler": 0, "target": {"node": node, "path": path}}]})


def skinned_strip():
    b = Builder()
    clay = b.add("materials", {"name": "clay", "pbrMetallicRoughness": {
        "baseColorFactor": [0.8, 0.5, 0.3, 1], "metallicFactor": 0.0, "roughnessFactor": 0.6}})
    positions, normals, faces, joints, weights = strip()
    primitive = b.primitive(positions, normals, None, faces, clay)
    primitive["attributes"]["JOINTS_0"] = b.accessor(joints, "VEC4", 5121)
    primitive["attributes"]["WEIGHTS_0"] = b.accessor(weights, "VEC4")
    b.json["meshes"].append({"name": "strip", "primitives": [primitive]})
    quad_positions = np.array([[-0.25, 0, 0], [0.25, 0, 0], [0.25, 0.5, 0], [-0.25, 0.5, 0]])
    quad = b.primitive(quad_positions, np.tile([0.0, 0.0, 1.0], (4, 1)), None, [0, 1, 2, 0, 2, 3], clay)
    quad["targets"] = [{"POSITION": b.accessor([[0, 0, 0], [0, 0, 0], [0, 0.5, 0], [0, 0.5, 0]], "VEC3",
                                               bounds=True)}]
    b.json["meshes"].append({"name": "morphing quad", "primitives": [quad], "weights": [0.0]})

    root = b.add("nodes", {"name": "joint 0", "children": [1]})
    b.add("nodes", {"name": "joint 1", "translation": [0.0, 1.0, 0.0]})
    inverse_bind = np.stack([np.eye(4), np.array([[1, 0, 0, 0], [0, 1, 0, -1.0], [0, 0, 1, 0], [0, 0, 0, 1]])])
    b.add("skins", {"joints": [0, 1], "skeleton": 0,
                    "inverseBindMatrices": _data(b, inverse_bind.transpose(0, 2, 1).reshape(-1, 16), "MAT4")})
    skinned = b.add("nodes", {"name": "strip", "mesh": 0, "skin": 0})
    morphing = b.add("nodes", {"name": "morphing quad", "mesh": 1, "translation": [1.5, 0.0, 0.0]})

    half = math.radians(BEND_DEGREES) / 2
    bent = [0.0, 0.0, math.sin(half), math.cos(half)]
    _animation(b, "bend", 1, "rotation", "LINEAR", [0, 1, 2], [[0, 0, 0, 1], bent, [0, 0, 0, 1]], "VEC4")
    _animation(b, "slide", root, "translation", "STEP", [0, 1], [[0, 0, 0], [1, 0, 0]], "VEC3")
    # CUBICSPLINE output: (in-tangent, value, out-tangent) per keyframe
    _animation(b, "breathe", root, "scale", "CUBICSPLINE", [0, 1],
               [[0, 0, 0], [1, 1, 1], [0, 0, 0], [3, 3, 3], [2, 2, 2], [3, 3, 3]], "VEC3")
    _animation(b, "morph", morphing, "weights", "LINEAR", [0, 1], [[0.0], [1.0]], "SCALAR")

    b.json["extensionsUsed"] = ["KHR_lights_punctual"]
    b.json["extensions"] = {"KHR_lights_punctual": {"lights": [{"type": "directional", "intensity": 3.0}]}}
    light = b.add("nodes", {"rotation": _look_rotation([0.4, -0.5, -1.0]),
                            "extensions": {"KHR_lights_punctual": {"light": 0}}})
    b.json["cameras"] = [{"type": "perspective", "perspective": {"yfov": 0.8, "aspectRatio": 1.5, "znear": 0.1}}]
    camera_at = np.array([0.5, 1.0, 5.0])
    camera = b.add("nodes", {"camera": 0, "translation": camera_at.tolist(),
                             "rotation": _look_rotation(np.array([0.5, 1.0, 0.0]) - camera_at)})
    b.json["scenes"] = [{"nodes": [root, skinned, morphing, light, camera]}]
    b.json["scene"] = 0
    b.write_gltf(HERE / "skinned_strip.gltf", external_bin=False)


if __name__ == "__main__":
    skinned_strip()
