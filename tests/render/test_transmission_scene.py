"""KHR_materials_transmission and KHR_materials_volume in scenes (transmission, thickness,
attenuation_color, attenuation_distance, ior; the transmission and thickness maps): what a
transmission of 0 is, that a thin wall shows the environment behind it, Beer-Lambert over the
thickness, lights from behind, GLSL against HLSL, and the reader's refusals. The white furnace
rows are in test_white_furnace.py, the GPU-vs-float64 comparison in
test_gpu_matches_cpu_reference.py."""

import numpy as np
import pytest

from pbrlab.foundation.errors import SceneError
from pbrlab.render.renderer import render_scene
from pbrlab.checking.sample_viewer import write_radiance_hdr
from pbrlab.scene import parse_scene

from render_scenes import one_sphere
from test_anisotropy_scene import LIGHTS, METAL, PLASTIC, _assert_float32_equal, _constant_map, _render

WHITE = {"albedo": [1.0, 1.0, 1.0], "smoothness": 0.9}
BASES = {"metal": METAL, "dielectric": PLASTIC, "white": WHITE}
# A light from behind the sphere (travelling towards the camera at +z)
BACK_LIGHT = [{"type": "directional", "direction": [0.1, 0.2, 1.0], "intensity": 2.0}]


def _render_in(material, gl_context, environment, lights=(), quality="high", language="glsl"):
    scene = one_sphere(material, list(lights), environment=environment)
    scene["render"] = {"quality": quality}
    return render_scene(parse_scene(scene), gl_context, language=language).linear.astype(np.float64)


@pytest.mark.parametrize("quality", ["high", "low"])
@pytest.mark.parametrize("base", sorted(BASES))
def test_transmission_zero_through_the_map_is_the_opaque_material_bit_for_bit(base, quality, gl_context,
                                                                                tmp_path):
    """The transmissive program (transmission 1, a volume) with a map whose red channel is 0:
    the transmission is 1 x 0 = 0, the diffuse colour x (1 - 0) is itself and the added term is
    0 x (finite): the opaque material's image bit for bit (measured: every pixel, base and tier)."""
    plain = _render(BASES[base], gl_context, quality=quality)
    masked = _render({**BASES[base], "transmission": 1.0, "thickness": 0.5, "attenuation_color": [0.5, 0.6, 0.7],
                      "textures": {"transmission": _constant_map(tmp_path, (0, 255, 255), "transmission.png")}},
                     gl_context, quality=quality)
    np.testing.assert_array_equal(masked.astype(np.float32).view(np.uint32), plain.astype(np.float32).view(np.uint32))


def _two_colour_environment(tmp_path):
    """An equirectangular environment orange behind the sphere (directions with z < 0, away
    from the camera at +z) and blue in front (z > 0)."""
    height, width = 64, 128
    phi = (np.arange(width) + 0.5) / width * 2.0 * np.pi
    # pbr/ibl/equirect.glsl: azimuth phi measured from -Z towards +X, so z = -cos(phi) sin(theta)
    behind = np.cos(phi) > 0.0
    rgb = np.empty((height, width, 3), np.float32)
    rgb[:, behind] = (0.9, 0.35, 0.05)
    rgb[:, ~behind] = (0.05, 0.3, 0.9)
    path = tmp_path / "two_colours.hdr"
    write_radiance_hdr(path, rgb)
    return {"path": str(path)}


def test_a_thin_white_wall_shows_the_environment_behind_it(gl_context, tmp_path):
    """A white sphere, smoothness 0.9, in an environment orange behind it and blue in front.
    Opaque, its centre is the diffuse irradiance around n = +z: blue (measured B/R 17.6). Thin
    and fully transmissive, its centre shows what lies along -v: orange (measured R/B 10.1,
    0.96 of the orange's red; the rest is the blue front's reflection); asked: R/B > 3 and
    red > 0.7 x the orange's."""
    environment = _two_colour_environment(tmp_path)
    opaque = _render_in(WHITE, gl_context, environment)[32, 32, :3]
    thin = _render_in({**WHITE, "transmission": 1.0}, gl_context, environment)[32, 32, :3]
    assert opaque[2] > 3.0 * opaque[0], opaque
    assert thin[0] > 3.0 * thin[2], thin
    assert thin[0] > 0.7 * 0.9, thin


