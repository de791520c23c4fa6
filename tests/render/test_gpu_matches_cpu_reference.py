"""GPU renders (GLSL library, float32) against the independent float64 CPU renderer
(numpy ray-sphere + pbrlab.maths.reference), on analytic scenes."""

from pathlib import Path

import numpy as np
import pytest

from pbrlab.foundation.images import read_image
from pbrlab.maths.reference import tonemap as ref_tonemap
from pbrlab.maths.reference.color import linear_to_srgb
from pbrlab.scene.model import TONEMAPPERS
from pbrlab.checking.charts import CHARTS
from pbrlab.render.cpu_render import render_scene_cpu
from pbrlab.render.renderer import render_scene
from pbrlab.scene import parse_scene

from render_scenes import light_zoo, one_sphere

# GPU (float32) vs float64 CPU, linear radiance, per channel: |gpu - cpu| <= ATOL +
# rtol * |cpu|. ATOL = 1e-5 is 1/30 of the smallest 8-bit sRGB step (3.04e-4), so it is
# invisible; it covers silhouette pixels (radiance ~1e-4 at grazing angles) where float32
# conditioning gives a few % relative. Measured on Mesa 22.3 llvmpipe with the
# cancellation-free GGX (1 - NdotH^2 as |n x h|^2): both renderers hit exactly the same
# pixels (same ray algebra); beyond ATOL, p99.99 3.7e-4 relative, at most 6.2e-6 of the
# pixels above 1e-3, worst 4.1e-3 (one highlight pixel of a smoothness-1 sphere, where
# D's peak makes float32 NdotH decisive). So: rtol 1e-3 for all but 2e-5 of the pixels,
# 5e-3 for every pixel, and no coverage difference.
ATOL = 1e-5
RTOL_TYPICAL = 1e-3
RTOL_WORST = 5e-3
FRACTION_OVER_TYPICAL = 2e-5


def _compare(scene_dict, gl_context, gpu=None):
    if gpu is None:
        gpu = render_scene(parse_scene(scene_dict), gl_context).linear
    gpu = gpu.astype(np.float64)
    cpu = render_scene_cpu(parse_scene(scene_dict))
    assert np.isfinite(gpu).all()
    covered_gpu = gpu[..., 3] > 0
    covered_cpu = cpu[..., 3] > 0
    assert np.array_equal(covered_gpu, covered_cpu), (covered_gpu != covered_cpu).sum()
    err = np.abs(gpu - cpu)[..., :3]
    ref = np.abs(cpu)[..., :3]
    assert np.all(err <= ATOL + RTOL_WORST * ref), ((err - ATOL) / ref).max()
    over_typical = (err > ATOL + RTOL_TYPICAL * ref).any(axis=-1)
    assert over_typical.mean() <= FRACTION_OVER_TYPICAL, over_typical.mean()
    return gpu, cpu


@pytest.mark.parametrize("chart", sorted(CHARTS))
def test_chart_matches_float64_cpu_render(chart, gl_context):
    _compare(CHARTS[chart](), gl_context)


@pytest.mark.parametrize("chart", sorted(CHARTS))
def test_chart_golden_file_matches_float64_cpu_render(chart, gl_context):
    # The stored golden itself, not only today's render, must agree with the
    # independent reference: a golden is never just "whatever the shader printed".
    path = Path(__file__).resolve().parents[2] / "goldens" / f"{chart}.exr"
    if not path.exists():
        pytest.fail(f"{path} is missing; create it with make test PYTEST_ARGS=--update-goldens")
    _compare(CHARTS[chart](), gl_context, gpu=read_image(path))


def test_point_and_spot_lights_match_float64_cpu_render(gl_context):
    gpu, cpu = _compare(light_zoo(), gl_context)
    assert cpu[..., :3].max() > 0.1  # the lights do reach the spheres


