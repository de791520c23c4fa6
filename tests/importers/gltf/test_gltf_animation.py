"""Animation samplers (gltf/animation.py) against values worked by hand from the spec's
Appendix C and against the float64 reference (reference/gltf_animation.py, a different
derivation); skins (gltf/skin.py) on scenes/gltf/skinned_strip.gltf
(make_animated_assets.py) against its analytically posed geometry; morph weight animation;
the errors of --time and --animation."""

from __future__ import annotations

import copy
import json
import math

import numpy as np
import pytest

from gltf_helpers import write
from pbrlab.commands import cli
from pbrlab.foundation.errors import PbrlabError, SceneError
from pbrlab.checking.golden_scenes import GLTF_DIR
from pbrlab.importers.gltf import load_gltf
from pbrlab.importers.gltf.animation import interpolate
from pbrlab.importers.gltf.skin import pose_vertices
from pbrlab.maths.reference import gltf_animation as reference

STRIP = GLTF_DIR / "skinned_strip.gltf"
DOC = json.loads(STRIP.read_text())
SIZE = (96, 64)
# positions are uploaded as float32: values up to ~2.3 round within 2^-23 x 2.3, twice
FLOAT32_POSITION = 4 * 2.3 * float(np.finfo(np.float32).eps)
# the file's quaternion and inverse bind matrices are float32 (sin 45 deg to 2^-24): the
# posed vertices move by up to |p| x 2^-23 more
FLOAT32_INPUT = 2 * FLOAT32_POSITION


def _z_rotation(degrees: float) -> np.ndarray:
    half = math.radians(degrees) / 2
    return np.array([0.0, 0.0, math.sin(half), math.cos(half)])


# ---------------------------------------------------------------- samplers: spec values by hand

def test_step_holds_each_keyframe_until_the_next():
    times, values = np.array([0.0, 1.0, 2.0]), np.array([[0.0], [10.0], [20.0]])
    for t, expected in ((0.0, 0), (0.999, 0), (1.0, 10), (1.5, 10), (2.0, 20), (-3.0, 0), (9.0, 20)):
        assert interpolate(times, values, "STEP", t)[0] == expected


def test_linear_is_the_straight_line_and_clamps_outside():
    times, values = np.array([1.0, 3.0]), np.array([[2.0, -4.0], [6.0, 0.0]])
    np.testing.assert_allclose(interpolate(times, values, "LINEAR", 1.5), [3.0, -3.0], rtol=0, atol=1e-15)
    np.testing.assert_array_equal(interpolate(times, values, "LINEAR", 0.0), [2.0, -4.0])
    np.testing.assert_array_equal(interpolate(times, values, "LINEAR", 7.0), [6.0, 0.0])


@pytest.mark.parametrize("s, degrees", [(0.5, 45.0), (1 / 3, 30.0), (0.9, 81.0)])
def test_linear_rotation_is_slerp_at_constant_angular_speed(s, degrees):
    """0 to 90 degrees about +Z: slerp at s turns 90 s degrees (a lerp of the quaternions
    would turn 45.0 at s = 0.5 but 27.9, not 30, at s = 1/3)."""
    got = interpolate(np.array([0.0, 1.0]), np.stack([_z_rotation(0), _z_rotation(90)]), "LINEAR", s,
                      rotation=True)
    np.testing.assert_allclose(got, _z_rotation(degrees), rtol=0, atol=1e-15)


def test_slerp_takes_the_shorter_arc():
    """-q is the same rotation as q: slerp from identity to -(90 deg) still turns 45 degrees
    at s = 0.5 (Appendix C's sign term), not 135."""
    got = interpolate(np.array([0.0, 1.0]), np.stack([_z_rotation(0), -_z_rotation(90)]), "LINEAR", 0.5,
                      rotation=True)
    assert abs(abs(got @ _z_rotation(45)) - 1) < 1e-15


@pytest.mark.parametrize("times, t, expected", [
    # v0 = 1, out-tangent b0 = 0, v1 = 2, in-tangent a1 = 3, td = 1, s = 0.5:
    # (2/8 - 3/4 + 1) 1 + 0 + (-2/8 + 3/4) 2 + 1 (1/8 - 1/4) 3 = 0.5 + 1 - 0.375
    ((0.0, 1.0), 0.5, 1.125),
    # td = 2 scales the tangent terms: 0.5 + 1 + 2 (-1/8) 3
    ((0.0, 2.0), 1.0, 0.75),
    # s = 0.25, td = 1: (2/64 - 3/16 + 1) + (-2/64 + 3/16) 2 + (1/64 - 1/16) 3 = 0.84375 + 0.3125 - 0.140625
    ((0.0, 1.0), 0.25, 1.015625),
])
def test_cubic_spline_is_appendix_c_hermite(times, t, expected):
    values = np.array([[0.0], [1.0], [0.0], [3.0], [2.0], [3.0]])  # (a, v, b) per keyframe
    assert interpolate(np.array(times), values, "CUBICSPLINE", t)[0] == pytest.approx(expected, abs=1e-15)


