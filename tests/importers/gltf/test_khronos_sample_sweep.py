"""scripts/khronos_sample_sweep.py sorts each model variant by what its image shows (drawn,
empty, black, differs from three.js), refused (with the message) and not available, and
counts them: on a folder of small models built here. The verdicts read the image, so a
blank render with exit 0 is not counted as drawn (issue 39)."""

from __future__ import annotations

import importlib.util
import json
from pathlib import Path

import numpy as np

from gltf_helpers import quad_document, write

SCRIPT = Path(__file__).resolve().parents[3] / "scripts" / "khronos_sample_sweep.py"


def _sweep():
    spec = importlib.util.spec_from_file_location("khronos_sample_sweep", SCRIPT)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def _looking_away() -> dict:
    """The quad, and a camera 3 units in front of it turned round: exit 0, nothing covered."""
    doc = quad_document()
    doc["cameras"] = [{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1}}]
    doc["nodes"].append({"camera": 0, "translation": [0, 0, 3], "rotation": [0, 1, 0, 0]})  # 180 deg about y
    doc["scenes"][0]["nodes"].append(1)
    return doc


def _black_metal() -> dict:
    """A metal of base colour 0: F0 = 0, no diffuse; it reflects nothing of the sky."""
    doc = quad_document()
    doc["materials"][0]["pbrMetallicRoughness"].update(baseColorFactor=[0, 0, 0, 1], metallicFactor=1.0)
    return doc


def _models(tmp_path, docs: dict) -> None:
    for name, doc in docs.items():
        folder = tmp_path / "Models" / name / "glTF"
        folder.mkdir(parents=True)
        write(folder, doc, f"{name}.gltf")


def test_the_sweep_counts_by_what_the_images_show(tmp_path):
    refused = quad_document()
    refused["extensionsRequired"] = refused["extensionsUsed"] = ["EXT_not_a_real_one"]
    missing = quad_document()
    missing["buffers"][0]["uri"] = "Missing.bin"
    _models(tmp_path, {"Good": quad_document(), "Refused": refused, "Missing": missing, "Away": _looking_away(),
                       "Black": _black_metal()})
    rows_path, table_path = tmp_path / "rows.json", tmp_path / "table.md"
    assert _sweep().main(["--models", str(tmp_path), "--json", str(rows_path), "--markdown", str(table_path),
                          "--no-threejs"]) == 0
    rows = {r["model"].split("/")[0]: r for r in json.loads(rows_path.read_text())}
    assert {name: row["result"] for name, row in rows.items()} == {
        "Good": "drawn", "Refused": "refused", "Missing": "not available", "Away": "empty", "Black": "black"}
    assert rows["Good"]["coverage"] > 0.3 and rows["Good"]["lit"] == 1.0
    assert "EXT_not_a_real_one is required by the file and not supported" in rows["Refused"]["reason"]
    assert rows["Missing"] == {"model": "Missing/glTF/Missing.gltf", "result": "not available",
                               "reason": "the snapshot lacks Missing.bin"}
    assert any("nothing drawn: every object lies outside the camera's view" in w for w in rows["Away"]["warnings"])
    assert table_path.read_text().startswith(
        "**1 of 4** variants drawn (0 differs from three.js, 1 empty, 1 black, 1 refused, 0 failed; "
        "1 more not available in the snapshot); 0 compared with three.js.")


def test_three_js_covers_what_pbrlab_covers_on_the_quad_and_the_check_fails_on_a_shifted_image(tmp_path):
    """The comparison itself (three.js r187 in headless Chromium, as setup.sh installs it):
    the quad agrees (0 pixels off silhouettes, colour within the screen); pbrlab's image
    moved by 10 px (a control) covers other pixels."""
    sweep = _sweep()
    from pbrlab.checking.fidelity import renderers
    from pbrlab.foundation import images
    from pbrlab.importers.gltf import load_gltf
    from pbrlab.render.renderer import render_scene
    from pbrlab.scene.model import Environment

    problems = renderers.missing_setup("threejs")
    assert not problems, "; ".join(problems) + " (bash scripts/setup.sh installs them)"
    model = write(tmp_path, quad_document())
    sky = tmp_path / "sky.exr"
    images.write_exr(sky, np.full((16, 32, 3), 0.3, np.float32))
    scene = load_gltf(model, size=sweep._size(), environment=Environment(color=np.array([0.3, 0.3, 0.3])),
                      emit_warnings=False).scene
    linear = render_scene(scene).linear
    same = sweep.threejs_comparison(model, linear, sky)
    assert same["coverage_pixels"] == 0 and same["mean_codes"] <= sweep.COLOUR_SCREEN_CODES, same
    shifted = sweep.threejs_comparison(model, np.roll(linear, 10, axis=1), sky)
    assert shifted["coverage_pixels"] > 100, shifted