def test_white_lambert_under_unit_light_along_normal_is_exactly_one(gl_context):
    # The lecture's convention ("lights are pi times too bright"): albedo 1, intensity 1,
    # light along the normal -> 1, and 255 through the sRGB framebuffer. Specular is
    # removed by a zero F0 (specular workflow, specular 0).
    scene = one_sphere({"workflow": "specular", "albedo": [1, 1, 1], "specular": [0, 0, 0],
                        "smoothness": 0.5},
                       [{"type": "directional", "direction": [0, 0, -1], "intensity": 1.0}],
                       size=(33, 33))
    rendering = render_scene(parse_scene(scene), gl_context)
    centre = rendering.linear[16, 16, :3]  # the pixel whose ray hits the sphere head-on
    np.testing.assert_allclose(centre, 1.0, rtol=2e-6)
    assert tuple(rendering.srgb8[16, 16, :3]) == (255, 255, 255)


def _material_row(materials, environment, lights=(), quality="high"):
    scene = one_sphere({}, list(lights), size=(40 * len(materials), 40), environment=environment)
    scene["camera"]["position"] = [0, 0, 4 * len(materials)]
    scene["materials"] = {f"m{i}": m for i, m in enumerate(materials)}
    scene["objects"] = [{"sphere": {"center": [2.2 * (i - (len(materials) - 1) / 2), 0, 0], "radius": 1.0},
                         "material": f"m{i}"} for i in range(len(materials))]
    scene["render"]["quality"] = quality
    return scene


ENVIRONMENT_MATERIALS = [
    {"workflow": "specular", "albedo": [1, 1, 1], "specular": [0, 0, 0], "smoothness": 0.5},
    {"albedo": [0.8, 0.3, 0.2], "smoothness": 0.8},
    {"albedo": [1.0, 0.766, 0.336], "metallic": 1.0, "smoothness": 0.9},
    {"albedo": [0.9, 0.9, 0.9], "metallic": 1.0, "smoothness": 0.2, "occlusion": 0.5},
    {"albedo": [0.9, 0.45, 0.2], "metallic": 0.5, "smoothness": 0.0},  # diffuse under the 0.04 coat only
]


@pytest.mark.parametrize("quality", ["high", "low"])
def test_constant_environment_matches_float64_cpu_render(quality, gl_context):
    # Indirect diffuse (SH9, exact for a constant), the split-sum specular and the
    # diffuse-specular coupling. The GPU interpolates the 256x256 DFG table (every tier)
    # where the CPU integrates at each pixel, and the prefiltered radiance of a constant is
    # that constant up to float32 sums: measured max relative difference 1.6e-5 (HIGH and
    # LOW; 3.1e-3 with the former noisy 32x32 table).
    scene = _material_row(ENVIRONMENT_MATERIALS, {"color": [0.25, 0.5, 0.75]},
                          lights=[{"type": "directional", "direction": [0.3, -0.5, -1]}], quality=quality)
    gpu = render_scene(parse_scene(scene), gl_context).linear.astype(np.float64)
    cpu = render_scene_cpu(parse_scene(scene))
    assert np.array_equal(gpu[..., 3] > 0, cpu[..., 3] > 0)
    err = np.abs(gpu - cpu)[..., :3]
    assert np.all(err <= ATOL + 5e-3 * np.abs(cpu[..., :3])), (err / (1e-3 + np.abs(cpu[..., :3]))).max()


# The white furnace (every tier, with and without compensation, every covered pixel against
# the float64 directional albedo) is tests/render/test_white_furnace.py.


@pytest.mark.parametrize("tonemap", TONEMAPPERS)
def test_display_image_is_exposure_tonemap_and_srgb_of_the_linear_render(tonemap, gl_context):
    # The PNG must be exactly the library's display transform of the EXR: exposure,
    # then the tonemapper, then the sRGB encode. Reference: float64 of all three on the
    # GPU's own linear output. Tolerance: the display encode rounds to the nearest code of
    # the exact curve (0.5 code); the shader's float32 exposure and tonemap may move a
    # value that sits on a rounding midpoint by a few thousandths of a code, so 0.504
    # (measured max 0.49986 over the six tonemappers; the hardware encode needed 1 code).
    scene = one_sphere({"albedo": [0.9, 0.6, 0.3], "smoothness": 0.8},
                       [{"type": "directional", "direction": [0.3, -0.4, -1], "intensity": 6.0}],
                       size=(48, 48), tonemap=tonemap)
    scene["render"]["exposure"] = 0.5
    rendering = render_scene(parse_scene(scene), gl_context)
    linear = rendering.linear[..., :3].astype(np.float64)
    exposed = ref_tonemap.apply_exposure(linear, 0.5)
    mapped = exposed if tonemap == "none" else ref_tonemap.tonemap(exposed, tonemap.upper())
    expected = linear_to_srgb(np.clip(mapped, 0.0, 1.0)) * 255.0
    got = rendering.srgb8[..., :3].astype(np.float64)
    assert exposed.max() > 1.5  # the input is HDR, so the tonemappers differ from clamping
    print(f"{tonemap}: max |code - exact| {np.abs(got - expected).max():.6f}")
    assert np.abs(got - expected).max() <= 0.504


