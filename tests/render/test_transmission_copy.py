"""The transmission copy of the scene (harness/pbrlab/render/transmission_copy.py,
templates/transmission_scene.inc): a transmissive material sees the non-transmissive objects
behind it, over the environment where the copy has nothing. Checked against the float64 CPU
renderer (cpu_render.py transmission_copy / _seen_through: its own ray-traced copy, read
at the projected exit point), which computes the transmitted fraction from
pbrlab.maths.reference, not from the shader; Beer-Lambert through the copy; GLSL against HLSL; and
that a scene without a transmissive material draws no copy."""

import copy

import numpy as np
import pytest
from scipy import ndimage

from pbrlab.render import transmission_copy
from pbrlab.render.cpu_render import render_scene_cpu
from pbrlab.render.renderer import render_scene
from pbrlab.scene import parse_scene

from test_anisotropy_scene import _assert_float32_equal

# A lamp that only emits (specular workflow, albedo and specular 0: no reflection), so its
# radiance is its emission at every pixel, behind a unit sphere of glass; the camera at +z.
LAMP_EMISSION = [0.8, 0.3, 0.1]
LAMP = {"workflow": "specular", "albedo": [0, 0, 0], "specular": [0, 0, 0], "smoothness": 0.0,
        "emission": LAMP_EMISSION}
THIN_GLASS = {"albedo": [1, 1, 1], "smoothness": 1.0, "transmission": 1.0}
ROUGH_VOLUME = {"albedo": [1, 1, 1], "smoothness": 0.8, "transmission": 0.9, "thickness": 0.6, "ior": 1.4,
                "attenuation_color": [0.5, 0.8, 0.9], "attenuation_distance": 0.5}
SKY = {"color": [0.2, 0.3, 0.4]}
LIGHTS = [{"type": "directional", "direction": [-0.4, -0.5, -1.0], "intensity": 1.5},
          {"type": "point", "position": [2.0, 1.5, 3.0], "intensity": 8.0}]
# |GPU - CPU| per channel: FLOAT_ATOL + FLOAT_RTOL |CPU|, the thin wall's smooth glass reading
# the copy at mip 6 x 0.045 = 0.27 (llvmpipe, 64 x 64): measured worst 2.3e-5 absolute on
# radiance up to 0.8 with no environment and 1.7e-5 with one (the DFG table's interpolation
# against the float64 integral, as in test_gpu_matches_cpu_reference.py, whose rtol this is)
FLOAT_ATOL = 1e-5
FLOAT_RTOL = 1e-3


def _scene(glass, environment=None, lights=(), lamp_radius=1.2, size=(64, 64), lamp=LAMP):
    return {
        "camera": {"position": [0, 0, 4], "target": [0, 0, 0], "size": list(size)},
        "lights": copy.deepcopy(list(lights)),
        "environment": environment,
        "materials": {"lamp": dict(lamp), "glass": dict(glass)},
        "objects": [{"sphere": {"center": [0.9, 0.2, -3.0], "radius": lamp_radius}, "material": "lamp"},
                    {"sphere": {"center": [0.0, 0.0, 0.0], "radius": 1.0}, "material": "glass"}],
    }


def _gpu(scene, gl_context, language="glsl"):
    return render_scene(parse_scene(scene), gl_context, language=language).linear.astype(np.float64)


def _glass_pixels(scene):
    """Pixels where the glass is the nearest surface (the CPU's own ray tracing)."""
    without_lamp = copy.deepcopy(scene)
    without_lamp["objects"] = without_lamp["objects"][1:]
    return render_scene_cpu(parse_scene(without_lamp))[..., 3] > 0


@pytest.mark.parametrize("environment, lights", [(None, ()), (SKY, LIGHTS)], ids=["copy only", "sky and lights"])
def test_a_thin_wall_matches_the_float64_render_of_what_lies_behind_it(environment, lights, gl_context):
    """Smooth thin glass before a lamp that covers half of it: every pixel within the float32
    bound of the CPU renderer, which sees the lamp through the glass where it lies along -v and
    the sky (or black) elsewhere. A renderer without the copy fails: the lamp's red is missing
    from the glass (checked: the glass pixels before the lamp hold > 0.5 of its red)."""
    scene = _scene(THIN_GLASS, environment, lights)
    gpu, cpu = _gpu(scene, gl_context), render_scene_cpu(parse_scene(scene))
    assert np.array_equal(gpu[..., 3] > 0, cpu[..., 3] > 0)
    err = np.abs(gpu - cpu)[..., :3]
    assert np.all(err <= FLOAT_ATOL + FLOAT_RTOL * np.abs(cpu[..., :3])), float(err.max())
    glass = _glass_pixels(scene)
    before_lamp = glass & (cpu[..., 0] > 0.5 * LAMP_EMISSION[0])
    assert before_lamp.sum() > 0.2 * glass.sum()
    assert (gpu[before_lamp, 0] > 0.5 * LAMP_EMISSION[0]).all()


