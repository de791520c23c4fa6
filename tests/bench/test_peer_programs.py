"""benchmarks/whole_program_cost.py's bench (pbrlab.bench.peer_programs) runs on one class from
the committed captures, and what it cannot measure it reports, never skips: a missing capture,
a capture of another file than the generator writes, a program that does not compile and a
page whose programs include none of the model's are errors naming the file or the peer. The
figures themselves are static ACO counts (no tolerance: nothing is compared against a bound)."""

import json
import shutil
from pathlib import Path

import pytest

from pbrlab.bench import gpu, peer_gltf, peer_programs
from pbrlab.foundation.errors import PbrlabError

FOLDER = Path(__file__).resolve().parents[2] / "benchmarks" / "peer_programs"
CASE = peer_programs.Case("metallic-roughness", 1, True)


def _require_null_device():
    if (why := gpu.unavailable_reason()) is not None:
        pytest.fail(f"RADV null device unavailable (bash scripts/setup.sh installs it): {why}")


def _copy_of_captures(tmp_path) -> Path:
    """The committed captures of CASE alone, in a folder the test may break."""
    folder = tmp_path / "peer_programs"
    for peer in peer_programs.PEERS:
        (folder / peer).mkdir(parents=True)
        shutil.copy(FOLDER / peer / f"{CASE.key}.frag", folder / peer)
    shutil.copy(FOLDER / "manifest.json", folder)
    return folder


def test_whole_program_cost_runs_on_metallic_roughness():
    _require_null_device()
    results = peer_programs.measure(FOLDER, [CASE], families=("rdna3",))
    row = results[CASE.key]
    assert set(row) == set(peer_programs.COLUMNS)
    for column, entry in row.items():
        figures = entry["families"]["rdna3"]
        assert figures["instructions"] > 0 and figures["vgprs"] > 0 and figures["waves"] > 0, column
        assert entry["honoured"], column
    # the checking program is the production program plus the harness's checks
    assert row["pbrlab checking"]["families"]["rdna3"]["instructions"] > \
        row["pbrlab production"]["families"]["rdna3"]["instructions"]
    assert peer_programs.cheapest(row) in peer_programs.COLUMNS
    table = peer_programs.markdown_table(CASE.key, row, families=("rdna3",))
    assert table.count("\n| ") == len(peer_programs.COLUMNS) + 1 and "**" in table


def test_missing_capture_is_an_error_naming_the_file(tmp_path):
    folder = _copy_of_captures(tmp_path)
    (folder / "sample_viewer" / f"{CASE.key}.frag").unlink()
    with pytest.raises(PbrlabError, match=rf"sample_viewer/{CASE.key}\.frag: no captured Sample Viewer program"):
        peer_programs.measure(folder, [CASE], families=("rdna3",))


def test_capture_of_another_file_is_an_error(tmp_path):
    folder = _copy_of_captures(tmp_path)
    manifest = json.loads((folder / "manifest.json").read_text())
    manifest["cases"][CASE.key]["gltf_sha256"] = "0" * 64
    (folder / "manifest.json").write_text(json.dumps(manifest))
    with pytest.raises(PbrlabError, match="captured from another"):
        peer_programs.measure(folder, [CASE], families=("rdna3",))


def test_program_that_does_not_compile_is_reported_by_its_file(tmp_path):
    _require_null_device()
    folder = _copy_of_captures(tmp_path)
    path = folder / "threejs" / f"{CASE.key}.frag"
    path.write_text(path.read_text().replace("void main() {", "void main() { undeclared_name = 1.0;", 1))
    with pytest.raises(PbrlabError, match=rf"threejs/{CASE.key}\.frag: does not compile"):
        peer_programs.measure(folder, [CASE], families=("rdna3",))


def test_rewrite_refuses_reduced_precision():
    with pytest.raises(PbrlabError, match="mediump"):
        peer_programs.vulkan_glsl("#version 300 es\nprecision mediump float;\nvoid main() {}\n", "x.frag")
    with pytest.raises(PbrlabError, match="not a WebGL2 program"):
        peer_programs.vulkan_glsl("#version 330\nvoid main() {}\n", "x.frag")
    assert peer_programs.vulkan_glsl("#version 300 es\nprecision highp float;\n", "x.frag") == \
        "#version 450\nprecision highp float;\n"


def test_selection_picks_the_models_program_and_fails_without_one():
    utility = {"fragment": "#version 300 es\n#define SHADER_NAME PMREMGGXConvolution\n", "draws": 18}
    model = {"fragment": "#version 300 es\n#define SHADER_NAME sheen\n#define USE_SHEEN\n", "draws": 1}
    undrawn = {"fragment": "#version 300 es\n#define SHADER_NAME sheen\n#define USE_SHEEN\n// other\n", "draws": 0}
    assert peer_programs.select("threejs", [utility, model, undrawn], "sheen") == (model["fragment"], 1)
    with pytest.raises(PbrlabError, match="none of the 2 captured programs"):
        peer_programs.select("threejs", [utility, undrawn], "sheen")
    viewer = {"fragment": "#version 300 es\n#define MATERIAL_SHEEN 1\n", "draws": 1}
    panorama = {"fragment": "#version 300 es\n#define MATH_PI 3.14\n", "draws": 6}
    assert peer_programs.select("sample_viewer", [panorama, viewer], "sheen")[0] == viewer["fragment"]


def test_class_markers_tell_a_peer_that_drops_the_class():
    """three.js r187 draws a specular-glossiness file as metallic-roughness: its capture carries
    no marker of the class, while the metallic-roughness capture carries its own."""
    sg = (FOLDER / "threejs" / "specular-glossiness-1light-env.frag").read_text()
    mr = (FOLDER / "threejs" / "metallic-roughness-1light-env.frag").read_text()
    assert not peer_programs.honours("threejs", "specular-glossiness", sg)
    assert peer_programs.honours("threejs", "metallic-roughness", mr)
    assert not peer_programs.honours("sample_viewer", "sheen", mr)  # control: a marker that is absent


def test_generated_gltf_is_deterministic():
    a = peer_gltf.gltf_bytes("sheen", 4)
    assert a == peer_gltf.gltf_bytes("sheen", 4)
    assert a != peer_gltf.gltf_bytes("sheen", 1)


def test_capture_reproduces_the_committed_programs(tmp_path):
    """Both peers rendered again in headless Chromium (the capture path of
    tools/threejs_gltf/render.mjs and tools/sample_viewer/render.mjs) give the committed
    programs of CASE text for text: the committed captures are what the tools produce, and the
    generated file is the one they were captured from."""
    root = FOLDER.parents[1]
    missing = [path for path in ("tools/threejs_gltf/node_modules/three",
                                 "tools/sample_viewer/node_modules/@khronosgroup/gltf-viewer",
                                 "tools/threejs_gltf/node_modules/playwright-core")
               if not (root / path).is_dir()]
    missing += [p for p in ("/usr/bin/chromium",) if not Path(p).exists()]
    assert not missing, f"missing {', '.join(missing)} (bash scripts/setup.sh installs them)"
    manifest = peer_programs.capture(root, tmp_path, [CASE], log=lambda line: None)
    for peer in peer_programs.PEERS:
        assert (tmp_path / peer / f"{CASE.key}.frag").read_text() == (FOLDER / peer / f"{CASE.key}.frag").read_text(), peer
        assert manifest["cases"][CASE.key][peer]["programs_matched"] == 1
    assert manifest["cases"][CASE.key]["gltf_sha256"] == json.loads(
        (FOLDER / "manifest.json").read_text())["cases"][CASE.key]["gltf_sha256"]
