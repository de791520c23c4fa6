"""The checking and the production program (PBRLAB_CHECKING, templates/surface_pixel.inc) and
the per-mesh tangent fallback (PBRLAB_TANGENT_FALLBACK, pbrlab.render.tangent_frames): the
production program has no NaN/Inf test, the checking one has (the control); where the surface
output is finite the two render the same image bit for bit; a mesh whose tangents are bounded
away from degenerate renders bit-identically without the fallback, and a mesh whose tangents
lie along its normals needs it (without it the pixels are NaN: the control)."""

import re
import subprocess
from pathlib import Path

import numpy as np
import pytest

from pbrlab.bench import gpu
from pbrlab.checking.fidelity import staging
from pbrlab.foundation import images
from pbrlab.importers.loader import parse_scene
from pbrlab.render import tangent_frames
from pbrlab.render.renderer import render_scene
from pbrlab.scene import meshes

from render_scenes import one_sphere

ROOT = Path(__file__).resolve().parents[2]
HELMET = ROOT / "corpus/gltf/khronos/DamagedHelmet/DamagedHelmet.glb"
CLEARCOAT = ROOT / "corpus/gltf/khronos/ClearCoatTest/ClearCoatTest.glb"


def _gltf_scene(model: Path, size=64):
    """``model`` under the fidelity benchmark's sunrise, as benchmarks/environment_read_cost.py frames it."""
    return parse_scene({"camera": {"position": [0, 0, 3], "target": [0, 0, 0], "size": [size, size]},
                        "environment": {"path": str(staging.ENVIRONMENTS_DIR / "sunrise.exr")},
                        "objects": [{"gltf": str(model)}]},
                       origin=model.name, base=model.parent)


def _preprocessed(text: str, suffix: str, tmp_path, include_dirs=()) -> str:
    """A fragment program after glslang's preprocessor (-E), whitespace removed."""
    path = tmp_path / f"program{suffix}"
    path.write_text(text)
    command = ["glslangValidator", "-E", *(["-D", "-S", "frag", "-e", "main"] if suffix == ".hlsl" else []),
               *(f"-I{d}" for d in include_dirs), str(path)]
    out = subprocess.run(command, capture_output=True, text=True)
    assert out.returncode == 0, out.stdout + out.stderr
    return re.sub(r"\s+", "", out.stdout)


@pytest.mark.parametrize("language", ["glsl", "hlsl"])
def test_the_production_program_has_no_nan_test_and_the_checking_one_has(tmp_path, language):
    scene = _gltf_scene(HELMET)
    found = {}
    for checking in (True, False):
        (program, _), = gpu.scene_programs(scene, "specialised", checking=checking).items()
        job = program.job(language)
        text = _preprocessed(job.fragment, ".frag" if language == "glsl" else ".hlsl", tmp_path, job.include_dirs)
        found[checking] = ("isnan(" in text, "isinf(" in text)
    assert found[True] == (True, True), "the checking program (the control) lost its NaN/Inf test"
    assert found[False] == (False, False)


def test_the_helmet_program_has_no_tangent_fallback_and_the_chair_keeps_it():
    """DamagedHelmet's tangents (from the file) are bounded away from degenerate; SheenChair
    has meshes whose tangents lie along their normals (the fallback is taken there)."""
    helmet = _gltf_scene(HELMET)
    assert [tangent_frames.needs_fallback([o]) for o in helmet.objects] == [False]
    chair = _gltf_scene(ROOT / "corpus/gltf/khronos/SheenChair/SheenChair.gltf")
    assert any(tangent_frames.needs_fallback([o]) for o in chair.objects)
    # a multisampled target interpolates outside the triangle: the fallback stays
    assert tangent_frames.needs_fallback(helmet.objects[:1], samples=4)


@pytest.mark.parametrize("model", [HELMET, CLEARCOAT], ids=lambda p: p.stem)
def test_production_and_checking_programs_render_the_same_image(gl_context, model):
    """Where no surface output is NaN or Inf the test is the only difference: 0 ulp."""
    scene = _gltf_scene(model, size=96)
    checking = render_scene(scene, gl_context).linear
    production = render_scene(scene, gl_context, checking=False).linear
    assert np.isfinite(checking).all()
    assert np.array_equal(checking, production)


