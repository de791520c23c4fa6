"""User mistakes on every command: exit status 2, one message that names the file, field
or limit, no traceback, no file written or changed."""

import json
import os

import numpy as np
import pytest

from hostile_common import base_scene
from pbrlab.commands import cli
from pbrlab.foundation import images


@pytest.fixture
def folder(tmp_path):
    (tmp_path / "scene.json").write_text(json.dumps(base_scene()))
    images.write_png(tmp_path / "a.png", np.full((4, 4, 3), 9, np.uint8))
    images.write_exr(tmp_path / "a.exr", np.ones((4, 4, 3), np.float32))
    (tmp_path / "png_as.exr").write_bytes((tmp_path / "a.png").read_bytes())
    (tmp_path / "latin1.glsl").write_bytes(b"// caf\xe9\nfloat f() { return 1.0; }\n")
    (tmp_path / "uses_latin1.glsl").write_text('#include "latin1.glsl"\n')
    (tmp_path / "loop.png").symlink_to(tmp_path / "loop.png")
    data = base_scene()
    data["lights"] = [{"type": "directional", "direction": [0, -1, 0]}] * 10000
    (tmp_path / "many_lights.json").write_text(json.dumps(data))
    (tmp_path / "nan.obj").write_text("v 0 0 nan\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
    data = base_scene()
    data["objects"] = [{"mesh": "nan.obj", "material": "m"}]
    (tmp_path / "nan_mesh.json").write_text(json.dumps(data))
    gltf = {"asset": {"version": "2.0"}, "buffers": [{"uri": "missing.bin", "byteLength": 36}]}
    (tmp_path / "missing_bin.gltf").write_text(json.dumps(gltf))
    (tmp_path / "string_materials.gltf").write_text(json.dumps({"asset": {"version": "2.0"},
                                                                "materials": "gold"}))
    (tmp_path / "inf_light.gltf").write_text('{"asset": {"version": "2.0"}, "extensions": '
                                             '{"KHR_lights_punctual": {"lights": [{"type": "point", '
                                             '"intensity": 1e400}]}}}')
    (tmp_path / "a_file").write_text("")
    return tmp_path


CASES = {
    "render: missing scene": (["render", "{d}/nope.json", "-o", "{d}/o.png"], "no such scene file"),
    "render: scene is a folder": (["render", "{d}", "-o", "{d}/o.png"], "is a directory"),
    "render: size 0x0": (["render", "{d}/scene.json", "-o", "{d}/o.png", "--size", "0x0"], "--size"),
    "render: size past GL": (["render", "{d}/scene.json", "-o", "{d}/o.png", "--size", "16385x2"], "--size"),
    "render: output is a folder": (["render", "{d}/scene.json", "-o", "{d}/sub.png"], "is a directory"),
    "render: output in a file": (["render", "{d}/scene.json", "-o", "{d}/a_file/o.png"], "not a directory"),
    "render: two outputs one file": (["render", "{d}/scene.json", "-o", "{d}/x.png", "--hdr", "{d}/x.png"],
                                     "expected a .exr"),
    "render: 10,000 lights": (["render", "{d}/many_lights.json", "-o", "{d}/o.png"], "at most 1920 directional"),
    "render: NaN mesh vertex": (["render", "{d}/nan_mesh.json", "-o", "{d}/o.png"], "NaN or infinite"),
    "features: 10,000 lights ok": None,
    "features: glTF without its .bin": (["features", "{d}/missing_bin.gltf"], "missing_bin.gltf"),
    "features: glTF materials a string": (["features", "{d}/string_materials.gltf"], "materials: expected an array"),
    "features: glTF 1e400": (["features", "{d}/inf_light.gltf"], "intensity: is infinite"),
    "diff: missing image": (["diff", "{d}/a.png", "{d}/nope.png"], "no such file"),
    "diff: png vs exr": (["diff", "{d}/a.png", "{d}/a.exr"], "compare PNG with PNG"),
    "diff: PNG bytes named .exr": (["diff", "{d}/a.exr", "{d}/png_as.exr"], "content is PNG data"),
    "diff: symlink loop": (["diff", "{d}/a.png", "{d}/loop.png"], "loop.png"),
    "diff: heatmap in a missing folder": (["diff", "{d}/a.png", "{d}/a.png", "--heatmap", "{d}/no/h.png"],
                                          "does not exist"),
    "amalgamate: non-UTF-8 include": (["amalgamate", "{d}/uses_latin1.glsl", "-o", "{d}/o.glsl"],
                                      "latin1.glsl:1: not UTF-8"),
    "amalgamate: non-UTF-8 entry": (["amalgamate", "{d}/latin1.glsl"], "latin1.glsl:1: not UTF-8"),
    "eval: the same name twice": (["eval", "x", "--var", "x=1", "--var", "x=2"], "given more than once"),
    "eval: --var vs --vec3 clash": (["eval", "x.x", "--var", "x=1", "--vec3", "x=1,2,3"], "given more than once"),
    "eval: huge count": (["eval", "x", "--var", "x=0:1:99999999999"], "count must be"),
    "eval: negative count": (["eval", "x", "--var", "x=0:1:-3"], "count must be"),
    "eval: bad expression": (["eval", "nope(x)", "--var", "x=1"], "nope"),
    "demo: --out is a file": (["demo", "--out", "{d}/a_file"], "not a directory"),
}


@pytest.mark.parametrize("case", sorted(k for k, v in CASES.items() if v))
def test_a_user_mistake_is_one_clear_message_and_exit_2(folder, capsys, case, census):
    args, message = CASES[case]
    (folder / "sub.png").mkdir(exist_ok=True)
    before = {p: p.read_bytes() for p in folder.iterdir() if p.is_file() and not p.is_symlink()}
    status = cli.main([a.format(d=folder) for a in args])
    err = capsys.readouterr().err
    assert status == 2, err
    assert "Traceback" not in err and err.count("\n") >= 1
    assert message in err, err
    after = {p: p.read_bytes() for p in folder.iterdir() if p.is_file() and not p.is_symlink()}
    assert after == before, "a refused command changed or wrote a file"
    census["cli mistake", "refused cleanly"] += 1


def test_many_lights_are_fine_for_features(folder, capsys, census):
    assert cli.main(["features", str(folder / "many_lights.json")]) == 0
    assert json.loads(capsys.readouterr().out)["scene"]["directional"] == 10000
    census["cli mistake", "handled"] += 1


@pytest.mark.parametrize("args, message", [
    (["eval", "x", "--var", "x=1e400"], "1e400 overflows to infinity"),
    (["eval", "x", "--var", "x=1e39"], "1e+39 is beyond the float32 range"),
    (["eval", "y.x", "--vec3", "y=1,2,1e39"], "beyond the float32 range"),
    (["hardcases", "--function", "pbr_D_GGz"], "no hard case covers it"),
])
def test_values_that_would_be_silently_wrong_are_refused(capsys, args, message, census):
    assert cli.main(args) == 2
    err = capsys.readouterr().err
    assert message in err and "Traceback" not in err, err
    census["cli mistake", "refused cleanly"] += 1