@pytest.mark.parametrize("quality", ["high", "medium", "low"])
def test_a_volume_darkens_by_its_attenuation_colour_over_its_distance(quality, gl_context):
    """Beer-Lambert (KHR_materials_volume): a white volume in a white constant environment
    shows E + T (1 - E), E its specular reflection, T the attenuation. With T(c) for colour c,
    T(0) = 0 and T(1) = 1, (L(c) - L(0)) / (L(1) - L(0)) is T itself at every pixel: c at
    thickness = attenuation_distance, c^2 at twice it. Bound 2e-6 absolute per channel
    (float32 differences of values near 1, about 17 ulp at 1; measured worst 2.8e-7 at every
    tier); T = c^(d/2D) or a linear 1 - (1 - c) d/D miss it by more than 0.05."""
    white = {"color": [1.0, 1.0, 1.0]}
    c = np.array([0.25, 0.6, 0.9])

    def radiance(colour, thickness):
        material = {**WHITE, "transmission": 1.0, "thickness": thickness, "attenuation_color": list(colour),
                    "attenuation_distance": 0.5}
        image = _render_in(material, gl_context, white, quality=quality)
        return image[..., :3][image[..., 3] > 0]

    for thickness, expected in ((0.5, c), (1.0, c * c)):
        black, full = radiance([0.0] * 3, thickness), radiance([1.0] * 3, thickness)
        ratio = (radiance(c, thickness) - black) / (full - black)
        assert np.abs(ratio - expected).max() <= 2e-6, (thickness, np.abs(ratio - expected).max())


def test_a_light_behind_passes_through_thin_and_volume(gl_context):
    """A light behind the sphere reaches the camera through a transmissive wall (thin: the
    mirrored-light lobe, measured peak 1.95 in the centre; volume: Walter's BTDF, whose
    refracted peak lies off the centre, measured peak 911 at smoothness 0.9), not through the
    opaque material (exactly 0 in the centre, where n.l < 0)."""
    opaque = _render_in(WHITE, gl_context, None, BACK_LIGHT)
    thin = _render_in({**WHITE, "transmission": 1.0}, gl_context, None, BACK_LIGHT)
    volume = _render_in({**WHITE, "transmission": 1.0, "thickness": 0.3}, gl_context, None, BACK_LIGHT)
    centre = (slice(24, 40), slice(24, 40))
    assert opaque[centre][..., :3].max() == 0.0
    assert thin[centre][..., :3].max() > 1.0 and volume[..., :3].max() > 1.0, volume[..., :3].max()


def test_transmissive_scenes_agree_in_glsl_and_hlsl(gl_context, tmp_path):
    """The same transmission (mapped thickness, a tinted volume, a thin wall, a light behind)
    through the GLSL library and its HLSL port: within the float32 bound of
    test_anisotropy_scene."""
    volume = {"transmission": 0.8, "thickness": 0.6, "attenuation_color": [0.8, 0.5, 0.3],
              "attenuation_distance": 0.4, "ior": 1.33,
              "textures": {"thickness": _constant_map(tmp_path, (0, 160, 0), "thickness.png")}}
    for material in ({**PLASTIC, **volume}, {**WHITE, "transmission": 1.0, "clearcoat": 0.5}):
        scene = one_sphere(material, LIGHTS + BACK_LIGHT, environment={"color": [0.3, 0.35, 0.4]})
        glsl = render_scene(parse_scene(scene), gl_context).linear.astype(np.float64)
        hlsl = render_scene(parse_scene(scene), gl_context, language="hlsl").linear.astype(np.float64)
        _assert_float32_equal(hlsl, glsl)


def test_the_thickness_map_scales_the_thickness(gl_context, tmp_path):
    """Thickness 0.8 x a map texel G = 128 against thickness 0.8 x 128/255 unmapped: equal to
    float32 rounding (the bound of test_anisotropy_scene)."""
    base = {**PLASTIC, "transmission": 1.0, "attenuation_color": [0.3, 0.6, 0.9], "attenuation_distance": 0.3}
    mapped = _render({**base, "thickness": 0.8,
                      "textures": {"thickness": _constant_map(tmp_path, (0, 128, 0), "thickness.png")}}, gl_context)
    plain = _render({**base, "thickness": 0.8 * 128 / 255}, gl_context)
    _assert_float32_equal(mapped, plain)