@pytest.mark.parametrize("quality", ["high", "medium", "low"])
def test_clear_coats_match_float64_cpu_render(quality, gl_context):
    """KHR_materials_clearcoat's layer over a dielectric, a metal and an emissive base, at
    three coat roughnesses and masks, under the light zoo and a constant environment."""
    scene = light_zoo()
    scene["environment"] = {"color": [0.3, 0.35, 0.4]}
    scene["render"] = {"quality": quality}
    scene["materials"] = {
        "plastic": {"albedo": [0.8, 0.2, 0.1], "smoothness": 0.3, "clearcoat": 1.0, "clearcoat_smoothness": 0.95},
        "gold": {"albedo": [1.0, 0.766, 0.336], "metallic": 1.0, "smoothness": 0.5, "clearcoat": 0.5,
                 "clearcoat_smoothness": 0.5},
        "rough": {"workflow": "specular", "albedo": [0.3, 0.5, 0.3], "specular": [0.04] * 3, "smoothness": 0.1,
                  "clearcoat": 0.8, "clearcoat_smoothness": 0.0, "emission": [0.2, 0.1, 0.0]},
    }
    gpu, cpu = _compare(scene, gl_context)
    uncoated = light_zoo()
    uncoated["environment"] = scene["environment"]
    uncoated["render"] = scene["render"]
    plain = render_scene(parse_scene(uncoated), gl_context).linear
    assert (np.abs(plain - gpu)[..., :3].max(axis=-1) > 0.01).mean() > 0.1  # the coat shows


@pytest.mark.parametrize("quality", ["high", "medium", "low"])
def test_sheens_match_float64_cpu_render(quality, gl_context):
    """KHR_materials_sheen's layer over a dielectric, a metal and an emissive base (one also
    coated), at three sheen roughnesses and colours, under the light zoo and a constant
    environment."""
    scene = light_zoo()
    scene["environment"] = {"color": [0.3, 0.35, 0.4]}
    scene["render"] = {"quality": quality}
    scene["materials"] = {
        "plastic": {"albedo": [0.5, 0.1, 0.1], "smoothness": 0.3, "sheen_color": [1.0, 0.6, 0.6],
                   "sheen_smoothness": 0.9},
        "gold": {"albedo": [1.0, 0.766, 0.336], "metallic": 1.0, "smoothness": 0.5, "sheen_color": [0.3, 0.3, 0.8],
                 "sheen_smoothness": 0.5, "clearcoat": 0.5, "clearcoat_smoothness": 0.8},
        "rough": {"workflow": "specular", "albedo": [0.3, 0.5, 0.3], "specular": [0.04] * 3, "smoothness": 0.1,
                  "sheen_color": [0.8, 0.8, 0.8], "sheen_smoothness": 0.0, "emission": [0.2, 0.1, 0.0]},
    }
    gpu, cpu = _compare(scene, gl_context)
    plain = light_zoo()
    plain["environment"] = scene["environment"]
    plain["render"] = scene["render"]
    base = render_scene(parse_scene(plain), gl_context).linear
    assert (np.abs(base - gpu)[..., :3].max(axis=-1) > 0.01).mean() > 0.1  # the sheen shows


