"""KHR_materials_anisotropy in scenes (anisotropy_strength, anisotropy_rotation, the anisotropy
map): what strength 0 is, which way the highlight stretches, how the map decodes, and the
reader's refusals. The GPU-vs-float64 comparison is in test_gpu_matches_cpu_reference.py."""

import math

import numpy as np
import pytest

from pbrlab.foundation.errors import SceneError
from pbrlab.foundation.images import write_png
from pbrlab.render.renderer import render_scene
from pbrlab.scene import parse_scene

from render_scenes import one_sphere

LIGHTS = [{"type": "directional", "direction": [0.3, -0.5, -1], "intensity": 1.5},
          {"type": "point", "position": [-2, 2, 3], "color": [1, 0.8, 0.6], "intensity": 12, "range": 9}]
ENVIRONMENT = {"color": [0.3, 0.35, 0.4]}
METAL = {"albedo": [0.9, 0.7, 0.5], "metallic": 1.0, "smoothness": 0.75}
PLASTIC = {"albedo": [0.6, 0.2, 0.1], "smoothness": 0.6}

# Two renders of the same radiance through different float32 paths (a texel against a
# uniform, the anisotropic D · V at strength 0 against the isotropic fused D · V): per channel
# |a - b| <= FLOAT32_ATOL + FLOAT32_RTOL |b|. Measured on llvmpipe (Mesa 22.3): worst 1.1e-6
# relative for strength 0 (the metal's highlight: anisotropic against fused D · V) and 1.6e-6
# for the map (texel against uniform, then cos/sin of the rotation), about 13 ulp; no pixel
# over the bound. 1e-5 relative is 84 ulp, invisible, and 2e3 times below what one code of the
# map changes (2.3e-2 relative: strength 129/255 instead of 128/255, or the rotation without
# atan(1/255), both fail the bound at 3200+ pixels). The MEDIUM tier's fast isotropic V makes
# strength 0 differ by up to 1.9e-2 relative: the comparison holds at HIGH only.
FLOAT32_ATOL = 1e-6
FLOAT32_RTOL = 1e-5


def _render(material, gl_context, size=(64, 64), quality="high", language="glsl"):
    scene = one_sphere(material, LIGHTS, size=size, environment=ENVIRONMENT)
    scene["render"] = {"quality": quality}
    return render_scene(parse_scene(scene), gl_context, language=language).linear.astype(np.float64)


def _assert_float32_equal(a, b):
    err = np.abs(a - b)[..., :3]
    bound = FLOAT32_ATOL + FLOAT32_RTOL * np.abs(b)[..., :3]
    assert np.all(err <= bound), float(np.max(err - bound))


def _constant_map(tmp_path, rgb, name="anisotropy.png"):
    path = tmp_path / name
    write_png(path, np.broadcast_to(np.array([*rgb, 255], np.uint8), (4, 4, 4)).copy())
    return str(path)


@pytest.mark.parametrize("base", [METAL, PLASTIC], ids=["metal", "dielectric"])
def test_strength_zero_through_the_map_renders_as_the_isotropic_material(base, gl_context, tmp_path):
    """The anisotropic program (strength 0.8) with a map whose blue channel is 0: strength
    0.8 x 0 = 0, the KHR mapping gives alphaT = alphaB = alpha, and the image is the isotropic
    material's to float32 rounding (HIGH tier: the same GGX / height-correlated Smith / Schlick
    model; MEDIUM and LOW use the fast V isotropically, see pbr/surface/lighting_anisotropy.glsl)."""
    isotropic = _render(base, gl_context)
    material = {**base, "anisotropy_strength": 0.8, "anisotropy_rotation": 0.4,
                "textures": {"anisotropy": _constant_map(tmp_path, (255, 128, 0))}}
    anisotropic = _render(material, gl_context)
    _assert_float32_equal(anisotropic, isotropic)
    stretched = _render({**base, "anisotropy_strength": 0.8}, gl_context)
    assert np.abs(stretched - isotropic)[..., :3].max() > 0.05  # the same program does stretch


def _highlight_spread(image):
    """Second moments (x, y) in pixels² of the highlight: the pixels over 10 % of the
    brightest, weighted by their mean radiance."""
    y = image[..., :3].mean(axis=-1)
    w = np.where(y > 0.1 * y.max(), y, 0.0)
    rows, cols = np.indices(y.shape)
    cx, cy = (w * cols).sum() / w.sum(), (w * rows).sum() / w.sum()
    return (w * (cols - cx) ** 2).sum() / w.sum(), (w * (rows - cy) ** 2).sum() / w.sum()


