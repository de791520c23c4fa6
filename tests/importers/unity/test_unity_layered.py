"""Unity surface shaders on pbrlab's layered models (``#pragma surface surf StandardLayered``,
``StandardSpecularLayered``): Unity's Standard fields plus URP's layer names in one output
struct, shaded by the same code as a JSON material with the same layers, in both languages."""

from __future__ import annotations

import re
import sys
from pathlib import Path

import numpy as np
import pytest

from pbrlab.render import features, renderer as render
from pbrlab import scene
from pbrlab.checking.compare import float32_ulps
from pbrlab.importers.unity import UnityShaderError, load_shader, parse

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "render"))
from render_scenes import layer_sphere  # noqa: E402

SHADERS = Path(__file__).parent / "shaders"
LANGUAGES = ("hlsl", "glsl")
# shader -> (the JSON material it is, the layers it writes)
LAYERED = {
    "clear_coat_layered.shader": ({"albedo": [0.8, 0.3, 0.2], "metallic": 0.25, "smoothness": 0.4,
                                   "clearcoat": 1.0, "clearcoat_smoothness": 0.85}, {"clearcoat"}),
    "sheen_specular_layered.shader": ({"workflow": "specular", "albedo": [0.2, 0.3, 0.6], "specular": [0.04] * 3,
                                       "smoothness": 0.5, "sheen_color": [0.6, 0.5, 0.9], "sheen_smoothness": 0.3,
                                       "clearcoat": 0.5}, {"sheen", "clearcoat"}),
}
# The front end's program and the default surface's: the same pbrlab_shade_surface, the
# material's numbers arriving as properties (Unity) or uniforms (JSON), the unwritten normal
# taken as the interpolated one (Unity) or through the tangent frame (JSON, normalised again).
# Measured: the coat 4 ulp per channel, the sheen under a coat 6 ulp (4.8e-7 absolute;
# radiance up to 16.3), both languages; bound 12 ulp of the JSON value.
ULP_BOUND = 12


def _scene(material):
    return scene.parse_scene(layer_sphere(material), "<test>", SHADERS)


@pytest.mark.parametrize("language", LANGUAGES)
@pytest.mark.parametrize("shader", sorted(LAYERED))
def test_a_layered_unity_shader_renders_like_the_json_material(shader, language):
    json_material, _ = LAYERED[shader]
    got = render.render_scene(_scene({"surface": shader}), language=language).linear
    want = render.render_scene(_scene(json_material), language=language).linear
    without_layers = {k: v for k, v in json_material.items() if k.startswith(("workflow", "albedo", "specular",
                                                                              "metallic", "smoothness"))}
    bare = render.render_scene(_scene(without_layers), language=language).linear
    covered = want[..., 3] > 0
    assert covered.sum() > 1000 and np.array_equal(got[..., 3] > 0, covered)
    assert float32_ulps(want[..., :3], got[..., :3])[covered].max() <= ULP_BOUND
    assert np.abs(bare - want)[..., :3].max() > 0.1  # the layers are there


@pytest.mark.parametrize("shader", sorted(LAYERED))
def test_a_layered_shader_compiles_the_layers_it_writes(shader):
    _, written = LAYERED[shader]
    assert load_shader(SHADERS / shader).surface.layers == written
    f = features.material_features(_scene({"surface": shader}).materials["m"])
    assert {layer for layer in features.LAYERS if getattr(f, layer)} == written


def test_a_layered_model_writing_no_layer_is_the_standard_shader(tmp_path):
    text = (SHADERS / "clear_coat_layered.shader").read_text()
    text = re.sub(r"\n\s*o\.ClearCoat\w+ = [^;]+;", "", text)
    (tmp_path / "plain.shader").write_text(text)
    assert load_shader(tmp_path / "plain.shader").surface.layers == frozenset()
    got = render.render_scene(_scene({"surface": str(tmp_path / "plain.shader")}), language="hlsl").linear
    want = render.render_scene(_scene({"albedo": [0.8, 0.3, 0.2], "metallic": 0.25, "smoothness": 0.4}),
                               language="hlsl").linear
    assert float32_ulps(want[..., :3], got[..., :3])[want[..., 3] > 0].max() <= ULP_BOUND


@pytest.mark.parametrize("edit, message", [
    # the brief's spelling of the model is not one: the clear error names the built-in ones
    (("surf StandardLayered", "surf StandardLayers"),
     r"#pragma surface names lighting model 'StandardLayers', but there is no LightingStandardLayers\(\.\.\.\) "
     r"function \(built in: .*StandardLayered, StandardSpecularLayered\)"),
    (("SurfaceOutputStandardLayered o", "SurfaceOutputStandard o"),
     r"surf fills SurfaceOutputStandard, but lighting model StandardLayered takes SurfaceOutputStandardLayered"),
    (("o.ClearCoatMask = 1;", "#ifdef POINT\n        o.ClearCoatMask = 1;\n        #endif"),
     r"lighting model StandardLayered shades every light in one program, so it cannot test Unity's per-light"),
])
def test_layered_model_mistakes_are_refused_by_name(tmp_path, edit, message):
    (tmp_path / "x.shader").write_text((SHADERS / "clear_coat_layered.shader").read_text().replace(*edit))
    with pytest.raises(UnityShaderError, match=r"x.shader:\d+: " + message):
        parse.parse_file(tmp_path / "x.shader")


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_scalar_written_to_a_layer_vector_is_ported_as_unity_reads_it(tmp_path, language):
    """o.SheenColor = 0.5 (Cg widens the scalar): the port knows the layered struct's fields."""
    text = (SHADERS / "sheen_specular_layered.shader").read_text()
    (tmp_path / "x.shader").write_text(text.replace("o.SheenColor = _SheenColor.rgb;", "o.SheenColor = 0.5;"))
    json_material = dict(LAYERED["sheen_specular_layered.shader"][0], sheen_color=[0.5, 0.5, 0.5])
    got = render.render_scene(_scene({"surface": str(tmp_path / "x.shader")}), language=language).linear
    want = render.render_scene(_scene(json_material), language=language).linear
    assert float32_ulps(want[..., :3], got[..., :3])[want[..., 3] > 0].max() <= ULP_BOUND