def test_cubic_spline_out_tangent_and_clamping():
    """v0 = v1 = 0, b0 = 1, a1 = 0, td = 1: the value is (s^3 - 2s^2 + s), 0.125 at s = 0.5;
    outside the range the keyframe values (the tangents play no part)."""
    values = np.array([[9.0], [0.0], [1.0], [0.0], [0.0], [9.0]])
    times = np.array([0.0, 1.0])
    assert interpolate(times, values, "CUBICSPLINE", 0.5)[0] == pytest.approx(0.125, abs=1e-15)
    assert interpolate(times, values, "CUBICSPLINE", -1.0)[0] == 0.0
    assert interpolate(times, values, "CUBICSPLINE", 2.0)[0] == 0.0


def test_cubic_spline_rotation_is_normalised():
    q0, q1 = _z_rotation(0), _z_rotation(90)
    values = np.stack([np.zeros(4), q0, np.zeros(4), np.zeros(4), q1, np.zeros(4)])
    got = interpolate(np.array([0.0, 1.0]), values, "CUBICSPLINE", 0.5, rotation=True)
    np.testing.assert_allclose(got, _z_rotation(45), rtol=0, atol=1e-15)  # (q0 + q1) / 2, normalised


# ---------------------------------------------------------------- samplers: against the reference

@pytest.mark.parametrize("interpolation", ["STEP", "LINEAR", "CUBICSPLINE"])
@pytest.mark.parametrize("rotation", [False, True])
def test_importer_samplers_match_the_float64_reference(interpolation, rotation):
    rng = np.random.default_rng(24)
    for _ in range(20):
        n = int(rng.integers(2, 6))
        times = np.cumsum(rng.uniform(0.1, 1.0, n))
        width = 4 if rotation else 3
        values = rng.normal(size=(n * (3 if interpolation == "CUBICSPLINE" else 1), width))
        if rotation:
            values /= np.linalg.norm(values, axis=1, keepdims=True)
        for t in np.concatenate([rng.uniform(times[0] - 0.5, times[-1] + 0.5, 25), times]):
            got = interpolate(times, values, interpolation, float(t), rotation)
            want = reference.sample(times, values, interpolation, float(t), rotation)
            if rotation:  # q and -q are one rotation
                want = want * np.sign(want @ got)
            np.testing.assert_allclose(got, want, rtol=0, atol=1e-12)


# ---------------------------------------------------------------- skins on the strip

def _strip(**kw):
    objects = load_gltf(kw.pop("path", STRIP), size=SIZE, emit_warnings=False, **kw).scene.objects
    return objects[0], objects[1]  # the strip, the morphing quad


def _built_strip():
    import sys
    sys.path.insert(0, str(GLTF_DIR))
    try:
        from make_animated_assets import strip
    finally:
        sys.path.remove(str(GLTF_DIR))
    return strip()


def _bent(degrees: float) -> np.ndarray:
    """The strip posed analytically: joint 1 (at (0, 1, 0)) turned about +Z by ``degrees``,
    each vertex blended (1 - w) p + w (R (p - j) + j), w = clip(y - 0.5, 0, 1)."""
    p, _, _, _, weights = _built_strip()
    a = math.radians(degrees)
    r = np.array([[math.cos(a), -math.sin(a), 0], [math.sin(a), math.cos(a), 0], [0, 0, 1]])
    j = np.array([0.0, 1.0, 0.0])
    w = weights[:, 1:2]
    return (1 - w) * p + w * ((p - j) @ r.T + j)


def test_rest_pose_is_the_strip_as_built_and_its_node_transform_is_ignored(tmp_path):
    strip, _ = _strip()
    np.testing.assert_allclose(strip.geometry.positions, _bent(0.0), rtol=0, atol=FLOAT32_POSITION)
    np.testing.assert_array_equal(strip.transform, np.eye(4))
    doc = copy.deepcopy(DOC)
    doc["nodes"][2]["translation"] = [5.0, 0.0, 0.0]  # the skinned mesh's node: MUST be ignored (3.7.3.1)
    doc["nodes"][0]["translation"] = [0.0, 0.0, 1.0]  # the root joint: moves the mesh
    moved, _ = _strip(path=write(tmp_path, doc))
    np.testing.assert_allclose(moved.geometry.positions, _bent(0.0) + [0, 0, 1], rtol=0, atol=FLOAT32_POSITION)
    assert moved.transform[0, 3] == 0.0