def test_rotation_by_a_quarter_turn_swaps_the_highlights_stretch(gl_context):
    """A light from the camera puts the highlight at the sphere's front, where the sphere's
    tangent (increasing u) is horizontal on screen and its bitangent vertical. Strength 0.5:
    rotation 0 stretches the highlight along the tangent (measured var_x / var_y = 26.6),
    rotation π/2 along the bitangent (var_y / var_x = 26.6); isotropic: 1.000. The two
    stretched highlights are mirror images only up to the sphere's curvature of its tangent
    field (the tangent turns along a parallel, the bitangent does not along a meridian):
    measured 6.6 % apart in their long moment, so 15 % is asked."""
    light = [{"type": "directional", "direction": [0, 0, -1], "intensity": 1}]
    spreads = {}
    for label, extra in (("isotropic", {}), ("0", {"anisotropy_strength": 0.5}),
                         ("90", {"anisotropy_strength": 0.5, "anisotropy_rotation": math.pi / 2})):
        scene = one_sphere({"albedo": [1, 1, 1], "metallic": 1.0, "smoothness": 0.75, **extra}, light,
                           size=(96, 96))
        spreads[label] = _highlight_spread(render_scene(parse_scene(scene), gl_context).linear.astype(np.float64))
    iso_x, iso_y = spreads["isotropic"]
    assert abs(iso_x / iso_y - 1.0) < 1e-3
    x0, y0 = spreads["0"]
    x90, y90 = spreads["90"]
    assert x0 / y0 > 10.0 and y90 / x90 > 10.0, spreads
    assert abs(x0 / y90 - 1.0) < 0.15 and abs(y0 / x90 - 1.0) < 0.15, spreads
    assert x0 > 10 * iso_x  # stretched, not only narrowed


def test_the_maps_channels_are_the_direction_and_the_strengths_factor(gl_context, tmp_path):
    """Texel (255, 128, 128): direction (1, 1/255) (rg x 2 - 1), strength factor 128/255. With
    strength 1 and rotation 1.2 it is the unmapped material of strength 128/255 and rotation
    1.2 + atan(1/255), to float32 rounding."""
    mapped = {**METAL, "anisotropy_strength": 1.0, "anisotropy_rotation": 1.2,
              "textures": {"anisotropy": _constant_map(tmp_path, (255, 128, 128))}}
    plain = {**METAL, "anisotropy_strength": 128 / 255, "anisotropy_rotation": 1.2 + math.atan(1 / 255)}
    _assert_float32_equal(_render(mapped, gl_context), _render(plain, gl_context))


def test_anisotropic_scenes_render_alike_in_glsl_and_hlsl(gl_context, tmp_path):
    """The same anisotropic material (mapped, rotated, also coated and sheened) through the
    GLSL library and its HLSL port: bit for bit (measured 0 ulp on llvmpipe)."""
    material = {**METAL, "anisotropy_strength": 0.7, "anisotropy_rotation": -0.6,
                "clearcoat": 0.5, "sheen_color": [0.2, 0.3, 0.4],
                "textures": {"anisotropy": _constant_map(tmp_path, (200, 90, 230))}}
    for quality in ("high", "low"):
        glsl = _render(material, gl_context, quality=quality)
        hlsl = _render(material, gl_context, quality=quality, language="hlsl")
        np.testing.assert_array_equal(glsl.astype(np.float32).view(np.uint32),
                                      hlsl.astype(np.float32).view(np.uint32))


@pytest.mark.parametrize("update, message", [
    ({"anisotropy_strength": 1.5}, "materials.m.anisotropy_strength: expected a number in [0.0, 1.0], got 1.5"),
    ({"anisotropy_strength": -0.1}, "materials.m.anisotropy_strength: expected a number in [0.0, 1.0]"),
    ({"anisotropy_rotation": "45deg"}, 'materials.m.anisotropy_rotation: expected a number, got "45deg"'),
    ({"anisotropy_rotation": 1e400}, "materials.m.anisotropy_rotation: is infinite"),
    ({"textures": {"anisotropy": "MAP"}}, "materials.m.textures.anisotropy: the anisotropy map scales "
                                           "anisotropy_strength, which is 0 here"),
])
def test_bad_anisotropy_fields_are_refused_by_name(update, message, tmp_path):
    material = {**METAL, **update}
    if "textures" in update:
        material["textures"] = {"anisotropy": _constant_map(tmp_path, (255, 128, 255))}
    with pytest.raises(SceneError) as info:
        parse_scene(one_sphere(material, LIGHTS))
    assert message in str(info.value)


def test_unity_brdf_model_refuses_an_anisotropic_material():
    scene = one_sphere({**METAL, "anisotropy_strength": 0.5}, LIGHTS)
    scene["render"] = {"brdf_model": "unity"}
    with pytest.raises(SceneError, match=r"render.brdf_model: Unity's BRDFs have no anisotropic lobe; "
                                         r"material 'm' is anisotropic"):
        parse_scene(scene)
    scene["materials"]["m"]["anisotropy_strength"] = 0.0
    parse_scene(scene)  # strength 0 is the isotropic material: allowed
