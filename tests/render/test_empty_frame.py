"""render/empty_frame.py: a frame with no covered pixel is named with its cause (issue 39).
The collapsed-skin and camera-turned-away causes are checked on the Draco strip in
tests/importers/gltf/test_gltf_draco_skins.py; here the third cause and a drawn frame."""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np

from pbrlab.importers.gltf import load_gltf
from pbrlab.render.empty_frame import covered_fraction, empty_frame_reason
from pbrlab.render.renderer import render_scene
from pbrlab.scene.model import Environment

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "importers" / "gltf"))
from gltf_helpers import quad_document, write  # noqa: E402

ENV = Environment(color=np.array([0.3, 0.3, 0.3]))


def _rendered(tmp_path, doc):
    scene = load_gltf(write(tmp_path, doc), size=(32, 24), environment=ENV, emit_warnings=False).scene
    return scene, render_scene(scene).linear


def test_a_drawn_quad_has_no_reason(tmp_path):
    scene, linear = _rendered(tmp_path, quad_document())
    assert covered_fraction(linear) > 0.3
    assert empty_frame_reason(scene, linear) is None


def test_a_quad_of_alpha_zero_in_view_is_named_as_covering_nothing(tmp_path):
    doc = quad_document()
    doc["materials"][0]["pbrMetallicRoughness"]["baseColorFactor"] = [0.8, 0.2, 0.1, 0.0]
    doc["materials"][0]["alphaMode"] = "MASK"  # cutoff 0.5: every fragment discarded
    scene, linear = _rendered(tmp_path, doc)
    assert covered_fraction(linear) == 0
    assert empty_frame_reason(scene, linear).startswith("nothing drawn: the objects are in view but cover no pixel")