@pytest.mark.parametrize("quality", ["high", "medium", "low"])
def test_anisotropic_bases_match_float64_cpu_render(quality, gl_context):
    """KHR_materials_anisotropy's lobe on a dielectric, a metal (also sheened and coated) and a
    rough specular-workflow base, at three strengths and rotations (the sphere's tangent runs
    along increasing u), under the light zoo and a constant environment. Measured on llvmpipe
    (Mesa 22.3): worst 1.1e-4 relative, 3.7e-5 absolute, inside the bounds of every scene here."""
    scene = light_zoo()
    scene["environment"] = {"color": [0.3, 0.35, 0.4]}
    scene["render"] = {"quality": quality}
    for (name, material), strength, rotation in zip(scene["materials"].items(), (0.9, 0.5, 1.0), (0.0, 1.0, -2.0)):
        material.update(anisotropy_strength=strength, anisotropy_rotation=rotation)
    scene["materials"]["gold"].update(sheen_color=[0.3, 0.3, 0.8], sheen_smoothness=0.5, clearcoat=0.5,
                                      clearcoat_smoothness=0.8)
    gpu, cpu = _compare(scene, gl_context)
    plain = light_zoo()
    plain["environment"] = scene["environment"]
    plain["render"] = scene["render"]
    plain["materials"]["gold"].update(sheen_color=[0.3, 0.3, 0.8], sheen_smoothness=0.5, clearcoat=0.5,
                                      clearcoat_smoothness=0.8)
    isotropic = render_scene(parse_scene(plain), gl_context).linear
    # the anisotropy shows: more than 4 % of the pixels move by more than 0.01 (measured 4.95 %
    # in LOW, whose bound V (issue 25) is dimmer at grazing, with or without its Fresnel rise
    # (issue 35); 5.4 % in HIGH and 5.1 % in MEDIUM)
    assert (np.abs(isotropic - gpu)[..., :3].max(axis=-1) > 0.01).mean() > 0.04


@pytest.mark.parametrize("quality", ["high", "medium", "low"])
def test_iridescent_bases_match_float64_cpu_render(quality, gl_context):
    """KHR_materials_iridescence's film on a dielectric, an anisotropic coated metal and a
    sheened specular-workflow base (films of 550, 300 and 800 nm, IOR 1.8, 1.3, 1.4), under
    the light zoo and a constant environment; the CPU renderer evaluates the film with
    reference/iridescence.py's float64 twin. Measured on llvmpipe (Mesa 22.3): worst 1.1e-4
    relative, 1.7e-4 absolute (on radiance up to 3), no pixel over the typical bound."""
    scene = light_zoo()
    scene["environment"] = {"color": [0.3, 0.35, 0.4]}
    scene["render"] = {"quality": quality}
    films = {"plastic": dict(iridescence=1.0, iridescence_ior=1.8, iridescence_thickness_max=550),
             "gold": dict(iridescence=0.7, iridescence_thickness_max=300),
             "rough": dict(iridescence=0.9, iridescence_ior=1.4, iridescence_thickness_max=800)}
    others = {"gold": dict(anisotropy_strength=0.6, clearcoat=0.5), "rough": dict(sheen_color=[0.2, 0.3, 0.2])}
    for name, material in scene["materials"].items():
        material.update(films[name], **others.get(name, {}))
    gpu, cpu = _compare(scene, gl_context)
    plain = light_zoo()
    plain["environment"] = scene["environment"]
    plain["render"] = scene["render"]
    for name, material in plain["materials"].items():
        material.update(others.get(name, {}))
    filmless = render_scene(parse_scene(plain), gl_context).linear
    assert (np.abs(filmless - gpu)[..., :3].max(axis=-1) > 0.01).mean() > 0.1  # the film shows


