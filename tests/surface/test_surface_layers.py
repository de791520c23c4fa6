"""A surface file writes the layers beyond the Standard model (SurfaceOutputStandardLayers, in
the third parameter of its surf): lit by the same LightingStandardLayers code as a JSON
material's fields, compiled in exactly where the surface writes them (surface_layers.py)."""

from __future__ import annotations

import re
import sys
from pathlib import Path

import numpy as np
import pytest

from pbrlab.render import features, renderer as render
from pbrlab import scene
from pbrlab.checking.compare import float32_ulps
from pbrlab.foundation.errors import SceneError
from pbrlab.scene.surface_layers import written_layers

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "render"))
from render_scenes import layer_sphere  # noqa: E402

SURFACES = Path(__file__).parent / "layered_surfaces"
LANGUAGES = ("glsl", "hlsl")
BASE = {"albedo": [0.8, 0.3, 0.2], "metallic": 0.25, "smoothness": 0.4}
COAT = {"clearcoat": 1.0, "clearcoat_smoothness": 0.85}
EVERY_LAYER = {"clearcoat": 0.7, "clearcoat_smoothness": 0.85, "sheen_color": [0.5, 0.4, 0.9],
               "sheen_smoothness": 0.6, "anisotropy_strength": 0.6, "iridescence": 0.8,
               "iridescence_thickness_max": 500.0, "transmission": 0.5}
# A surface file against the same material as JSON numbers: the surface's constants are
# folded by the compiler where the JSON material's uniforms are read at run time, and a
# surface file compiles emission, occlusion and alpha (features.py). A plain surface (no
# layer) already differs from its JSON twin by up to 4 ulp per channel (measured, both
# languages; radiance up to 16.3); with the coat 3 ulp, with every layer 4 ulp; bound 8 ulp
# of the JSON value.
ULP_BOUND = 8


def _scene(material, folder=SURFACES):
    return scene.parse_scene(layer_sphere(material), "<test>", folder)


@pytest.mark.parametrize("language", LANGUAGES)
@pytest.mark.parametrize("surface, fields", [("coat.glsl", COAT), ("every_layer.glsl", EVERY_LAYER)],
                         ids=["coat", "every_layer"])
def test_a_surface_file_writing_layers_renders_like_the_json_material(surface, fields, language):
    got = render.render_scene(_scene({"surface": surface}), language=language).linear
    want = render.render_scene(_scene({**BASE, **fields}), language=language).linear
    bare = render.render_scene(_scene(BASE), language=language).linear
    covered = want[..., 3] > 0
    assert covered.sum() > 1000 and np.array_equal(got[..., 3] > 0, covered)
    assert float32_ulps(want[..., :3], got[..., :3])[covered].max() <= ULP_BOUND
    # the layers are there: without them the image is another one (by up to 17 in radiance)
    assert np.abs(bare - want)[..., :3].max() > 1.0


SPECULAR_BASE = {"workflow": "specular", "albedo": [0.8, 0.3, 0.2], "specular": [0.01, 0.01, 0.0], "smoothness": 0.6}


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_surface_file_writing_specular_f90_renders_like_the_json_material(language):
    """SpecularF90 (KHR_materials_specular's F90) from a surface file and from JSON
    specular_f90: the same image to ULP_BOUND; without it F90 follows F0 (0.5 here against
    pbr_f90_from_f0's 16.5 x 0.02 = 0.33) and the rims differ."""
    got = render.render_scene(_scene({"surface": "specular_f90.glsl", "workflow": "specular"}),
                              language=language).linear
    want = render.render_scene(_scene({**SPECULAR_BASE, "specular_f90": 0.5}), language=language).linear
    bare = render.render_scene(_scene(SPECULAR_BASE), language=language).linear
    covered = want[..., 3] > 0
    assert covered.sum() > 1000 and np.array_equal(got[..., 3] > 0, covered)
    assert float32_ulps(want[..., :3], got[..., :3])[covered].max() <= ULP_BOUND
    assert np.abs(bare - want)[..., :3].max() > 0.01


METALLIC_BASE = {"albedo": [0.8, 0.3, 0.2], "metallic": 0.5, "smoothness": 0.6}


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_surface_file_writing_the_dielectric_f0_renders_like_the_json_material(language):
    """DielectricSpecular and SpecularF90 (KHR_materials_ior / _specular on a half metal) from a
    surface file and from JSON dielectric_specular / specular_f90: the same image to ULP_BOUND;
    without them the dielectric is 0.04 and F90 follows F0, and the image differs."""
    got = render.render_scene(_scene({"surface": "dielectric_specular.glsl"}), language=language).linear
    want = render.render_scene(_scene({**METALLIC_BASE, "dielectric_specular": [0.12, 0.05, 0.0],
                                       "specular_f90": 0.6}), language=language).linear
    bare = render.render_scene(_scene(METALLIC_BASE), language=language).linear
    covered = want[..., 3] > 0
    assert covered.sum() > 1000 and np.array_equal(got[..., 3] > 0, covered)
    assert float32_ulps(want[..., :3], got[..., :3])[covered].max() <= ULP_BOUND
    assert np.abs(bare - want)[..., :3].max() > 0.01


