"""Issue 26 (round two), the numbers: a direction too short for its square, a fractional
subdivision count, an unknown primitive parameter, a display transfer the API lacks."""

import numpy as np
import pytest

from hostile_common import base_scene
from pbrlab.foundation.errors import PbrlabError
from pbrlab.render.renderer import render_scene
from pbrlab.scene import parse_scene


def test_a_tiny_light_direction_is_still_its_direction(gl_context, census):
    """[1e-200, 1e-200, -1e-200]: |v|² underflows to 0 in float64 (it rendered black); the
    direction is the same as [1, 1, -1]'s."""
    tiny, plain = base_scene(), base_scene()
    tiny["lights"][0]["direction"] = [1e-200, 1e-200, -1e-200]
    plain["lights"][0]["direction"] = [1, 1, -1]
    a = render_scene(parse_scene(tiny), gl_context).linear
    b = render_scene(parse_scene(plain), gl_context).linear
    np.testing.assert_array_equal(a, b)
    assert a[..., :3].max() > 0
    census["light direction", "handled"] += 1


@pytest.mark.parametrize("value, ok", [(2.5, False), (9, False), (-1, False), (True, False), ("3", False),
                                       (3.0, True), (0, True)])
def test_subdivisions_are_whole_numbers_in_range(value, ok, census):
    scene = base_scene()
    scene["objects"][1]["mesh"] = {"primitive": "icosphere", "subdivisions": value}
    if ok:
        assert parse_scene(scene).objects[1].primitive["subdivisions"] == int(value)
        census["primitive parameter", "handled"] += 1
        return
    with pytest.raises(PbrlabError, match=r"objects\[1\]\.mesh\.subdivisions: expected a whole number in \[0, 8\]"):
        parse_scene(scene)
    census["primitive parameter", "refused cleanly"] += 1


def test_an_unknown_primitive_parameter_is_refused_when_the_scene_is_read(census):
    scene = base_scene()
    scene["objects"][1]["mesh"] = {"primitive": "box", "size": 1.0, "radius": 2.0}
    with pytest.raises(PbrlabError, match=r"objects\[1\]\.mesh\.radius: unknown parameter of a box; use size"):
        parse_scene(scene)
    census["primitive parameter", "refused cleanly"] += 1


def test_an_unknown_transfer_is_a_pbrlab_error_naming_the_choices(gl_context, census):
    with pytest.raises(PbrlabError, match="transfer='LINEAR': expected one of EXACT, HARDWARE, SRGB"):
        render_scene(parse_scene(base_scene()), gl_context, transfer="LINEAR")
    census["api argument", "refused cleanly"] += 1


NULL_SHADER = """Shader "Test/Null" {
    Properties {
        _Color ("Color", Color) = (1,1,1,1)
        _Glossiness ("Smoothness", Range(0,1)) = 0.5
        _MainTex ("Albedo", 2D) = "white" {}
    }
    SubShader {
        CGPROGRAM
        #pragma surface surf Standard
        sampler2D _MainTex;
        fixed4 _Color;
        half _Glossiness;
        struct Input { float2 uv_MainTex; };
        void surf (Input IN, inout SurfaceOutputStandard o) {
            o.Albedo = tex2D(_MainTex, IN.uv_MainTex).rgb * _Color.rgb;
            o.Smoothness = _Glossiness;
        }
        ENDCG
    }
}
"""


@pytest.mark.parametrize("name", ["_Glossiness", "_Color", "_MainTex"])
def test_a_null_property_value_is_refused_not_taken_as_the_default(tmp_path, name, census):
    import json
    from pbrlab.scene import load_scene
    (tmp_path / "null.shader").write_text(NULL_SHADER)
    scene = base_scene()
    scene["materials"]["m"] = {"surface": "null.shader", "properties": {name: None}}
    (tmp_path / "scene.json").write_text(json.dumps(scene))
    with pytest.raises(PbrlabError, match=rf"properties\.{name}: null is not a value"):
        load_scene(tmp_path / "scene.json")
    scene["materials"]["m"]["properties"] = {}
    (tmp_path / "scene.json").write_text(json.dumps(scene))
    assert load_scene(tmp_path / "scene.json").materials["m"].properties["_Glossiness"] == 0.5
    census["unity properties", "refused cleanly"] += 1
