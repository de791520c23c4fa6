"""The JSON material fields specular_f90 (KHR_materials_specular's F90) and dielectric_specular
(the metallic workflow's dielectric F0): what the parser refuses, by name (scene.py), and what
the features turn on (features.py)."""

import pytest

from pbrlab.render import features
from pbrlab.foundation.errors import PbrlabError
from pbrlab.scene import parse_scene

BASE = {"camera": {"position": [0, 0, 5], "target": [0, 0, 0]}, "lights": [],
        "objects": [{"sphere": {"center": [0, 0, 0], "radius": 1}, "material": "m"}]}
SPECULAR = {"workflow": "specular", "specular": [0.02, 0.02, 0.02]}


@pytest.mark.parametrize("material, render, message", [
    ({"metallic": 0.5, "dielectric_specular": [0.6, 0.0, 0.0], "specular_f90": 0.5}, {},
     "F90 0.5 is below the F0 `dielectric_specular` 0.6"),
    ({"metallic": 0.5, "specular_f90": 0.03}, {}, "F90 0.03 is below the F0 `dielectric_specular` 0.04"),
    ({**SPECULAR, "specular": [0.2, 0.0, 0.0], "specular_f90": 0.1}, {}, "F90 0.1 is below the F0 `specular` 0.2"),
    ({**SPECULAR, "specular_f90": 1.5}, {}, "materials.m.specular_f90: expected a number in [0.0, 1.0]"),
    ({**SPECULAR, "specular_f90": 0.5}, {"brdf_model": "unity"}, "render.brdf_model: Unity's BRDFs take F90 from F0"),
], ids=["metallic_below_dielectric_f0", "metallic_below_default_f0", "below_f0", "above_one", "unity"])
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


@pytest.mark.parametrize("material, render, message", [
    ({**SPECULAR, "dielectric_specular": [0.02, 0.02, 0.02]}, {},
     "materials.m.dielectric_specular: belongs to the metallic workflow"),
    ({"dielectric_specular": [0.02, 1.5, 0.02]}, {}, "materials.m.dielectric_specular"),
    ({"dielectric_specular": [0.02, 0.02, 0.02], "surface": "x.glsl"}, {},
     "materials.m.dielectric_specular: the dielectric F0 belongs to the default surface"),
    ({"metallic": 0.5, "dielectric_specular": [0.02, 0.02, 0.02]}, {"brdf_model": "unity"},
     "render.brdf_model: Unity's metallic setup has the dielectric F0 0.04"),
], ids=["specular_workflow", "above_one", "surface_file", "unity"])
def test_dielectric_specular_is_refused_by_name(material, render, message, tmp_path):
    (tmp_path / "x.glsl").write_text("void surf(Input IN, inout SurfaceOutputStandard o) {}\n")
    with pytest.raises(PbrlabError, match=".*" + message.replace("[", r"\[").replace("]", r"\]")
                       .replace("(", r"\(").replace(")", r"\)").replace(".", r"\.")):
        parse_scene(dict(BASE, materials={"m": material}, render=render), base=tmp_path)


def test_dielectric_specular_is_a_layer_only_where_given():
    given = parse_scene(dict(BASE, materials={"m": {"metallic": 0.5, "dielectric_specular": [0.1, 0.2, 0.3],
                                                    "specular_f90": 0.5}}))
    without = parse_scene(dict(BASE, materials={"m": {"metallic": 0.5}}))
    assert given.materials["m"].dielectric_specular.tolist() == [0.1, 0.2, 0.3]
    assert without.materials["m"].dielectric_specular is None
    on, off = (features.material_features(s.materials["m"]) for s in (given, without))
    assert on.dielectric_specular and on.specular_f90 and not off.dielectric_specular


@pytest.mark.parametrize("layer", [{"transmission": 0.5}, {"anisotropy_strength": 0.5}, {"iridescence": 0.5},
                                   {"clearcoat": 0.5}, {"sheen_color": [0.5, 0.5, 0.5]}],
                         ids=["transmission", "anisotropy", "iridescence", "clearcoat", "sheen"])
def test_specular_f90_combines_with_every_layer(layer):
    """Every layer's base reads the explicit F90 (pbr/unity/surface_layers.glsl), so none is refused."""
    scene = parse_scene(dict(BASE, materials={"m": {**SPECULAR, "specular_f90": 0.5, **layer}}))
    assert features.material_features(scene.materials["m"]).specular_f90
