"""Hostile round three, unbounded memory from a few bytes of glTF: an accessor without a
bufferView is zeros the file does not hold, so its count alone sized the allocation (2^28 VEC3
positions: 6 GiB as float64 from a 400-byte file). Refused by accessors.MAX_UNBACKED_BYTES, the
render's per-array budget, naming the accessor and the limit. The render runs in a child with its
address space capped at 2 GiB (the budget): without the limit (main before this test) it ends in
"out of memory (try a smaller --size or fewer samples)", blaming the image, after filling the cap;
uncapped it takes 6 GiB of the machine. An accessor within the limit renders (the control)."""

from __future__ import annotations

import base64
import json
import resource
import subprocess
import sys

import numpy as np

from pbrlab.importers.gltf.accessors import MAX_UNBACKED_BYTES

BUDGET = 2 << 30  # the address space the child may use


def _model(tmp_path, count: int):
    # A triangle's positions (accessor 0, a data: URI) and accessor 1 without a bufferView: `count`
    # zeros, the morph target's POSITION deltas; with count 3 the primitive is the triangle, else its
    # POSITION is accessor 1 too (a count of zeros, as a hostile file writes it).
    triangle = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0]], "<f4").tobytes()
    uri = "data:application/octet-stream;base64," + base64.b64encode(triangle).decode()
    doc = {
        "asset": {"version": "2.0"},
        "buffers": [{"byteLength": len(triangle), "uri": uri}],
        "bufferViews": [{"buffer": 0, "byteLength": len(triangle)}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]},
            {"componentType": 5126, "count": count, "type": "VEC3", "min": [0, 0, 0], "max": [0, 0, 0]},
        ],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 1 if count != 3 else 0},
                                    "targets": [{"POSITION": 1}]}]}],
        "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}], "scene": 0,
    }
    path = tmp_path / "model.gltf"
    path.write_text(json.dumps(doc), encoding="utf-8")
    return path


def _render_capped(path, tmp_path):
    def cap():
        resource.setrlimit(resource.RLIMIT_AS, (BUDGET, BUDGET))
    return subprocess.run([sys.executable, "-m", "pbrlab", "render", str(path), "-o", str(tmp_path / "out.png"),
                           "--environment", "0.3,0.3,0.3"],
                          capture_output=True, text=True, timeout=120, preexec_fn=cap)


def test_an_accessor_of_zeros_past_the_budget_is_refused_naming_it(tmp_path):
    count = 1 << 28
    assert count * 3 * 8 > MAX_UNBACKED_BYTES
    run = _render_capped(_model(tmp_path, count), tmp_path)
    assert run.returncode == 2, run.stderr
    assert "Traceback" not in run.stderr
    assert "accessor 1 has no bufferView" in run.stderr and "MAX_UNBACKED_BYTES" in run.stderr, run.stderr
    assert not (tmp_path / "out.png").exists()


def test_an_accessor_of_zeros_within_the_budget_is_read(tmp_path):
    """The control: the same file with the triangle's own 3 zeros as its morph target renders."""
    run = _render_capped(_model(tmp_path, 3), tmp_path)
    assert run.returncode == 0, run.stderr
    assert (tmp_path / "out.png").stat().st_size > 0