def test_a_nan_normal_is_a_nan_pixel_only_in_the_checking_program(gl_context, tmp_path):
    """The control of the test above: the guard is what makes a NaN normal visible."""
    (tmp_path / "nan.glsl").write_text(
        "uniform float u_zero_here;\n"
        "void surf(Input IN, inout SurfaceOutputStandard o) {\n"
        "    o.Albedo = vec3(0.8);\n    o.Normal = vec3(u_zero_here / u_zero_here);\n}\n")
    data = one_sphere({"surface": "nan.glsl"}, [{"type": "directional", "direction": [0, 0, -1]}], size=(16, 16))
    scene = parse_scene(data, base=tmp_path)
    checking = render_scene(scene, gl_context).linear
    production = render_scene(scene, gl_context, checking=False).linear
    covered = checking[..., 3] != 0  # 80 pixels
    assert covered.sum() > 50 and np.isnan(checking[covered][:, :3]).all()
    # production: the NaN normal clamps every N.L to 0 (measured: 0 of the 80 NaN, all black)
    assert not np.isnan(production[covered][:, :3]).any()


def _degenerate_plane(tmp_path, gl_context, tangent_along_normal: bool):
    """A plane under a tilted normal map, its tangents along its normal (the fallback's case)
    or along +x (a valid frame)."""
    images.write_png(tmp_path / "n.png", np.full((4, 4, 3), (200, 128, 230), np.uint8))
    data = one_sphere({"albedo": [0.8, 0.8, 0.8], "smoothness": 0.4, "textures": {"normal": "n.png"}},
                      [{"type": "directional", "direction": [0.3, -1, -0.2]}], size=(24, 24))
    data["camera"] = {"position": [0, 3, 0.01], "target": [0, 0, 0], "fov_y_deg": 30, "size": [24, 24]}
    data["objects"] = [{"mesh": {"primitive": "plane", "size": 4.0}, "material": "m"}]
    scene = parse_scene(data, base=tmp_path)
    obj = scene.objects[0]
    positions, normals, uv, tangents, indices = meshes.mesh_data(obj).arrays[:5]
    tangents = tangents.copy()
    tangents[:, :3] = normals if tangent_along_normal else (1.0, 0.0, 0.0)
    geometry = meshes.Geometry(("tangent test", tangent_along_normal), positions, normals, uv, tangents,
                               uv, np.ones((len(positions), 4), np.float32), indices)
    obj.geometry = geometry
    obj.mesh_path = obj.primitive = None
    return scene


def test_a_mesh_with_valid_tangents_renders_the_same_without_the_fallback(gl_context, tmp_path, monkeypatch):
    scene = _degenerate_plane(tmp_path, gl_context, tangent_along_normal=False)
    assert not tangent_frames.needs_fallback(scene.objects)
    without = render_scene(scene, gl_context).linear
    monkeypatch.setattr(tangent_frames, "draw_defines", lambda *args, **kwargs: {})  # the fallback compiled
    with_fallback = render_scene(scene, gl_context).linear
    assert np.isfinite(without).all() and np.array_equal(without, with_fallback)


def test_tangents_along_the_normal_need_the_fallback(gl_context, tmp_path, monkeypatch):
    """The control: the bound refuses this mesh, and leaving the fallback out anyway changes
    every pixel: t = T - n (n.T) = 0 exactly on a flat plane, so the world normal is NaN and
    every N.L clamps to 0 (measured: all 576 pixels black; the checking program's test reads
    the surface's output, not the world normal, so nothing refuses it: the bound must hold)."""
    scene = _degenerate_plane(tmp_path, gl_context, tangent_along_normal=True)
    assert tangent_frames.needs_fallback(scene.objects)
    kept = render_scene(scene, gl_context).linear
    covered = kept[..., 3] != 0
    assert np.isfinite(kept).all() and (kept[covered][:, :3] > 0).all()
    monkeypatch.setattr(tangent_frames, "draw_defines",
                        lambda *args, **kwargs: {tangent_frames.TANGENT_FALLBACK_DEFINE: 0})
    forced = render_scene(scene, gl_context).linear
    assert (forced[covered][:, :3] != kept[covered][:, :3]).any(axis=1).all()
