"""The fidelity protocol's pieces against what their sources state (pbrlab.checking.fidelity):
the metric (model-viewer's common.ts and pixelmatch's colorDelta), the display transform
(the protocol's Cycles render.py) and the orbit camera (the same render.py's Blender rig)."""

import itertools
import json
import math

import numpy as np
import pytest

from pbrlab.checking.fidelity import display, metric, staging
from pbrlab.foundation.errors import PbrlabError


def _rgba(*pixels):
    return np.array([pixels], np.uint8)


def test_the_largest_yiq_delta_is_the_protocols_constant():
    """common.ts states 35215 as the metric's largest value; the coefficients we copied from
    colorDelta must reach it (over the RGB cube's corners, where a quadratic form on a box
    peaks): cyan against red, 35214.75."""
    corners = np.array([c + (255,) for c in itertools.product((0, 255), repeat=3)], np.uint8)
    deltas = metric.color_delta(np.repeat(corners[:, None], 8, 1), np.repeat(corners[None], 8, 0))
    assert round(deltas.max()) == metric.MAX_COLOR_DISTANCE


def test_the_delta_of_black_and_white_by_hand():
    # Y of white = 255 * (0.29889531 + 0.58662247 + 0.11448223) = 255.0000002; I and Q sum to 0
    y = 255 * (0.29889531 + 0.58662247 + 0.11448223)
    i = 255 * (0.59597799 - 0.27417610 - 0.32180189)
    q = 255 * (0.21147017 - 0.52261711 + 0.31114694)
    expected = 0.5053 * y * y + 0.299 * i * i + 0.1957 * q * q
    got = metric.color_delta(_rgba((0, 0, 0, 255)), _rgba((255, 255, 255, 255)))[0, 0]
    assert got == pytest.approx(expected, rel=1e-15)


def test_transparent_pixels_are_white_and_only_the_candidates_pixels_count():
    # a golden pixel with alpha 0 is white; the candidate's transparent pixel is not scored
    candidate = _rgba((255, 255, 255, 255), (0, 0, 0, 0))
    golden = _rgba((0, 0, 0, 0), (0, 0, 0, 255))
    assert metric.rms_distance_ratio(candidate, golden) == 0.0
    half = _rgba((0, 0, 0, 128))  # over white: 255 - 255 * 128/255 = 127
    delta = metric.color_delta(half, _rgba((127, 127, 127, 255)))[0, 0]
    assert delta == pytest.approx(0.0, abs=1e-9)


def test_the_score_is_rms_of_the_delta_in_decibels():
    candidate = _rgba((0, 0, 0, 255), (255, 255, 255, 255))
    golden = _rgba((255, 255, 255, 255), (255, 255, 255, 255))
    d = metric.color_delta(_rgba((0, 0, 0, 255)), _rgba((255, 255, 255, 255)))[0, 0]
    ratio = math.sqrt((d * d + 0) / 2) / 35215
    assert metric.score_db(candidate, golden) == pytest.approx(10 * math.log10(ratio), rel=1e-12)


def test_an_empty_candidate_is_refused_not_scored():
    with pytest.raises(ValueError, match="covers no pixel"):
        metric.score_db(_rgba((0, 0, 0, 0)), _rgba((0, 0, 0, 255)))


def test_display_transform_by_hand():
    """render.py: x/0.6, three.js's ACES fit, pow(clip(x, 0, 0.9999), 1/2.2), *255 truncated."""
    def by_hand(c):
        v = np.array(c) / 0.6
        m_in = np.array([[0.59719, 0.07600, 0.02840], [0.35458, 0.90834, 0.13383], [0.04823, 0.01566, 0.83777]])
        m_out = np.array([[1.60475, -0.10208, -0.00327], [-0.53108, 1.10813, -0.07276],
                          [-0.07367, -0.00605, 1.07602]])  # render.py's transposed matrices (row vectors)
        v = v @ m_in
        v = (v * (v + 0.0245786) - 0.000090537) / (v * (0.983729 * v + 0.4329510) + 0.238081)
        v = v @ m_out
        return (np.power(np.clip(v, 0.0, 0.9999), 1 / 2.2) * 255).astype(np.uint8)
    colours = [(0.0, 0.0, 0.0), (0.18, 0.18, 0.18), (1.0, 0.5, 0.25), (40.0, 0.01, 3.0), (1e4, 1e4, 1e4)]
    linear = np.array([[c + (1.0,) for c in colours]], np.float32)
    got = display.display_rgba8(linear)
    for k, c in enumerate(colours):
        assert got[0, k, :3].tolist() == by_hand(np.float32(c).astype(np.float64)).tolist(), c
    assert got[0, -1, :3].tolist() == [254, 254, 254]  # 0.9999^(1/2.2) * 255 = 254.99: never 255
    assert (got[..., 3] == 255).all()


def test_display_refuses_non_finite_pixels():
    image = np.zeros((1, 2, 4), np.float32)
    image[0, 1, 0] = np.nan
    with pytest.raises(ValueError, match="1 pixels are not finite"):
        display.display_rgba8(image)


def _blender_eye(target, theta, phi, radius):
    """render.py's rig: camera at (0, 0, radius) under an empty at the target (Blender: x, -z, y)
    rotated by Euler XYZ (phi, 0, theta): R = Rz(theta) Rx(phi); back to glTF (x, z, -y)."""
    t, p = math.radians(theta), math.radians(phi)
    rx = np.array([[1, 0, 0], [0, math.cos(p), -math.sin(p)], [0, math.sin(p), math.cos(p)]])
    rz = np.array([[math.cos(t), -math.sin(t), 0], [math.sin(t), math.cos(t), 0], [0, 0, 1]])
    eye_blender = np.array([target[0], -target[2], target[1]]) + rz @ rx @ np.array([0, 0, radius])
    return np.array([eye_blender[0], eye_blender[2], -eye_blender[1]])