@pytest.mark.parametrize("quality", ["high", "medium", "low"])
def test_transmissive_bases_match_float64_cpu_render(quality, gl_context):
    """KHR_materials_transmission / _volume: a thin wall on the plastic, a tinted volume of IOR
    1.33 under a coat on the gold (half metallic here, so the transmission has a diffuse weight
    to take), a rough tinted volume in the specular workflow, under the light zoo, a light from
    behind and a constant environment; the CPU renderer evaluates reference/transmission.py's
    float64 Walter BTDF, thin lobe and Beer-Lambert (reference/surface.py lighting_transmission).
    Measured on llvmpipe (Mesa 22.3): worst 1.1e-4 relative, 3.6e-3 absolute (on radiance up to
    125, the thin wall's peak from the light behind), no pixel over the typical bound."""
    scene = _transmissive_zoo(quality)
    gpu, cpu = _compare(scene, gl_context)
    plain = _transmissive_zoo(quality)
    for material in plain["materials"].values():
        for key in ("transmission", "thickness", "attenuation_color", "attenuation_distance", "ior"):
            material.pop(key, None)
    opaque = render_scene(parse_scene(plain), gl_context).linear
    assert (np.abs(opaque - gpu)[..., :3].max(axis=-1) > 0.01).mean() > 0.1  # the transmission shows


def _transmissive_zoo(quality):
    scene = light_zoo()
    scene["environment"] = {"color": [0.3, 0.35, 0.4]}
    scene["render"] = {"quality": quality}
    scene["lights"].append({"type": "directional", "direction": [0.15, 0.1, 1.0], "intensity": 1.5})
    scene["materials"]["plastic"].update(transmission=1.0)
    scene["materials"]["gold"].update(metallic=0.5, transmission=0.8, thickness=0.7, ior=1.33, clearcoat=0.5,
                                      attenuation_color=[0.9, 0.6, 0.3], attenuation_distance=0.5)
    scene["materials"]["rough"].update(transmission=0.6, thickness=1.5, attenuation_color=[0.4, 0.8, 0.6],
                                       attenuation_distance=2.0, ior=1.6)
    return scene


@pytest.mark.parametrize("quality", ["high", "medium", "low"])
def test_explicit_f90_bases_match_float64_cpu_render(quality, gl_context):
    """KHR_materials_specular's F90 (JSON specular_f90, the specular workflow): a black F0
    with F90 0.8 (the extension's rim-lit sphere), a yellow F0 at strength 0.5 (F0 = 0.5 x
    min(0.04 x colour, 1), F90 = 0.5) and a coated one at strength 0.2, under the light zoo and
    a constant environment: the direct lobe, the split sum and both diffuse couplings take
    F90 (reference.shading / reference.surface with f90). Measured on llvmpipe (Mesa 22.3):
    within the module's bounds at every tier."""
    scene = light_zoo()
    scene["environment"] = {"color": [0.3, 0.35, 0.4]}
    scene["render"] = {"quality": quality}
    bases = {"plastic": dict(specular=[0.0, 0.0, 0.0], specular_f90=0.8, smoothness=0.8),
             "gold": dict(specular=[0.02, 0.02, 0.0], specular_f90=0.5, smoothness=0.5),
             "rough": dict(specular=[0.008, 0.008, 0.008], specular_f90=0.2, clearcoat=0.6)}
    for name, material in scene["materials"].items():
        material.pop("metallic", None)
        material.update(workflow="specular", **bases[name])
    gpu, _ = _compare(scene, gl_context)
    for material in scene["materials"].values():
        del material["specular_f90"]
    from_f0 = render_scene(parse_scene(scene), gl_context).linear
    # the F90 shows, at the rims (measured 1.8 % of the image by more than 0.01; 0 if ignored)
    assert (np.abs(from_f0 - gpu)[..., :3].max(axis=-1) > 0.01).mean() > 0.01


