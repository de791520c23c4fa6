"""The material charts, the lit scene and the torture chart shaded by the HLSL library
(hlsl_ports/) through the harness's HLSL pixel shaders: glslang's HLSL front end -> SPIR-V
-> spirv-cross -> this GL (harness/pbrlab/gpu/programs.py). Each render diffs against the GLSL
golden of the same scene within the golden tolerance, read-only: an HLSL render never
writes a golden, even under --update-goldens. The lit scene's bricks use the Unity surface
function's HLSL port, scenes/unity_example/brick_surface.hlsl."""

import json
import shutil
from pathlib import Path

import numpy as np
import pytest

from pbrlab.commands import cli
from pbrlab.gpu import programs
from pbrlab.checking.charts import CHARTS
from pbrlab.foundation.errors import PbrlabError, ShaderCompileError
from pbrlab.checking.golden_scenes import GOLDEN_SCENES, lit_scene
from pbrlab.render.renderer import render_scene
from pbrlab.scene import QUALITIES, load_scene, parse_scene

REPO = Path(__file__).resolve().parents[3]
_lit_scene = lit_scene


@pytest.mark.parametrize("chart", sorted(CHARTS))
def test_hlsl_chart_matches_glsl_golden(chart, gl_context, golden):
    rendering = render_scene(parse_scene(CHARTS[chart](), origin=chart), gl_context, language="hlsl")
    golden.check(chart, rendering.linear, rendering.srgb8, read_only=True)


@pytest.mark.parametrize("quality", QUALITIES)
def test_hlsl_lit_scene_matches_glsl_golden(quality, gl_context, golden):
    rendering = render_scene(_lit_scene(quality), gl_context, language="hlsl")
    golden.check(f"lit_scene_{quality}", rendering.linear, rendering.srgb8, read_only=True)


def test_hlsl_torture_chart_matches_glsl_golden(gl_context, golden):
    rendering = render_scene(GOLDEN_SCENES["torture_chart"](), gl_context, language="hlsl")
    golden.check("torture_chart", rendering.linear, rendering.srgb8, read_only=True)


@pytest.mark.parametrize("name", ["chart_terms", "lit_scene_high"])
def test_hlsl_full_program_matches_glsl_golden(name, gl_context, golden):
    """The runtime-branching program (every effect compiled in) in HLSL: the same image."""
    scene = _lit_scene() if name == "lit_scene_high" else parse_scene(CHARTS[name](), origin=name)
    rendering = render_scene(scene, gl_context, specialise=False, language="hlsl")
    assert not rendering.programs.specialised
    golden.check(name, rendering.linear, rendering.srgb8, read_only=True)


def test_hlsl_programs_are_the_cross_compiled_hlsl(gl_context):
    """The renders above ran the HLSL: every scene program's fragment stage holds the HLSL
    $Global cbuffer as spirv-cross's uniform struct, with the material's uniforms in it."""
    render_scene(_lit_scene(), gl_context, language="hlsl")
    hlsl_programs = {key[1]: program for key, program in programs.program_cache(gl_context).items()
                     if key[1].endswith(".hlsl")}
    assert set(hlsl_programs) == {"sphere.hlsl", "mesh.hlsl", "resolve.hlsl"}
    assert "u_albedo" in hlsl_programs["sphere.hlsl"].extra["members"]
    assert "u_exposure_ev" in hlsl_programs["resolve.hlsl"].extra["members"]
    source = programs.hlsl_template_source("sphere.hlsl", {"PBRLAB_DIRECTIONAL_COUNT": 1,
                                                           "PBRLAB_POINT_COUNT": 0,
                                                           "PBRLAB_SPOT_COUNT": 0}).text
    assert "struct _Global" in source and "gl_FragDepth" in source


def test_hlsl_matrix_order_is_what_the_lit_scene_checks(gl_context, monkeypatch):
    """The lit scene's depth test reads the sphere program's mul(u_view_proj, p): uploading
    the matrix as GLSL's mat4 gets it (not its transpose) changes the image, so the golden
    check above would catch a wrong matrix convention (programs.py, module doc)."""
    right = render_scene(_lit_scene(), gl_context, language="hlsl").linear
    monkeypatch.setattr(programs, "_GL_FLOAT_MATRICES", {})  # no transpose for struct members
    wrong = render_scene(_lit_scene(), gl_context, language="hlsl").linear
    assert (np.abs(wrong - right).max(axis=-1) > 1e-3).sum() > 20


