"""Shared pieces of the hostile suite: a small valid scene, hypothesis settings, and the
check that a refusal is clean (a PbrlabError whose message names where the problem is)."""

import copy

from hypothesis import HealthCheck, settings

# Few examples, no deadline, a fixed seed and no example database: the suite must run in
# CI in seconds, the same way every time, and leave no .hypothesis folder behind.
FAST = settings(max_examples=60, deadline=None, derandomize=True, database=None,
                suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture])
SLOW = settings(FAST, max_examples=12)  # each example renders or spawns a process

BASE_SCENE = {
    "camera": {"position": [0, 0, 6], "target": [0, 0, 0], "fov_y_deg": 30, "size": [8, 6]},
    "lights": [{"type": "directional", "direction": [0.2, -0.4, -1], "intensity": 2.0},
               {"type": "point", "position": [1, 2, 3], "intensity": 5.0, "range": 20},
               {"type": "spot", "position": [0, 3, 3], "direction": [0, -1, -1], "intensity": 9,
                "inner_cone_deg": 10, "outer_cone_deg": 30}],
    "environment": {"color": [0.1, 0.1, 0.2], "intensity": 1.0},
    "materials": {"m": {"albedo": [0.8, 0.3, 0.2], "smoothness": 0.6, "metallic": 0.0},
                  "s": {"workflow": "specular", "specular": [0.04, 0.04, 0.04], "alpha": 0.5,
                        "alpha_mode": "fade", "brdf": {"specular_d": "ggx"}}},
    "objects": [{"sphere": {"center": [0, 0, 0], "radius": 1.0}, "material": "m"},
                {"mesh": {"primitive": "box", "size": 1.0}, "material": "s",
                 "transform": {"translate": [1, 0, 0], "rotate_deg": [0, 30, 0], "scale": 0.5}}],
    "render": {"quality": "high", "tonemap": "reinhard", "exposure": 0.0,
               "energy_compensation": True, "hdr_target": "rgba32f"},
}


def base_scene():
    return copy.deepcopy(BASE_SCENE)


def leaf_paths(node, path=()):
    """Every (path) to a value in a JSON-like tree, containers included."""
    yield path
    if isinstance(node, dict):
        for key, value in node.items():
            yield from leaf_paths(value, path + (key,))
    elif isinstance(node, list):
        for i, value in enumerate(node):
            yield from leaf_paths(value, path + (i,))


def replace_at(tree, path, value):
    if not path:
        return value
    node = tree
    for key in path[:-1]:
        node = node[key]
    node[path[-1]] = value
    return tree


def assert_clean_refusal(exc, origin=None):
    """A refusal is clean when it is a PbrlabError with a one-line-or-more message that says
    where (the origin file or a field path) and is not a Python repr of an exception."""
    from pbrlab.foundation.errors import PbrlabError
    assert isinstance(exc, PbrlabError), f"{type(exc).__name__}: {exc}"
    text = str(exc)
    assert text.strip(), "empty message"
    assert "Traceback" not in text
    if origin is not None:
        assert text.startswith(origin), text


# A Unity surface shader that shows its one texture property (the round-three path and output tests).
UNITY_TEXTURE = """Shader "Test/Texture" {
    Properties { _MainTex ("Texture", 2D) = "white" {} }
    SubShader {
        CGPROGRAM
        #pragma surface surf Lambert
        struct Input { float2 uv_MainTex; };
        sampler2D _MainTex;
        void surf (Input IN, inout SurfaceOutput o) { o.Albedo = tex2D (_MainTex, IN.uv_MainTex).rgb; }
        ENDCG
    }
}
"""
