"""KHR_materials_iridescence in scenes (iridescence, iridescence_ior, iridescence_thickness_min /
_max, the iridescence and iridescence_thickness maps): what a mask of 0 and a film of 0 nm
are, that the film colours a grey reflection, how the maps decode, GLSL against HLSL, and the
reader's refusals. The GPU-vs-float64 comparison is in test_gpu_matches_cpu_reference.py."""

import numpy as np
import pytest

from pbrlab.foundation.errors import SceneError
from pbrlab.render.renderer import render_scene
from pbrlab.scene import parse_scene

from render_scenes import one_sphere
from test_anisotropy_scene import LIGHTS, METAL, PLASTIC, _assert_float32_equal, _constant_map, _render

# A near-black dielectric: what it shows is mostly its specular reflection, so the film's
# colour is not hidden under a diffuse one.
DARK = {"albedo": [0.05, 0.05, 0.05], "smoothness": 0.8}
BASES = {"metal": METAL, "dielectric": PLASTIC, "dark": DARK}


@pytest.mark.parametrize("quality", ["high", "low"])
@pytest.mark.parametrize("base", sorted(BASES))
def test_mask_zero_through_the_map_is_the_filmless_material_bit_for_bit(base, quality, gl_context, tmp_path):
    """The iridescent program (iridescence 1) with a map whose red channel is 0: the mask is
    1 x 0 = 0, mix(F0, F0_film, 0) is F0 exactly, and the image is the filmless material's
    bit for bit (measured: every pixel, every base and tier)."""
    plain = _render(BASES[base], gl_context, quality=quality)
    masked = _render({**BASES[base], "iridescence": 1.0,
                      "textures": {"iridescence": _constant_map(tmp_path, (0, 255, 255))}}, gl_context, quality=quality)
    np.testing.assert_array_equal(masked.astype(np.float32).view(np.uint32), plain.astype(np.float32).view(np.uint32))


@pytest.mark.parametrize("base", sorted(BASES))
def test_a_film_of_zero_nanometres_is_the_filmless_material(base, gl_context):
    """Thickness 0 is Schlick's Fresnel of the base (pbr_F_Iridescence's rule), inverted back
    to the base's F0 (pbr_f0_from_schlick): the filmless image to float32 rounding (measured
    worst 3.1e-7 relative, 96 % of the pixels bit for bit; the bound of test_anisotropy_scene)."""
    plain = _render(BASES[base], gl_context)
    film = _render({**BASES[base], "iridescence": 1.0, "iridescence_thickness_max": 0.0}, gl_context)
    _assert_float32_equal(film, plain)


def _chroma(image):
    """(max - min) / max of each covered pixel's RGB: 0 for grey."""
    c = image[..., :3][image[..., 3] > 0]
    return (c.max(axis=-1) - c.min(axis=-1)) / np.maximum(c.max(axis=-1), 1e-12)


def test_the_film_colours_a_grey_reflection(gl_context):
    """A grey dark dielectric under a white light and a grey environment reflects grey
    (measured chroma 0: the same arithmetic per channel); a 450 nm film of IOR 1.3 colours it
    (measured median chroma 0.15, 0.1 asked); a 900 nm film another way (measured up to 2.4
    apart in radiance, 0.05 asked)."""
    light = [{"type": "directional", "direction": [0.3, -0.5, -1], "intensity": 1.5}]

    def render(**film):
        scene = one_sphere({**DARK, **film}, light, size=(64, 64), environment={"color": [0.5, 0.5, 0.5]})
        return render_scene(parse_scene(scene), gl_context).linear.astype(np.float64)

    grey = render()
    assert _chroma(grey).max() <= 1e-6
    film = render(iridescence=1.0, iridescence_thickness_max=450.0)
    assert np.median(_chroma(film)) > 0.1, np.median(_chroma(film))
    thicker = render(iridescence=1.0, iridescence_thickness_max=900.0)
    assert np.abs(thicker - film)[..., :3].max() > 0.05  # another thickness, another colour