@pytest.mark.parametrize("quality", ["high", "medium", "low"])
def test_metallic_dielectric_specular_matches_float64_cpu_render(quality, gl_context):
    """KHR_materials_ior / _specular on partly metallic materials (JSON dielectric_specular,
    the metallic workflow, with and without specular_f90): F0 = mix(dielectric F0, albedo,
    metallic), F90 = mix(specular_f90, 1, metallic), the diffuse albedo (1 - max(dielectric
    F0)) (1 - metallic) coupled to the dielectric's albedo, under the light zoo and a constant
    environment; one base coated. Within the module's bounds at every tier (llvmpipe)."""
    scene = light_zoo()
    scene["environment"] = {"color": [0.3, 0.35, 0.4]}
    scene["render"] = {"quality": quality}
    bases = {"plastic": dict(metallic=0.5, dielectric_specular=[0.0, 0.0, 0.0], specular_f90=0.8, smoothness=0.8),
             "gold": dict(metallic=0.3, dielectric_specular=[0.16, 0.09, 0.02], smoothness=0.5),
             "rough": dict(metallic=0.7, dielectric_specular=[0.5, 0.9, 1.0], specular_f90=1.0, clearcoat=0.6)}
    for name, material in scene["materials"].items():
        material.pop("specular", None)
        material.update(workflow="metallic", **bases[name])
    gpu, _ = _compare(scene, gl_context)
    for material in scene["materials"].values():
        del material["dielectric_specular"]
        material.pop("specular_f90", None)
    plain = render_scene(parse_scene(scene), gl_context).linear
    # the dielectric F0 shows (0 if ignored)
    assert (np.abs(plain - gpu)[..., :3].max(axis=-1) > 0.01).mean() > 0.01


# The bases that change with a layer (KHR_materials_anisotropy, _iridescence, _transmission),
# each with KHR_materials_specular's explicit F90 on every material of the light zoo.
F90_LAYERS = {
    "anisotropy": {"plastic": dict(anisotropy_strength=0.9), "gold": dict(anisotropy_strength=0.5, clearcoat=0.5),
                   "rough": dict(anisotropy_strength=1.0, anisotropy_rotation=-2.0)},
    "iridescence": {"plastic": dict(iridescence=1.0, iridescence_ior=1.8, iridescence_thickness_max=550),
                    "gold": dict(iridescence=0.7, iridescence_thickness_max=300, anisotropy_strength=0.6),
                    "rough": dict(iridescence=0.9, iridescence_ior=1.4, iridescence_thickness_max=800,
                                  sheen_color=[0.2, 0.3, 0.2])},
    "transmission": {"plastic": dict(transmission=1.0),
                     "gold": dict(transmission=0.8, thickness=0.7, ior=1.33, clearcoat=0.5,
                                  attenuation_color=[0.9, 0.6, 0.3], attenuation_distance=0.5),
                     "rough": dict(transmission=0.6, thickness=1.5, attenuation_color=[0.4, 0.8, 0.6],
                                   attenuation_distance=2.0, ior=1.6)},
}
F90_BASES = {"plastic": dict(specular=[0.0, 0.0, 0.0], specular_f90=0.8, smoothness=0.8),
             "gold": dict(specular=[0.02, 0.02, 0.0], specular_f90=0.5, smoothness=0.5),
             "rough": dict(specular=[0.008, 0.008, 0.008], specular_f90=0.2)}


@pytest.mark.parametrize("layer", sorted(F90_LAYERS))
@pytest.mark.parametrize("quality", ["high", "medium", "low"])
def test_explicit_f90_with_base_layers_matches_float64_cpu_render(quality, layer, gl_context):
    """The explicit F90 through the anisotropic lobe, the film (the film over F0 / F90, scaled
    by F90: reference/specular_extension.py iridescent_f0_f90) and the transmission's weights
    (coat_f90), under the light zoo (a light from behind for the transmission) and a constant
    environment: the GPU within the module's bounds of the float64 CPU renderer, and the F90
    visible (the same scene with F90 from F0 differs by more than 0.01 on over 1 % of the
    pixels; measured on llvmpipe, Mesa 22.3, in the commit adding this test)."""
    scene = light_zoo()
    scene["environment"] = {"color": [0.3, 0.35, 0.4]}
    scene["render"] = {"quality": quality}
    if layer == "transmission":
        scene["lights"].append({"type": "directional", "direction": [0.15, 0.1, 1.0], "intensity": 1.5})
    for name, material in scene["materials"].items():
        material.pop("metallic", None)
        material.update(workflow="specular", **F90_BASES[name], **F90_LAYERS[layer][name])
    gpu, _ = _compare(scene, gl_context)
    for material in scene["materials"].values():
        del material["specular_f90"]
    from_f0 = render_scene(parse_scene(scene), gl_context).linear
    assert (np.abs(from_f0 - gpu)[..., :3].max(axis=-1) > 0.01).mean() > 0.01