def _scene_with_surface(tmp_path, surface_hlsl: str | None) -> Path:
    """The one-sphere chart with the lit scene's GLSL brick surface, and an HLSL twin."""
    shutil.copy(REPO / "scenes" / "unity_example" / "brick_surface.glsl", tmp_path / "brick_surface.glsl")
    if surface_hlsl is not None:
        (tmp_path / "brick_surface.hlsl").write_text(surface_hlsl, encoding="utf-8")
    assets = REPO / "scenes" / "assets"
    scene = {
        "camera": {"position": [0, 0, 6], "target": [0, 0, 0], "fov_y_deg": 30, "size": [32, 32]},
        "lights": [{"type": "directional", "direction": [0, 0, -1]}],
        "materials": {"bricks": {"surface": "brick_surface.glsl", "textures": {
            name: {"path": str(assets / f"bricks_{file}.png"), "srgb": srgb}
            for name, file, srgb in (("_MainTex", "albedo", True), ("_BumpMap", "normal", False),
                                     ("_MetallicGlossMap", "metallic_smoothness", False),
                                     ("_EmissionMap", "emission", True))}}},
        "objects": [{"sphere": {"center": [0, 0, 0], "radius": 1.0}, "material": "bricks"}],
    }
    path = tmp_path / "scene.json"
    path.write_text(json.dumps(scene), encoding="utf-8")
    return path


def test_surface_without_hlsl_twin_is_a_clear_error(tmp_path, gl_context, capsys):
    scene = _scene_with_surface(tmp_path, None)
    render_scene(load_scene(scene), gl_context)  # GLSL needs no twin
    with pytest.raises(PbrlabError, match=r"brick_surface\.glsl: rendering in HLSL needs its HLSL "
                                          r"twin brick_surface\.hlsl"):
        render_scene(load_scene(scene), gl_context, language="hlsl")
    capsys.readouterr()
    assert cli.main(["render", str(scene), "-o", str(tmp_path / "out.png"), "--language", "hlsl"]) == 2
    err = capsys.readouterr().err
    assert "needs its HLSL twin brick_surface.hlsl" in err and "Traceback" not in err
    assert not (tmp_path / "out.png").exists()


def test_hlsl_surface_error_is_reported_at_its_file_and_line(tmp_path, gl_context):
    twin = (REPO / "scenes" / "unity_example" / "brick_surface.hlsl").read_text(encoding="utf-8")
    lines = twin.splitlines()
    line = next(i for i, text in enumerate(lines) if "o.Metallic = mg.r;" in text)
    lines[line] = "    o.Metallic = mg.r + undefined_gloss;"
    scene = _scene_with_surface(tmp_path, "\n".join(lines) + "\n")
    with pytest.raises(ShaderCompileError, match=rf"brick_surface\.hlsl:{line + 1}: error: .*undefined_gloss"):
        render_scene(load_scene(scene), gl_context, language="hlsl")


def test_hlsl_surface_twin_renders_as_its_glsl_original(tmp_path, gl_context):
    """The port in the scene folder, on a second scene: the same image as the GLSL surface."""
    twin = (REPO / "scenes" / "unity_example" / "brick_surface.hlsl").read_text(encoding="utf-8")
    scene = _scene_with_surface(tmp_path, twin)
    glsl = render_scene(load_scene(scene), gl_context)
    hlsl = render_scene(load_scene(scene), gl_context, language="hlsl")
    assert (glsl.linear[..., 3] > 0).sum() > 300  # the sphere covers the middle of the frame
    np.testing.assert_allclose(hlsl.linear, glsl.linear, rtol=0, atol=1e-5)


def test_unknown_language_is_a_clear_error(gl_context):
    with pytest.raises(ValueError, match="language='msl'"):
        render_scene(parse_scene(CHARTS["chart_f0"](), origin="chart_f0"), gl_context, language="msl")
