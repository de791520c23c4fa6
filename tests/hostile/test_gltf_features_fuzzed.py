"""Property-based glTF documents for `features` (the parts of glTF it reads: materials and
KHR_lights_punctual lights): every field replaced by hostile values gives a clean
refusal naming the file, or a report; the file is never changed."""

import json

from hypothesis import given
from hypothesis import strategies as st

from hostile_common import FAST, assert_clean_refusal, leaf_paths, replace_at
from pbrlab.features import gltf_features

BASE = {
    "asset": {"version": "2.0"},
    "extensions": {"KHR_lights_punctual": {"lights": [{"type": "point", "intensity": 3.0},
                                                      {"type": "spot", "spot": {}}]}},
    "materials": [{"name": "gold", "pbrMetallicRoughness": {"baseColorTexture": {"index": 0}},
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
        report = gltf_features(path)
    except Exception as exc:  # noqa: BLE001
        assert_clean_refusal(exc, origin=str(path))
        census["glTF features", "refused cleanly"] += 1
    else:
        assert set(report) == {"scene", "materials"}
        census["glTF features", "handled"] += 1
    assert path.read_bytes() == raw
