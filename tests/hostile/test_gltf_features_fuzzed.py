"""Property-based glTF documents for `features` and `render` (the glTF importer,
pbrlab.importers.gltf, then the feature plan): every field of a small valid document replaced by a
hostile value gives a clean refusal naming the file, or a plan; the file is never changed."""

import json

from hypothesis import given
from hypothesis import strategies as st

from hostile_common import FAST, assert_clean_refusal, leaf_paths, replace_at
from pbrlab.render.features import plan_programs
from pbrlab.importers.gltf import load_gltf

# One triangle (positions in a data: URI buffer), one material, two lights on nodes.
_POSITIONS = "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"
BASE = {
    "asset": {"version": "2.0"},
    "scene": 0,
    "scenes": [{"nodes": [0, 1, 2]}],
    "nodes": [{"mesh": 0}, {"extensions": {"KHR_lights_punctual": {"light": 0}}, "translation": [0, 0, 2]},
              {"extensions": {"KHR_lights_punctual": {"light": 1}}, "rotation": [0, 0, 0, 1]}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "material": 0}]}],
    "buffers": [{"byteLength": 36, "uri": _POSITIONS}],
    "bufferViews": [{"buffer": 0, "byteLength": 36}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                   "min": [0, 0, 0], "max": [1, 1, 0]}],
    "extensionsUsed": ["KHR_lights_punctual"],
    "extensions": {"KHR_lights_punctual": {"lights": [{"type": "point", "intensity": 3.0},
                                                      {"type": "spot", "spot": {}}]}},
    "materials": [{"name": "gold", "pbrMetallicRoughness": {"metallicFactor": 1.0},
                   "emissiveFactor": [0, 0, 0.5], "alphaMode": "MASK"}],
}
PATHS = list(leaf_paths(BASE))
junk = st.one_of(st.none(), st.booleans(), st.integers(-5, 5), st.floats(), st.text(max_size=4),
                 st.lists(st.integers(0, 2), max_size=3), st.dictionaries(st.text(max_size=3), st.integers(), max_size=2),
                 st.sampled_from(["OPAQUE", "BLEND", "directional", "NaN", "Infinity", "1e400"]))


@FAST
@given(index=st.integers(0, len(PATHS) - 1), value=junk, raw_literal=st.sampled_from(["", "NaN", "1e400", "dup"]))
def test_a_hostile_gltf_field_is_refused_by_name_or_reported(tmp_path_factory, index, value, raw_literal, census):
    folder = tmp_path_factory.mktemp("gltf")
    text = json.dumps(replace_at(json.loads(json.dumps(BASE)), PATHS[index], value))
    if raw_literal == "dup":
        text = text.replace('"asset": {', '"asset": {"version": "2.0", ', 1)
    elif raw_literal:
        text = text.replace('"intensity": 3.0', f'"intensity": {raw_literal}', 1)
    path = folder / "x.gltf"
    path.write_text(text)
    raw = path.read_bytes()
    try:
        plan = plan_programs(load_gltf(path, emit_warnings=False).scene)
    except Exception as exc:  # noqa: BLE001
        assert_clean_refusal(exc, origin=str(path))
        census["glTF features", "refused cleanly"] += 1
    else:
        assert plan.defines
        census["glTF features", "handled"] += 1
    assert path.read_bytes() == raw


def test_the_unchanged_document_is_handled(tmp_path):
    """The fuzzing starts from a valid file: unchanged, it loads and plans."""
    path = tmp_path / "x.gltf"
    path.write_text(json.dumps(BASE))
    scene = load_gltf(path, emit_warnings=False).scene
    assert len(scene.lights) == 2 and plan_programs(scene).defines
