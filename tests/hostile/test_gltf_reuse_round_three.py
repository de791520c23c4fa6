"""Hostile round three, one accessor read again and again: a few kilobytes of JSON can name the
same accessor from 1,000 JOINTS_n / WEIGHTS_n sets or 3,000 morph targets, and each use read it
again (issue 39, "not bounded yet"). Main: 1,000 skin sets of a 20,000-vertex grid were
concatenated and every set's joint matrices gathered at once, 10 GiB, ending in "out of memory"
under a 4 GiB cap; 3,000 morph targets of a 40,000-vertex grid were read one after the other,
2.7 GiB (accepted: the time grows with targets x vertices, which the file does not bound). Now every read counts against the import's budget (gltf.document.MAX_READ_BYTES, the
import's half of a render's 2 GiB) and the file is refused naming the accessor and the limit; the
same files with one set or one target render (the controls). Each render runs in a child capped at
4 GiB of address space (pbrlab with an llvmpipe context maps about 1 GiB; the budget 1 GiB more)."""

from __future__ import annotations

import base64
import json
import resource
import subprocess
import sys

import numpy as np
import pytest

from pbrlab.importers.gltf.document import MAX_READ_BYTES

CAP = 4 << 30


def _grid(n: int):
    """An n x n grid of vertices in the unit square, two triangles a cell."""
    u, v = np.meshgrid(np.linspace(0, 1, n), np.linspace(0, 1, n))
    positions = np.stack([u.ravel(), v.ravel(), np.zeros(n * n)], axis=1).astype("<f4")
    corner = (np.arange(n - 1)[None, :] + n * np.arange(n - 1)[:, None]).ravel()
    triangles = np.stack([corner, corner + 1, corner + n, corner + 1, corner + n + 1, corner + n], axis=1)
    return positions, triangles.astype("<u4").ravel()


def _document(n: int, arrays: list[tuple[np.ndarray, str, int]]):
    """A glTF whose accessor i holds arrays[i] = (values, type, componentType), one data: URI."""
    blob, views, accessors = b"", [], []
    for values, kind, component in arrays:
        views.append({"buffer": 0, "byteOffset": len(blob), "byteLength": values.nbytes})
        count = len(values) if values.ndim > 1 else len(values)
        accessor = {"bufferView": len(views) - 1, "componentType": component, "count": count, "type": kind}
        if len(accessors) == 0:
            accessor.update(min=values.min(axis=0).tolist(), max=values.max(axis=0).tolist())
        accessors.append(accessor)
        blob += values.tobytes()
        blob += b"\0" * (-len(blob) % 4)
    uri = "data:application/octet-stream;base64," + base64.b64encode(blob).decode()
    return {"asset": {"version": "2.0"}, "buffers": [{"byteLength": len(blob), "uri": uri}],
            "bufferViews": views, "accessors": accessors}


def _skinned(tmp_path, n: int, sets: int):
    positions, indices = _grid(n)
    joints = np.zeros((n * n, 4), "<u1")
    weights = np.zeros((n * n, 4), "<f4")
    weights[:, 0] = 1.0 / sets  # the sets together weigh each vertex 1 on joint 0
    doc = _document(n, [(positions, "VEC3", 5126), (indices, "SCALAR", 5125), (joints, "VEC4", 5121),
                        (weights, "VEC4", 5126)])
    attributes = {"POSITION": 0}
    for k in range(sets):
        attributes[f"JOINTS_{k}"], attributes[f"WEIGHTS_{k}"] = 2, 3
    doc.update(meshes=[{"primitives": [{"attributes": attributes, "indices": 1}]}],
               nodes=[{"mesh": 0, "skin": 0}, {"name": "joint"}], skins=[{"joints": [1]}],
               scenes=[{"nodes": [0, 1]}], scene=0)
    path = tmp_path / "skinned.gltf"
    path.write_text(json.dumps(doc))
    return path


def _morphed(tmp_path, n: int, targets: int):
    positions, indices = _grid(n)
    delta = np.zeros_like(positions)
    delta[:, 2] = 0.01
    doc = _document(n, [(positions, "VEC3", 5126), (indices, "SCALAR", 5125), (delta, "VEC3", 5126)])
    doc.update(meshes=[{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1,
                                        "targets": [{"POSITION": 2}] * targets}],
                        "weights": [1.0 / targets] * targets}],
               nodes=[{"mesh": 0}], scenes=[{"nodes": [0]}], scene=0)
    path = tmp_path / "morphed.gltf"
    path.write_text(json.dumps(doc))
    return path


def _render_capped(path, tmp_path):
    def cap():
        resource.setrlimit(resource.RLIMIT_AS, (CAP, CAP))
    return subprocess.run([sys.executable, "-m", "pbrlab", "render", str(path), "-o", str(tmp_path / "out.png"),
                           "--size", "32x24", "--environment", "0.3,0.3,0.3"],
                          capture_output=True, text=True, timeout=300, preexec_fn=cap)


# (file, the read it asks for in bytes as float64): 1,000 pairs of 20,000 x 4 values, 3,000
# targets of 40,000 x 3 values; both past the budget, each set or target far within it.
CASES = {"joints_sets": (lambda tmp, k: _skinned(tmp, 141, k), 1000, 141 * 141 * 4 * 8 * 2),
         "morph_targets": (lambda tmp, k: _morphed(tmp, 200, k), 3000, 200 * 200 * 3 * 8)}


@pytest.mark.parametrize("case", sorted(CASES))
def test_an_accessor_read_past_the_import_budget_is_refused_naming_it(tmp_path, case, census):
    make, uses, per_use = CASES[case]
    assert uses * per_use > MAX_READ_BYTES > 10 * per_use
    run = _render_capped(make(tmp_path, uses), tmp_path)
    assert run.returncode == 2, run.stderr
    assert "Traceback" not in run.stderr, run.stderr
    assert "MAX_READ_BYTES" in run.stderr and "accessor" in run.stderr, run.stderr
    assert not (tmp_path / "out.png").exists()
    census["gltf reuse round three", "refused cleanly"] += 1


@pytest.mark.parametrize("case", sorted(CASES))
def test_the_same_file_with_one_use_renders(tmp_path, case, census):
    make, _, _ = CASES[case]
    run = _render_capped(make(tmp_path, 1), tmp_path)
    assert run.returncode == 0, run.stderr
    assert "warning" not in run.stderr, run.stderr  # drawn and lit (render.empty_frame)
    assert (tmp_path / "out.png").stat().st_size > 0
    census["gltf reuse round three", "handled"] += 1
