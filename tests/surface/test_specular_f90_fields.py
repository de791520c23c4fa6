"""The JSON material field specular_f90 (KHR_materials_specular's F90): what the parser refuses,
by name (scene.py), and what the features turn on (features.py)."""

import pytest

from pbrlab import features
from pbrlab.errors import PbrlabError
from pbrlab.scene import parse_scene

BASE = {"camera": {"position": [0, 0, 5], "target": [0, 0, 0]}, "lights": [],
        "objects": [{"sphere": {"center": [0, 0, 0], "radius": 1}, "material": "m"}]}
SPECULAR = {"workflow": "specular", "specular": [0.02, 0.02, 0.02]}


@pytest.mark.parametrize("material, render, message", [
    ({"specular_f90": 0.5}, {}, "materials.m.specular_f90: belongs to the specular workflow"),
    ({**SPECULAR, "specular": [0.2, 0.0, 0.0], "specular_f90": 0.1}, {}, "F90 0.1 is below the F0 `specular` 0.2"),
    ({**SPECULAR, "specular_f90": 1.5}, {}, "materials.m.specular_f90: expected a number in [0.0, 1.0]"),
    ({**SPECULAR, "specular_f90": 0.5}, {"brdf_model": "unity"}, "render.brdf_model: Unity's BRDFs take F90 from F0"),
], ids=["metallic", "below_f0", "above_one", "unity"])
def test_specular_f90_is_refused_by_name(material, render, message):
    with pytest.raises(PbrlabError, match=".*" + message.replace("[", r"\[").replace("]", r"\]")
                       .replace("(", r"\(").replace(")", r"\)").replace(".", r"\.")):
        parse_scene(dict(BASE, materials={"m": material}, render=render))


def test_specular_f90_is_a_layer_only_where_given():
    with_f90 = parse_scene(dict(BASE, materials={"m": {**SPECULAR, "specular_f90": 0.5}}))
    without = parse_scene(dict(BASE, materials={"m": SPECULAR}))
    assert with_f90.materials["m"].specular_f90 == 0.5 and without.materials["m"].specular_f90 is None
    assert features.material_features(with_f90.materials["m"]).specular_f90
    assert not features.material_features(without.materials["m"]).specular_f90


@pytest.mark.parametrize("layer", [{"transmission": 0.5}, {"anisotropy_strength": 0.5}, {"iridescence": 0.5},
                                   {"clearcoat": 0.5}, {"sheen_color": [0.5, 0.5, 0.5]}],
                         ids=["transmission", "anisotropy", "iridescence", "clearcoat", "sheen"])
def test_specular_f90_combines_with_every_layer(layer):
    """Every layer's base reads the explicit F90 (pbr/unity/surface_layers.glsl), so none is refused."""
    scene = parse_scene(dict(BASE, materials={"m": {**SPECULAR, "specular_f90": 0.5, **layer}}))
    assert features.material_features(scene.materials["m"]).specular_f90