@pytest.mark.parametrize("theta,phi,radius", [(0, 90, 1), (-35, 75, 0.037), (35, 49, 0.275), (45, 65, 50),
                                              (-140, 50, 1), (0, 98, 2.9)])
def test_the_orbit_camera_is_the_protocols_blender_rig(theta, phi, radius):
    target = (0.03, 0.06, -0.2)
    ours = np.array(target) + radius * staging.orbit_direction(theta, phi)
    assert np.allclose(ours, _blender_eye(target, theta, phi, radius), rtol=0, atol=1e-12 * max(1, radius))


def _scenario(**orbit):
    return staging.Scenario("s", staging.SCENARIOS_FILE, "sunrise", (768, 768), (0.0, 0.0, 0.0),
                            orbit.get("theta", 0.0), orbit.get("phi", 90.0), orbit.get("radius", 1.0), 45.0)


def test_a_zero_radius_looks_along_the_orbit_direction():
    cam = staging.camera_of(_scenario(radius=0.0), (np.zeros(3) - 1, np.zeros(3) + 1))
    assert np.allclose(cam["eye"], [0, 0, 0]) and np.allclose(cam["target"], [0, 0, -1])
    assert 0 < cam["znear"] < cam["zfar"]


def test_the_far_plane_holds_the_whole_model():
    lo, hi = np.array([-1.0, -2.0, -3.0]), np.array([5.0, 1.0, 2.0])
    cam = staging.camera_of(_scenario(radius=0.5), (lo, hi))
    corners = np.array(list(itertools.product(*zip(lo, hi))))
    assert np.linalg.norm(corners - np.array(cam["eye"]), axis=1).max() < cam["zfar"]


def test_the_committed_scenarios_read(tmp_path):
    rows = staging.read_scenarios()
    assert len(rows) == len({r.key for r in rows}) >= 20
    assert all(r.model.is_file() for r in rows)


@pytest.mark.parametrize("text,message", [
    ("{", "invalid JSON"),
    ('{"scenarios": [{"name": "x"}]}', "\"model\""),
    ('{"scenarios": [{"name": "x", "model": "nope.glb"}]}', "does not exist"),
    ('{"scenarios": [{"name": "x", "model": "m.glb", "orbit": {"radius": -1}}], "lightings": ["a"]}', "radius"),
    ('{"scenarios": [{"name": "x", "model": "m.glb"}]}', "no lighting"),
    ('{"scenarios": [{"name": "x", "model": "m.glb", "zoom": 2}], "lightings": ["a"]}', "unknown keys"),
])
def test_a_bad_scenarios_file_is_named_with_the_fault(tmp_path, text, message):
    (tmp_path / "m.glb").write_bytes(b"glTF")
    path = tmp_path / "s.json"
    path.write_text(text)
    with pytest.raises(PbrlabError, match=message) as info:
        staging.read_scenarios(path)
    assert str(path) in str(info.value)


def test_a_scenarios_files_references_lie_beside_it_named_for_it(tmp_path):
    from pbrlab.checking.fidelity import benchmark

    assert benchmark.references_for(staging.SCENARIOS_FILE) == benchmark.REFERENCES_DIR
    assert benchmark.references_for(tmp_path / "heldout_scenarios.json") == tmp_path / "heldout_references"
    assert benchmark.references_for(tmp_path / "mine.json") == tmp_path / "mine_references"


HELDOUT_FILE = staging.BENCHMARK_DIR / "heldout_scenarios.json"


def test_the_held_out_set_shares_no_model_and_no_lighting_with_the_benchmark():
    """docs/fidelity.md, "A held-out set": scenes pbrlab was not developed on."""
    benchmark_rows, heldout = staging.read_scenarios(), staging.read_scenarios(HELDOUT_FILE)
    assert len({r.name for r in heldout}) >= 8 and all(r.model.is_file() for r in heldout)
    assert not {r.model for r in heldout} & {r.model for r in benchmark_rows}
    assert not {r.lighting for r in heldout} & {r.lighting for r in benchmark_rows}


def _fidelity_cli(*argv):
    import subprocess
    import sys

    return subprocess.run([sys.executable, "-m", "pbrlab.commands.cli", "fidelity", *argv],
                          capture_output=True, text=True)


def test_fidelity_names_a_missing_scenarios_file_or_references_folder(tmp_path):
    missing = tmp_path / "nope.json"
    result = _fidelity_cli("--scenarios", str(missing), "--out", str(tmp_path / "out"))
    assert result.returncode == 2 and str(missing) in result.stderr and "Traceback" not in result.stderr
    (tmp_path / "m.glb").write_bytes(b"glTF")
    mine = tmp_path / "mine.json"
    mine.write_text('{"lightings": ["forest"], "scenarios": [{"name": "x", "model": "m.glb"}]}')
    result = _fidelity_cli("--scenarios", str(mine), "--out", str(tmp_path / "out"))
    assert result.returncode == 2 and str(mine) in result.stderr and "mine_references" in result.stderr, result.stderr


def test_every_held_out_row_has_its_committed_references():
    from pbrlab.checking.fidelity import benchmark, renderers

    folder = benchmark.references_for(HELDOUT_FILE)
    for row in staging.read_scenarios(HELDOUT_FILE):
        for name in ("cycles", benchmark.NOISE, *renderers.PEERS):
            assert benchmark.reference_path(row.key, name, folder).is_file(), (row.key, name)