def test_the_maps_channels_are_the_mask_and_the_thickness(gl_context, tmp_path):
    """Map texels R = 128 (mask 1 x 128/255) and G = 128 (thickness mix(100, 500, 128/255))
    against the unmapped material with those values: equal to float32 rounding (measured
    5.3e-7 relative); one code more in either map changes the image by 5.7e-3 (R) and 1.6e-2
    (G) relative, thousands of pixels over the bound."""
    mapped = {**DARK, "iridescence": 1.0, "iridescence_thickness_min": 100.0, "iridescence_thickness_max": 500.0,
              "textures": {"iridescence": _constant_map(tmp_path, (128, 0, 0), "mask.png"),
                           "iridescence_thickness": _constant_map(tmp_path, (0, 128, 0), "thickness.png")}}
    plain = {**DARK, "iridescence": 128 / 255, "iridescence_thickness_max": 100.0 + 400.0 * 128 / 255}
    _assert_float32_equal(_render(mapped, gl_context), _render(plain, gl_context))


def test_iridescent_scenes_agree_in_glsl_and_hlsl(gl_context, tmp_path):
    """The same film (mapped, over an anisotropic coated metal and a dark dielectric) through
    the GLSL library and its HLSL port. Not bit for bit: the two programs contract the
    interference phase's multiply-add differently (tests/gpu/hlsl/test_function_agreement.py's
    stated bound for pbr_F_Iridescence); measured worst 2.8e-6 relative, inside the float32
    bound of test_anisotropy_scene."""
    film = {"iridescence": 0.9, "iridescence_ior": 1.6, "iridescence_thickness_min": 200.0,
            "iridescence_thickness_max": 650.0,
            "textures": {"iridescence_thickness": _constant_map(tmp_path, (0, 90, 0))}}
    for material in ({**DARK, **film}, {**METAL, **film, "anisotropy_strength": 0.6, "clearcoat": 0.5}):
        glsl = _render(material, gl_context)
        hlsl = _render(material, gl_context, language="hlsl")
        _assert_float32_equal(hlsl, glsl)


@pytest.mark.parametrize("update, message", [
    ({"iridescence": 1.2}, "materials.m.iridescence: expected a number in [0.0, 1.0], got 1.2"),
    ({"iridescence": 1.0, "iridescence_ior": 0.9}, "materials.m.iridescence_ior: expected a number in [1.0, 16.0]"),
    ({"iridescence": 1.0, "iridescence_thickness_max": -5}, "materials.m.iridescence_thickness_max: expected a "
                                                            "number in [0.0, inf], got -5"),
    ({"iridescence_thickness_min": "thin"}, 'materials.m.iridescence_thickness_min: expected a number, got "thin"'),
    ({"textures": "iridescence_thickness"}, "materials.m.textures.iridescence_thickness: the iridescence_thickness "
                                            "map belongs to the thin film, whose mask `iridescence` is 0 here"),
])
def test_bad_iridescence_fields_are_refused_by_name(update, message, tmp_path):
    material = {**METAL, **update}
    if "textures" in update:
        material["textures"] = {update["textures"]: _constant_map(tmp_path, (255, 128, 255))}
    with pytest.raises(SceneError) as info:
        parse_scene(one_sphere(material, LIGHTS))
    assert message in str(info.value)


def test_unity_brdf_model_refuses_an_iridescent_material():
    scene = one_sphere({**METAL, "iridescence": 0.5}, LIGHTS)
    scene["render"] = {"brdf_model": "unity"}
    with pytest.raises(SceneError, match=r"render.brdf_model: Unity's BRDFs have no F0 a thin film could replace; "
                                         r"material 'm' is iridescent"):
        parse_scene(scene)
    scene["materials"]["m"]["iridescence"] = 0.0
    parse_scene(scene)  # mask 0 is the filmless material: allowed
