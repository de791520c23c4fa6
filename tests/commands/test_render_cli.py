"""`pbrlab render` and `pbrlab demo`: outputs, atomic writes, and clear errors."""

import html
import json
import sys
from pathlib import Path

import numpy as np
import pytest

from pbrlab.commands import cli
from pbrlab.checking import contact_sheets
from pbrlab.checking.charts import CHARTS
from pbrlab.foundation.images import read_image

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "render"))  # render_scenes.py, the render tests' scenes
from render_scenes import one_sphere  # noqa: E402

LIT_SPHERE = one_sphere({"albedo": [0.8, 0.3, 0.2], "smoothness": 0.6},
                        [{"type": "directional", "direction": [0.2, -0.4, -1]}], size=(40, 30))


@pytest.fixture
def scene_file(tmp_path):
    path = tmp_path / "scene.json"
    path.write_text(json.dumps(LIT_SPHERE))
    return path


def test_render_writes_png_and_exr_of_the_requested_size(scene_file, tmp_path, capsys):
    png, exr = tmp_path / "o.png", tmp_path / "o.exr"
    assert cli.main(["render", str(scene_file), "-o", str(png), "--hdr", str(exr), "--size", "24x20"]) == 0
    srgb, linear = read_image(png), read_image(exr)
    assert srgb.shape == (20, 24, 4) and srgb.dtype == np.uint8
    assert linear.shape == (20, 24, 4) and linear.dtype == np.float32
    assert linear[10, 12, 0] > 0.05 and linear[10, 12, 3] == 1.0  # sphere centre: lit, covered
    assert linear[0, 0].sum() == 0  # corner: empty, alpha 0


@pytest.mark.parametrize("backend", ["egl", "osmesa"])
def test_render_backends_write_identical_files(scene_file, tmp_path, backend):
    out = tmp_path / f"{backend}.exr"
    assert cli.main(["render", str(scene_file), "--hdr", str(out), "--backend", backend]) == 0
    reference = tmp_path / "reference.exr"
    cli.main(["render", str(scene_file), "--hdr", str(reference), "--backend", "egl"])
    np.testing.assert_array_equal(read_image(out), read_image(reference))


def test_failed_render_keeps_the_previous_output(scene_file, tmp_path, capsys):
    png = tmp_path / "keep.png"
    png.write_bytes(b"previous good image")
    broken = json.loads(scene_file.read_text())
    broken["objects"] = [{"mesh": "broken.obj", "material": "m"}]
    (tmp_path / "broken.obj").write_text("this is not a mesh\n")
    bad_scene = tmp_path / "bad.json"
    bad_scene.write_text(json.dumps(broken))
    assert cli.main(["render", str(bad_scene), "-o", str(png)]) == 2
    assert png.read_bytes() == b"previous good image"
    assert "Traceback" not in capsys.readouterr().err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["bad.json", "broken.obj", "keep.png", "scene.json"]


@pytest.mark.parametrize("args, message", [
    (["--size", "12", "-o", "x.png"], "expected WIDTHxHEIGHT"),
    (["-o", "picture.jpg"], "expected a .png file name"),
    ([], "nothing to write"),
    (["-o", "/nonexistent-dir/x.png"], "cannot write"),
])
def test_render_mistakes_get_one_line_messages(scene_file, args, message, capsys):
    assert cli.main(["render", str(scene_file), *args] if args != [] else ["render", str(scene_file)]) == 2
    err = capsys.readouterr().err
    assert message in err and "Traceback" not in err


def test_render_names_the_bad_scene_field(tmp_path, capsys):
    bad = dict(LIT_SPHERE, materials={"m": {"albedo": [0.8, 0.3, 0.2], "smoothness": -1}})
    path = tmp_path / "bad.json"
    path.write_text(json.dumps(bad))
    assert cli.main(["render", str(path), "-o", str(tmp_path / "x.png")]) == 2
    assert "materials.m.smoothness: expected a number in [0.0, 1.0], got -1" in capsys.readouterr().err
    assert not (tmp_path / "x.png").exists()


def test_demo_writes_every_chart_and_matches_goldens(tmp_path, capsys):
    assert cli.main(["demo", "--out", str(tmp_path)]) == 0
    out = capsys.readouterr().out
    index = (tmp_path / "index.html").read_text(encoding="utf-8")
    for name in [*CHARTS, "lit_scene_high"]:
        assert (tmp_path / f"{name}.png").is_file() and (tmp_path / f"{name}.exr").is_file()
        assert f"matches goldens/{name}" in out
        # the labelled contact sheet beside the raw render, larger (titles, labels, caption)
        sheet = read_image(tmp_path / f"{name}_sheet.png")
        raw = read_image(tmp_path / f"{name}.png")
        assert sheet.shape[0] > raw.shape[0] and sheet.shape[1] >= raw.shape[1]
        info = contact_sheets.layout(name)
        for text in (info.title, info.caption, f"golden: matches goldens/{name}", f"{name}_sheet.png",
                     f"{name}.png", f"{name}.exr"):
            assert html.escape(text) in index, text