@pytest.mark.parametrize("time, degrees", [(0.25, 22.5), (0.5, 45.0), (1.0, 90.0), (1.5, 45.0), (7.0, 0.0)])
def test_bend_animation_poses_the_strip_as_computed_analytically(time, degrees):
    strip, _ = _strip(time=time, animation="bend")
    np.testing.assert_allclose(strip.geometry.positions, _bent(degrees), rtol=0, atol=FLOAT32_INPUT)
    assert np.abs(strip.geometry.positions - _bent(0.0)).max() > 0.1 or degrees == 0.0
    # the blend of I and a rotation about Z keeps the normal +Z (inverse transpose of a z-block matrix)
    np.testing.assert_allclose(strip.geometry.normals, np.tile([0, 0, 1], (len(_bent(0)), 1)), atol=1e-6)


def test_step_translation_jumps_at_its_keyframe():
    before, _ = _strip(time=0.999, animation="slide")
    at, _ = _strip(time=1.0, animation=1)
    np.testing.assert_allclose(before.geometry.positions, _bent(0.0), rtol=0, atol=FLOAT32_POSITION)
    np.testing.assert_allclose(at.geometry.positions, _bent(0.0) + [1, 0, 0], rtol=0, atol=FLOAT32_POSITION)


def test_cubic_spline_scale_of_the_root_joint():
    """breathe: scale 1 -> 2, tangents 3/s: 1.125 at 0.5 s (worked above) about the origin."""
    strip, _ = _strip(time=0.5, animation="breathe")
    np.testing.assert_allclose(strip.geometry.positions, 1.125 * _bent(0.0), rtol=0, atol=FLOAT32_INPUT)


FIRST_OF_FOUR = ("animation 0 sampled, the first of 4 (0 'bend', 1 'slide', 2 'breathe', 3 'morph'); glTF "
                 "animations are alternatives: --animation NAME|INDEX picks another, --animation all samples them "
                 "together")


def test_the_first_animation_alone_is_sampled_by_default_and_the_others_are_named():
    """glTF animations are alternatives (gltf/animation.py): at 0.5 s the default is "bend"
    alone, 45 degrees, without breathe's 1.125 scale and with the quad unmorphed (0.5, not
    0.75); the warning names all four."""
    result = load_gltf(STRIP, size=SIZE, emit_warnings=False, time=0.5)
    strip, quad = result.scene.objects[:2]
    np.testing.assert_allclose(strip.geometry.positions, _bent(45.0), rtol=0, atol=FLOAT32_INPUT)
    assert quad.geometry.positions[2, 1] == pytest.approx(0.5, abs=1e-6)
    assert result.warnings == [FIRST_OF_FOUR]


def test_animation_all_samples_every_animation_together():
    strip, quad = _strip(time=0.5, animation="all")
    np.testing.assert_allclose(strip.geometry.positions, 1.125 * _bent(45.0), rtol=0, atol=2 * FLOAT32_INPUT)
    assert quad.geometry.positions[2, 1] == pytest.approx(0.75, abs=1e-6)


def test_a_named_animation_or_a_file_with_one_gives_no_warning(tmp_path):
    assert load_gltf(STRIP, size=SIZE, emit_warnings=False, time=0.5, animation="bend").warnings == []
    doc = copy.deepcopy(DOC)
    doc["animations"] = doc["animations"][:1]
    assert load_gltf(write(tmp_path, doc), size=SIZE, emit_warnings=False, time=0.5).warnings == []


def test_the_default_animation_is_named_on_the_command_line(tmp_path, capsys):
    assert cli.main(["render", str(STRIP), "-o", str(tmp_path / "x.png"), "--size", "8x8", "--time", "0.5"]) == 0
    assert f"warning: {FIRST_OF_FOUR}" in capsys.readouterr().err


def test_a_json_scene_chooses_the_animation_of_its_gltf_object(tmp_path):
    """The scene format's gltf object takes "time" and "animation" as the command line does."""
    from pbrlab.importers.loader import load_scene
    scene = {"objects": [{"gltf": str(STRIP), "time": 0.5, "animation": "all"}]}
    (tmp_path / "scene.json").write_text(json.dumps(scene))
    strip = load_scene(tmp_path / "scene.json").objects[0]
    np.testing.assert_allclose(strip.geometry.positions, 1.125 * _bent(45.0), rtol=0, atol=2 * FLOAT32_INPUT)
    scene["objects"][0]["animation"] = 2.5
    (tmp_path / "scene.json").write_text(json.dumps(scene))
    with pytest.raises(SceneError, match=r"objects\[0\]\.animation: expected an animation index, name or \"all\""):
        load_scene(tmp_path / "scene.json")


