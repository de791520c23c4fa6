"""scripts/khronos_sample_sweep.py sorts each model variant into rendered, refused (with
the message) and not available, and counts them: on a three-model folder built here."""

from __future__ import annotations

import importlib.util
import json
from pathlib import Path

from gltf_helpers import quad_document, write

SCRIPT = Path(__file__).resolve().parents[3] / "scripts" / "khronos_sample_sweep.py"


def _sweep():
    spec = importlib.util.spec_from_file_location("khronos_sample_sweep", SCRIPT)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_the_sweep_counts_rendered_refused_and_unavailable(tmp_path):
    for name in ("Good", "Refused", "Missing"):
        (tmp_path / "Models" / name / "glTF").mkdir(parents=True)
    write(tmp_path / "Models" / "Good" / "glTF", quad_document(), "Good.gltf")
    refused = quad_document()
    refused["extensionsRequired"] = refused["extensionsUsed"] = ["EXT_not_a_real_one"]
    write(tmp_path / "Models" / "Refused" / "glTF", refused, "Refused.gltf")
    missing = quad_document()
    missing["buffers"][0]["uri"] = "Missing.bin"
    write(tmp_path / "Models" / "Missing" / "glTF", missing, "Missing.gltf")
    rows_path, table_path = tmp_path / "rows.json", tmp_path / "table.md"
    assert _sweep().main(["--models", str(tmp_path), "--json", str(rows_path), "--markdown", str(table_path)]) == 0
    rows = {r["model"]: r for r in json.loads(rows_path.read_text())}
    assert rows["Good/glTF/Good.gltf"]["result"] == "rendered"
    assert rows["Refused/glTF/Refused.gltf"]["result"] == "refused"
    assert "EXT_not_a_real_one is required by the file and not supported" in rows["Refused/glTF/Refused.gltf"]["reason"]
    assert rows["Missing/glTF/Missing.gltf"] == {"model": "Missing/glTF/Missing.gltf", "result": "not available",
                                                 "reason": "the snapshot lacks Missing.bin"}
    assert table_path.read_text().startswith("**1 of 2** variants rendered, 1 refused, 0 failed (1 more not available")