F90_LAYERS = {"anisotropy_strength": 0.6, "iridescence": 0.8, "iridescence_thickness_max": 500.0, "transmission": 0.5}


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_surface_file_writing_specular_f90_with_base_layers_renders_like_the_json_material(language):
    """SpecularF90 beside the anisotropy, the film and the transmission (each reads it:
    pbr/unity/surface_layers.glsl) from a surface file and from JSON: the same image to
    ULP_BOUND, and another one with F90 from F0 (the layers' own F90 is read)."""
    got = render.render_scene(_scene({"surface": "specular_f90_layers.glsl", "workflow": "specular"}),
                              language=language).linear
    want = render.render_scene(_scene({**SPECULAR_BASE, **F90_LAYERS, "specular_f90": 0.5}),
                               language=language).linear
    from_f0 = render.render_scene(_scene({**SPECULAR_BASE, **F90_LAYERS}), language=language).linear
    covered = want[..., 3] > 0
    assert covered.sum() > 1000 and np.array_equal(got[..., 3] > 0, covered)
    assert float32_ulps(want[..., :3], got[..., :3])[covered].max() <= ULP_BOUND
    assert np.abs(from_f0 - want)[..., :3].max() > 0.01


def test_the_layers_compiled_are_the_ones_the_surface_writes():
    def layers(surface):
        f = features.material_features(_scene({"surface": surface}).materials["m"])
        return {layer for layer in features.LAYERS if getattr(f, layer)}

    assert layers("coat.glsl") == {"clearcoat"}
    # every layer but the explicit F90 (its JSON twin is metallic; JSON's specular_f90 is the specular
    # workflow's) and the metallic workflow's dielectric F0 (dielectric_specular.glsl below)
    assert layers("every_layer.glsl") == set(features.LAYERS) - {"specular_f90", "dielectric_specular"}
    assert layers("specular_f90.glsl") == {"specular_f90"}
    assert layers("specular_f90_layers.glsl") == {"specular_f90", "anisotropy", "iridescence", "transmission"}
    assert layers("dielectric_specular.glsl") == {"dielectric_specular", "specular_f90"}
    assert layers("../../../scenes/unity_example/brick_surface.glsl") == set()


def test_a_write_is_an_assignment_to_a_layer_field_outside_comments():
    assert written_layers("l.SheenColor.rgb *= t; x.Anisotropy= 1.0;") == {"sheen", "anisotropy"}
    assert written_layers("if (l.Transmission == 0.0) { y = l.ClearCoatMask; }") == set()
    assert written_layers("o . IridescenceIor += 0.1;") == {"iridescence"}


@pytest.mark.parametrize("text, message", [
    ("void surf(Input IN, inout SurfaceOutputStandard o) { o.ClearCoatMask = 1.0; }",
     "writes ClearCoatMask (layers beyond SurfaceOutputStandard), so its surface function takes them"),
    ("void surf(Input IN, inout SurfaceOutputStandard o, inout SurfaceOutputStandardLayers l) { o.Albedo = vec3(1.0); }",
     "surf takes SurfaceOutputStandardLayers but writes none of its fields"),
])
def test_a_surface_whose_parameters_and_writes_disagree_is_refused_by_name(tmp_path, text, message):
    (tmp_path / "s.glsl").write_text(text)
    with pytest.raises(SceneError, match=re.escape("s.glsl: " + message)):
        render.render_scene(_scene({"surface": "s.glsl"}, tmp_path))


def test_an_hlsl_twin_writing_other_layers_is_refused_by_name(tmp_path):
    (tmp_path / "s.glsl").write_text((SURFACES / "coat.glsl").read_text())
    (tmp_path / "s.hlsl").write_text((SURFACES / "every_layer.hlsl").read_text())
    with pytest.raises(SceneError, match=r"materials.m: s.hlsl writes the layers \['anisotropy', 'clearcoat', "
                                         r"'iridescence', 'sheen', 'transmission'\], s.glsl writes \['clearcoat'\]"):
        render.render_scene(_scene({"surface": "s.glsl"}, tmp_path), language="hlsl")


def test_unitys_brdf_model_refuses_a_surface_writing_a_base_layer():
    data = {"camera": {"position": [0, 0, 4], "target": [0, 0, 0], "size": [8, 8]},
            "materials": {"m": {"surface": "every_layer.glsl"}}, "render": {"brdf_model": "unity"},
            "objects": [{"sphere": {"center": [0, 0, 0], "radius": 1}, "material": "m"}]}
    with pytest.raises(SceneError, match="render.brdf_model: Unity's BRDFs have no anisotropic lobe; "
                                         "material 'm' is anisotropic"):
        scene.parse_scene(data, "<test>", SURFACES)