@pytest.mark.parametrize("time, top", [(0.0, 0.5), (0.25, 0.625), (1.0, 1.0), (3.0, 1.0)])
def test_morph_weight_animation(time, top):
    _, quad = _strip(time=time, animation="morph")
    np.testing.assert_allclose(quad.geometry.positions[2:, 1], [top, top], rtol=0, atol=1e-6)
    _, overridden = _strip(time=time, animation="morph", weights=(0.0,))  # --weights wins
    np.testing.assert_allclose(overridden.geometry.positions[2:, 1], [0.5, 0.5], rtol=0, atol=1e-6)


def test_normals_go_by_the_inverse_transpose_of_the_skin_matrix():
    """A non-uniform scale (2 along x) tilts a 45-degree normal toward y: (1, 1)/sqrt2
    becomes (1/2, 1) normalised, perpendicular to the scaled surface; tangents by the matrix."""
    skin = np.tile(np.diag([2.0, 1.0, 1.0, 1.0]), (1, 1, 1))
    normal = np.array([[1.0, 1.0, 0.0]]) / math.sqrt(2)
    tangent = np.array([[1.0, -1.0, 0.0, -1.0]])
    _, n, t = pose_vertices(skin, np.zeros((1, 3)), normal, tangent)
    np.testing.assert_allclose(n[0], np.array([0.5, 1.0, 0.0]) / math.hypot(0.5, 1.0), rtol=0, atol=1e-15)
    np.testing.assert_allclose(t[0], [2 / math.sqrt(5), -1 / math.sqrt(5), 0.0, -1.0], rtol=0, atol=1e-15)
    assert abs(n[0] @ t[0, :3]) < 1e-15


def test_riggedsimple_bends_at_one_second():
    """Khronos' RiggedSimple (corpus/gltf/khronos; its rest pose agrees with the Sample
    Renderer, test_khronos_models.py): its one animation turns the upper bone by 1 s."""
    from pbrlab.importers.gltf import load_gltf as load
    model = GLTF_DIR.parents[1] / "corpus" / "gltf" / "khronos" / "RiggedSimple" / "RiggedSimple.glb"
    rest = load(model, emit_warnings=False).scene.objects[0].geometry.positions
    bent = load(model, time=1.0, emit_warnings=False).scene.objects[0].geometry.positions
    assert np.isfinite(bent).all() and np.abs(bent - rest).max() > 1.0
    np.testing.assert_array_equal(rest[:, 1].min(), bent[:, 1].min())  # the lower bone stays


def test_a_posed_render_differs_from_the_rest_pose(tmp_path, capsys):
    rest, bent = tmp_path / "rest.exr", tmp_path / "bent.exr"
    assert cli.main(["render", str(STRIP), "--hdr", str(rest), "--size", "48x32"]) == 0
    assert cli.main(["render", str(STRIP), "--hdr", str(bent), "--size", "48x32", "--time", "1",
                     "--animation", "bend"]) == 0
    from pbrlab.foundation.images import read_image as read_exr
    assert np.abs(read_exr(rest) - read_exr(bent)).max() > 0.05
    assert "warning" not in capsys.readouterr().err


# ---------------------------------------------------------------- errors

@pytest.mark.parametrize("args, message", [
    (["--time", "nan"], "--time nan: expected a finite number of seconds"),
    (["--time", "soon"], "--time soon: expected a finite number"),
    (["--time", "1", "--animation", "wave"],
     "--animation wave: no animation has that index or name (the file's animations: 0 'bend', 1 'slide', "
     "2 'breathe', 3 'morph'; or all)"),
    (["--animation", "4"], "--animation 4: no animation has that index or name"),
])
def test_bad_time_and_animation_are_refused_by_name(tmp_path, capsys, args, message):
    assert cli.main(["render", str(STRIP), "-o", str(tmp_path / "x.png"), "--size", "8x8", *args]) == 2
    assert message in capsys.readouterr().err


def test_time_on_a_file_without_animations_is_refused():
    with pytest.raises(SceneError, match="--time: the file has no animations"):
        load_gltf(GLTF_DIR / "morph_scenes.gltf", time=1.0, emit_warnings=False)
    with pytest.raises(PbrlabError, match="--time inf"):
        load_gltf(STRIP, time=math.inf, emit_warnings=False)


def test_bad_skin_data_is_refused_by_name(tmp_path):
    doc = copy.deepcopy(DOC)
    doc["skins"][0]["joints"] = [0]  # vertices name joint 1 with weight > 0
    doc["skins"][0].pop("inverseBindMatrices")
    with pytest.raises(SceneError, match=r"JOINTS_0: vertex \d+ names joint 1; skins\[0\] has 1 joints"):
        load_gltf(write(tmp_path, doc), emit_warnings=False)
    doc = copy.deepcopy(DOC)
    del doc["meshes"][0]["primitives"][0]["attributes"]["WEIGHTS_0"]
    with pytest.raises(SceneError, match="has JOINTS_0 without WEIGHTS_0"):
        load_gltf(write(tmp_path, doc), emit_warnings=False)