def test_a_thin_wall_passes_the_opaque_render_times_the_float64_fraction(gl_context):
    """The pixels of the glass before the lamp equal the lamp's own render (the scene without
    the glass) times the fraction the glass transmits, F = rho (1 - E_spec) per pixel,
    computed by the float64 CPU renderer (pbrlab.maths.reference.surface.lighting_transmission) as
    the render of the same glass before a lamp of emission 1: within the float32 bound
    (measured 4e-6 relative). F is 0.96 at the centre and falls towards the rim."""
    scene = _scene(THIN_GLASS)
    opaque = copy.deepcopy(scene)
    opaque["objects"] = opaque["objects"][:1]
    unit = _scene(THIN_GLASS, lamp={**LAMP, "emission": [1.0, 1.0, 1.0]})
    fraction = render_scene_cpu(parse_scene(unit))[..., :3]
    lamp = _gpu(opaque, gl_context)
    through = _gpu(scene, gl_context)
    glass = _glass_pixels(scene)
    inside = glass & (lamp[..., 3] > 0) & (fraction[..., 0] > 0.5)
    assert inside.sum() > 300
    expected = lamp[..., :3] * fraction
    err = np.abs(through[..., :3] - expected)[inside]
    assert np.all(err <= FLOAT_ATOL + FLOAT_RTOL * expected[inside]), float(err.max())
    assert 0.95 < fraction[inside].max() <= 0.961 and fraction[inside].min() < 0.9


def test_a_volume_darkens_what_lies_behind_it_by_beer_lambert(gl_context):
    """A rough tinted volume before the lamp: against the same volume with a white attenuation
    colour, every pixel where the lamp is seen through it is darker by exactly
    attenuation_color^(thickness / attenuation_distance) (Beer-Lambert over the thickness;
    no light, no environment: all it shows is the lamp through the volume). Bound 2e-6
    absolute on the ratio (float32; measured 1e-7)."""
    tinted = _gpu(_scene(ROUGH_VOLUME), gl_context)
    clear = _gpu(_scene({**ROUGH_VOLUME, "attenuation_color": [1.0, 1.0, 1.0]}), gl_context)
    seen = _glass_pixels(_scene(ROUGH_VOLUME)) & (clear[..., 0] > 0.5 * LAMP_EMISSION[0])
    assert seen.sum() > 100
    ratio = tinted[seen][:, :3] / clear[seen][:, :3]
    expected = np.array(ROUGH_VOLUME["attenuation_color"]) ** (ROUGH_VOLUME["thickness"]
                                                               / ROUGH_VOLUME["attenuation_distance"])
    assert np.abs(ratio - expected).max() <= 2e-6, np.abs(ratio - expected).max()


def test_a_rough_refracting_volume_matches_the_float64_render_away_from_the_lamps_edge(gl_context):
    """The rough volume (perceptual roughness 0.2: the copy's mip 1.2, a blur of a few
    pixels that the CPU renderer, reading the finest level, does not model) with the sky and
    two lights: within the float32 bound of the CPU renderer at every pixel whose value does
    not move when the lamp's radius changes by +-0.5 (about 5 pixels on the lamp: its edge is
    then farther than the trilinear footprint of mip 1.2, up to 4 pixels, from where the
    refracted ray leaves the volume; at +-0.15, 239 pixels differ by up to 0.02). Measured
    worst 5.5e-5 absolute on 458 pixels. The refracted exit point
    moves the lamp's image: the thin wall's straight-through lookup fails this test."""
    scenes = [_scene(ROUGH_VOLUME, SKY, LIGHTS, lamp_radius=r) for r in (0.7, 1.2, 1.7)]
    cpus = [render_scene_cpu(parse_scene(s)) for s in scenes]
    gpu = _gpu(scenes[1], gl_context)
    steady = np.all(np.abs(cpus[0] - cpus[2])[..., :3] < 1e-12, axis=-1) & np.all(
        np.abs(cpus[0] - cpus[1])[..., :3] < 1e-12, axis=-1)
    steady &= ndimage.binary_erosion(gpu[..., 3] > 0, iterations=1)
    glass = _glass_pixels(scenes[1])
    lamp_seen = steady & glass & (cpus[1][..., 0] > 0.3)
    assert lamp_seen.sum() > 100 and (steady & glass).sum() > 0.3 * glass.sum()
    err = np.abs(gpu - cpus[1])[..., :3][steady]
    assert np.all(err <= FLOAT_ATOL + FLOAT_RTOL * np.abs(cpus[1][..., :3][steady])), float(err.max())
    straight = copy.deepcopy(scenes[1])
    straight["materials"]["glass"]["ior"] = 1.0  # unbent: the exit point projects to the pixel itself
    moved_cpu = (np.abs(render_scene_cpu(parse_scene(straight)) - cpus[1])[..., :3] > 0.1).any(axis=-1)
    moved_gpu = (np.abs(_gpu(straight, gl_context) - gpu)[..., :3] > 0.1).any(axis=-1)
    stray = moved_gpu & ~ndimage.binary_dilation(moved_cpu, iterations=2)
    assert moved_cpu.sum() > 20 and moved_gpu.sum() > 0.5 * moved_cpu.sum() and not stray.any(), \
        (moved_cpu.sum(), moved_gpu.sum(), stray.sum())


def test_the_copy_agrees_in_glsl_and_hlsl(gl_context):
    for glass in (THIN_GLASS, ROUGH_VOLUME):
        scene = _scene(glass, SKY, LIGHTS)
        _assert_float32_equal(_gpu(scene, gl_context, "hlsl"), _gpu(scene, gl_context))


def test_a_scene_without_transmission_draws_no_copy(gl_context, monkeypatch):
    """Only a scene with a transmissive material pays for the copy's pass: the same scene with
    opaque glass never makes one (a copy made would raise here); with transmission it does."""
    made = []

    class Refused(transmission_copy.TransmissionCopy):
        def __init__(self, *args):
            made.append(args)
            super().__init__(*args)

    monkeypatch.setattr(transmission_copy, "TransmissionCopy", Refused)
    _gpu(_scene({**THIN_GLASS, "transmission": 0.0}), gl_context)
    assert made == []
    _gpu(_scene(THIN_GLASS), gl_context)
    assert len(made) == 1