@pytest.mark.parametrize("update, message", [
    ({"transmission": 1.5}, "materials.m.transmission: expected a number in [0.0, 1.0], got 1.5"),
    ({"transmission": 1.0, "thickness": -1}, "materials.m.thickness: expected a number in [0.0, inf], got -1"),
    ({"transmission": 1.0, "attenuation_distance": 0}, "materials.m.attenuation_distance: expected a number in"),
    ({"transmission": 1.0, "attenuation_color": [1.2, 1, 1]}, "materials.m.attenuation_color"),
    ({"transmission": 1.0, "ior": 0.5}, "materials.m.ior: expected a number in [1.0, 16.0]"),
    ({"thickness": 0.5}, "materials.m.thickness: `thickness` belongs to the transmission, which is 0 here"),
    ({"textures": "transmission"}, "materials.m.textures.transmission: the transmission map belongs to the "
                                   "transmission, which is 0 here"),
    ({"transmission": 1.0, "textures": "thickness"}, "materials.m.textures.thickness: the thickness map scales "
                                                     "`thickness`, which is 0 (thin-walled) here"),
])
def test_bad_transmission_fields_are_refused_by_name(update, message, tmp_path):
    material = {**PLASTIC, **update}
    if "textures" in update:
        material["textures"] = {update["textures"]: _constant_map(tmp_path, (255, 128, 255))}
    with pytest.raises(SceneError) as info:
        parse_scene(one_sphere(material, LIGHTS))
    assert message in str(info.value)


def test_unity_brdf_model_refuses_a_transmissive_material():
    scene = one_sphere({**PLASTIC, "transmission": 0.5}, LIGHTS)
    scene["render"] = {"brdf_model": "unity"}
    with pytest.raises(SceneError, match=r"render.brdf_model: Unity's BRDFs have no transmission; "
                                         r"material 'm' is transmissive"):
        parse_scene(scene)
    scene["materials"]["m"]["transmission"] = 0.0
    parse_scene(scene)  # transmission 0 is the opaque material: allowed


def test_a_surface_file_material_refuses_the_transmission_fields(tmp_path):
    """A surface file writes its own output: the default surface's transmission fields are
    refused by name (as the other layers' are)."""
    surface = tmp_path / "plain.glsl"
    surface.write_text("void surf(Input IN, inout SurfaceOutputStandard o) { o.Albedo = vec3(1.0); }\n")
    with pytest.raises(SceneError, match=r"materials.m.transmission: the transmission belongs to the default "
                                         r"surface; .*\(remove `transmission`, `attenuation_color`\)"):
        parse_scene(one_sphere({"surface": str(surface), "transmission": 0.5, "attenuation_color": [1, 1, 1]},
                               LIGHTS))


def test_a_scene_where_everything_transmits_reads_an_empty_copy_not_a_stale_unit(gl_context):
    """Every object transmits: the copy holds nothing (the environment shows through), and it
    is still made and bound. Before, no copy was made, and the transmissive program sampled
    whatever texture its copy unit last held: another render's copy, or (here) a planted
    texture, so this scene's image depended on which render ran before it."""
    material = {**PLASTIC, "transmission": 1.0, "thickness": 0.5, "attenuation_distance": 0.3}
    alone = one_sphere(material, LIGHTS, environment={"color": [0.4, 0.5, 0.6]})
    behind = {**alone, "materials": {**alone["materials"], "wall": dict(PLASTIC)},
              "objects": alone["objects"] + [{"sphere": {"center": [0, 0, -4], "radius": 2.0}, "material": "wall"}]}
    render_scene(parse_scene(behind), gl_context)  # the same program, its copy sampler set
    images = []
    for planted in (100.0, 7.0):
        texture = gl_context.texture((4, 4), 4, np.full((4, 4, 4), planted, np.float32).tobytes(), dtype="f4")
        texture.use(3)  # render.py's TRANSMISSION_COPY_UNIT
        images.append(render_scene(parse_scene(alone), gl_context).linear)
        texture.release()
    assert np.array_equal(images[0], images[1])