def test_demo_without_goldens_renders_and_says_so_once(tmp_path, capsys, monkeypatch):
    """An installed wheel ships no goldens (locations.checkout_folder finds none): the demo
    renders everything, says once that there is nothing to compare, and exits 0."""
    from pbrlab.foundation import locations
    monkeypatch.setattr(locations, "checkout_folder", lambda name: None)
    assert cli.main(["demo", "--out", str(tmp_path)]) == 0
    out = capsys.readouterr().out
    assert out.count("no golden to compare") == 1 and "DIFFERS" not in out and "matches" not in out
    for name in [*CHARTS, "lit_scene_high"]:
        assert (tmp_path / f"{name}_sheet.png").is_file() and (tmp_path / f"{name}.exr").is_file()
    index = (tmp_path / "index.html").read_text(encoding="utf-8")
    assert index.count('class="none">golden: rendered, no golden to compare') == len(CHARTS) + 1


def test_demo_reports_a_chart_that_differs_from_its_golden(tmp_path, capsys):
    goldens = tmp_path / "goldens"
    goldens.mkdir()
    from pbrlab.checking import goldens as store
    from pbrlab.render.renderer import render_scene
    from pbrlab.scene import parse_scene

    import shutil
    for chart, build in CHARTS.items():
        rendering = render_scene(parse_scene(build()))
        linear = rendering.linear.copy()
        if chart == "chart_f0":
            linear[10, 10, 0] += 0.01  # one changed pixel
        store.check_golden(chart, linear, rendering.srgb8, update=True, root=goldens)
    repo_goldens = Path(__file__).resolve().parents[2] / "goldens"
    for suffix in (".exr", ".png", ".json"):
        shutil.copy(repo_goldens / f"lit_scene_high{suffix}", goldens)
    assert cli.main(["demo", "--out", str(tmp_path / "out"), "--goldens", str(goldens)]) == 1
    out = capsys.readouterr().out
    assert "chart_f0" in out and "DIFFERS" in out and "1 differ" in out
    # the same figures as the test failure: where, how much, how many pixels, the tolerance
    assert "max abs 0.01 linear at (y=10, x=10)" in out
    assert "1 of 184320 pixels" in out and "tolerance max_abs 1e-05 linear" in out
    assert "tolerance profile llvmpipe" in out
    index = (tmp_path / "out" / "index.html").read_text(encoding="utf-8")
    assert 'class="bad">golden: DIFFERS from goldens/chart_f0' in index
    assert index.count('class="ok">golden: matches') == len(CHARTS)  # the other charts and the lit scene
    assert not any(line.rstrip().endswith(":") for line in out.splitlines())


def test_readme_example_scene_renders_finite(tmp_path):
    from pathlib import Path

    example = Path(__file__).resolve().parents[2] / "scenes" / "example.json"
    exr, png = tmp_path / "example.exr", tmp_path / "example.png"
    assert cli.main(["render", str(example), "--hdr", str(exr), "-o", str(png), "--size", "160x100"]) == 0
    linear = read_image(exr)
    assert np.isfinite(linear).all() and (linear[..., :3] >= 0).all()
    assert (linear[..., 3] > 0).mean() > 0.5  # spheres, torus and floor cover most of it


def test_error_in_a_surface_file_is_reported_at_its_line(tmp_path, capsys):
    (tmp_path / "bad_surface.glsl").write_text(
        "void surf(Input IN, inout SurfaceOutputStandard o) {\n"
        "    o.Albedo = vec3(1.0);\n"
        "    o.Smoothness = undeclared_gloss;\n"
        "}\n")
    scene = dict(LIT_SPHERE)
    scene["materials"] = {"m": {"surface": "bad_surface.glsl"}}
    (tmp_path / "s.json").write_text(json.dumps(scene))
    assert cli.main(["render", str(tmp_path / "s.json"), "-o", str(tmp_path / "x.png")]) == 2
    err = capsys.readouterr().err
    assert "bad_surface.glsl:3:" in err and "undeclared_gloss" in err
    assert not (tmp_path / "x.png").exists()
