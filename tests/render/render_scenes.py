"""Small analytic test scenes (JSON scene dicts) shared by the rendering tests."""

import copy


def one_sphere(material, lights, size=(64, 64), environment=None, fov=30.0, tonemap="none"):
    return {
        "camera": {"position": [0, 0, 6], "target": [0, 0, 0], "fov_y_deg": fov, "size": list(size)},
        "lights": copy.deepcopy(lights),
        "environment": environment,
        "materials": {"m": dict(material)},
        "objects": [{"sphere": {"center": [0, 0, 0], "radius": 1.0}, "material": "m"}],
        "render": {"tonemap": tonemap},
    }


def layer_sphere(material):
    """One sphere under a directional and a point light and a constant environment: a
    surface file's or Unity shader's layers against the same JSON material's."""
    return one_sphere(material, [{"type": "directional", "direction": [-0.5, -0.3, -1.0]},
                                 {"type": "point", "position": [1, 2, 2], "intensity": 5}],
                      environment={"color": [0.3, 0.3, 0.35]})


def light_zoo():
    """Directional, point and spot lights with ranges, on a row of three materials."""
    scene = one_sphere({"albedo": [0.8, 0.2, 0.1], "smoothness": 0.7}, [], size=(160, 64), fov=25)
    scene["camera"]["position"] = [0, 0, 12]
    scene["materials"] = {
        "plastic": {"albedo": [0.8, 0.2, 0.1], "smoothness": 0.7},
        "gold": {"albedo": [1.0, 0.766, 0.336], "metallic": 1.0, "smoothness": 0.5},
        "rough": {"workflow": "specular", "albedo": [0.3, 0.5, 0.3], "specular": [0.04] * 3,
                  "smoothness": 0.1},
    }
    scene["objects"] = [{"sphere": {"center": [x, 0, 0], "radius": 1.0}, "material": m}
                        for x, m in ((-2.5, "plastic"), (0, "gold"), (2.5, "rough"))]
    scene["lights"] = [
        {"type": "directional", "direction": [0.3, -0.5, -1], "intensity": 1.2},
        {"type": "point", "position": [-2, 2, 3], "color": [1, 0.8, 0.6], "intensity": 12, "range": 9},
        {"type": "spot", "position": [3, 1, 4], "direction": [-0.1, -0.2, -1], "intensity": 25,
         "inner_cone_deg": 8, "outer_cone_deg": 20},
    ]
    return scene
