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


def test_a_quad_without_any_light_is_named_as_black(tmp_path):
    """A glTF without KHR_lights_punctual rendered without an environment: every covered
    pixel exactly 0. Main: an opaque black PNG, exit 0, not a word (issue 39)."""
    scene = load_gltf(write(tmp_path, quad_document()), size=(32, 24), environment=None, emit_warnings=False).scene
    linear = render_scene(scene).linear
    assert covered_fraction(linear) > 0.3 and not np.any(linear[..., :3])
    assert "the scene has no light and no environment" in empty_frame_reason(scene, linear)


def test_a_quad_lit_only_from_behind_is_named_as_black(tmp_path):
    """A directional light turned to shine on the quad's back (the quad faces +z, the camera
    looks from +z), no environment: lights that reach no visible surface."""
    doc = quad_document()
    doc["extensionsUsed"] = ["KHR_lights_punctual"]
    doc["extensions"] = {"KHR_lights_punctual": {"lights": [{"type": "directional", "intensity": 3.0}]}}
    # a glTF light shines along its node's -z, onto the quad's front; turned 180 degrees about y, along +z
    doc["nodes"].append({"extensions": {"KHR_lights_punctual": {"light": 0}}, "rotation": [0, 1, 0, 0]})
    doc["scenes"][0]["nodes"].append(len(doc["nodes"]) - 1)
    scene = load_gltf(write(tmp_path, doc), size=(32, 24), environment=None, emit_warnings=False).scene
    linear = render_scene(scene).linear
    assert covered_fraction(linear) > 0.3 and not np.any(linear[..., :3])
    assert empty_frame_reason(scene, linear).startswith("every covered pixel is black: no light reaches")
    # control: the light as the node first had it lights the quad
    del doc["nodes"][-1]["rotation"]
    scene = load_gltf(write(tmp_path, doc), size=(32, 24), environment=None, emit_warnings=False).scene
    linear = render_scene(scene).linear
    assert np.any(linear[..., :3]) and empty_frame_reason(scene, linear) is None
