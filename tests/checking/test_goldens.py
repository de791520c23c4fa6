"""The golden store: explicit creation, explicit updates, and failures that show their evidence."""

import json

import numpy as np
import pytest

from pbrlab.checking import goldens
from pbrlab.foundation import images
from pbrlab.checking.compare import GOLDEN_SRGB_TOLERANCE, GOLDEN_TOLERANCE, Tolerance
from pbrlab.foundation.errors import PbrlabError

INFO = {"GL_RENDERER": "llvmpipe (test)", "GL_VERSION": "4.5 (Core Profile) Mesa 0.0",
        "mesa": "0.0", "moderngl": "x", "openimageio": "y", "llvmpipe_cpu_caps": "sse4.1"}


def _render(height=12, width=16):
    y, x = np.mgrid[0:height, 0:width]
    linear = np.stack([x / width, y / height, 0.25 + 0 * x, 1 + 0 * x], axis=-1).astype(np.float32)
    srgb8 = np.round(np.clip(linear, 0, 1) ** (1 / 2.2) * 255).astype(np.uint8)
    return linear, srgb8


@pytest.fixture
def store(tmp_path):
    """check_golden with this test's folders; returns (check, root, output_dir)."""
    root, out = tmp_path / "goldens", tmp_path / "test-output"

    def check(name, linear, srgb8, *, update=False, tolerance=GOLDEN_TOLERANCE):
        return goldens.check_golden(name, linear, srgb8, tolerance, INFO, update=update,
                                    root=root, output_dir=out)
    return check, root, out


def test_missing_golden_fails_with_the_command_that_creates_it(store):
    check, root, out = store
    with pytest.raises(goldens.GoldenMissing) as failure:
        check("charts/metal", *_render())
    message = str(failure.value)
    assert "python -m pytest --update-goldens" in message
    assert "make test" not in message and ".venv" not in message  # an installed plugin has neither
    assert "metal.exr" in message
    assert not root.exists()  # nothing is created without the flag
    assert (out / "charts/metal/obtained.png").exists()  # the render a person would approve


def test_update_writes_exr_png_and_sidecar_then_the_check_passes(store):
    check, root, _ = store
    linear, srgb8 = _render()
    result = check("charts/metal", linear, srgb8, update=True)
    assert result.passed
    np.testing.assert_array_equal(images.read_image(root / "charts/metal.exr"), linear)
    np.testing.assert_array_equal(images.read_image(root / "charts/metal.png"), srgb8)
    sidecar = json.loads((root / "charts/metal.json").read_text())
    assert sidecar["renderer"] == INFO
    assert sidecar["tolerance"]["max_abs"] == GOLDEN_TOLERANCE.max_abs
    assert sidecar["tolerance"]["reason"] == GOLDEN_TOLERANCE.reason
    assert sidecar["srgb_tolerance"]["max_abs"] == GOLDEN_SRGB_TOLERANCE.max_abs
    assert images.read_metadata(root / "charts/metal.exr")["GL_RENDERER"] == "llvmpipe (test)"
    assert check("charts/metal", linear, srgb8).passed


def test_goldens_change_only_under_update(store):
    check, root, _ = store
    linear, srgb8 = _render()
    check("a", linear, srgb8, update=True)
    before = {p.name: p.read_bytes() for p in root.iterdir()}
    changed = linear.copy()
    changed[0, 0, 0] += 0.5
    with pytest.raises(goldens.GoldenMismatch):
        check("a", changed, srgb8)
    assert {p.name: p.read_bytes() for p in root.iterdir()} == before
    check("a", changed, srgb8, update=True)
    assert images.read_image(root / "a.exr")[0, 0, 0] == changed[0, 0, 0]


def test_rewriting_an_unchanged_golden_keeps_its_bytes(store):
    check, root, _ = store
    check("a", *_render(), update=True)
    before = {p.name: p.read_bytes() for p in root.iterdir()}
    check("a", *_render(), update=True)
    assert {p.name: p.read_bytes() for p in root.iterdir()} == before


def test_changed_pixel_fails_and_leaves_expected_obtained_diff(store):
    check, _, out = store
    linear, srgb8 = _render()
    check("spheres", linear, srgb8, update=True)
    changed = linear.copy()
    changed[7, 3, 1] += 2e-4  # below one sRGB step: only the linear EXR can see it
    with pytest.raises(goldens.GoldenMismatch) as failure:
        check("spheres", changed, srgb8)
    message = str(failure.value)
    assert "linear EXR  FAIL" in message and "(y=7, x=3)" in message
    assert "sRGB PNG    ok" in message and "--update-goldens" in message
    for artefact in goldens.ARTEFACTS:
        assert (out / "spheres" / artefact).exists(), artefact
    heat = images.read_image(out / "spheres/diff.png")
    assert heat[7, 3, 0] > 0 and heat[0, 0].tolist() == [0, 0, 0]
    np.testing.assert_array_equal(images.read_image(out / "spheres/obtained.exr"), changed)
    np.testing.assert_array_equal(images.read_image(out / "spheres/expected.png"), srgb8)
    assert failure.value.linear.worst_pixel == (7, 3)


def test_srgb_png_is_checked_in_code_values(store):
    check, _, _ = store
    linear, srgb8 = _render()
    check("a", linear, srgb8, update=True)
    off_by_one, off_by_two = srgb8.copy(), srgb8.copy()
    off_by_one[2, 2, 0] += 1
    off_by_two[2, 2, 0] += 2
    assert check("a", linear, off_by_one).passed
    with pytest.raises(goldens.GoldenMismatch, match=r"sRGB PNG    FAIL"):
        check("a", linear, off_by_two)


def test_nan_render_fails_and_is_never_stored(store):
    check, root, _ = store
    linear, srgb8 = _render()
    check("a", linear, srgb8, update=True)
    broken = linear.copy()
    broken[1, 1, 2] = np.nan
    lenient = Tolerance(1.0, 1.0, "test: everything but NaN passes")
    with pytest.raises(goldens.GoldenMismatch, match="non-finite"):
        check("a", broken, srgb8, tolerance=lenient)
    with pytest.raises(goldens.GoldenNonFinite):
        check("a", broken, srgb8, update=True)
    assert np.isfinite(images.read_image(root / "a.exr")).all()


def test_shape_mismatch_fails_with_a_clear_message(store):
    check, _, out = store
    check("a", *_render(12, 16), update=True)
    with pytest.raises(goldens.GoldenMismatch, match="shape mismatch: expected 16x12"):
        check("a", *_render(12, 15))
    assert (out / "a/diff.png").exists()


def test_incomplete_golden_counts_as_missing(store):
    check, root, _ = store
    check("a", *_render(), update=True)
    (root / "a.json").unlink()
    with pytest.raises(goldens.GoldenMissing, match=r"a\.json not found"):
        check("a", *_render())


def test_passing_check_removes_stale_failure_artefacts(store):
    check, _, out = store
    linear, srgb8 = _render()
    check("a", linear, srgb8, update=True)
    with pytest.raises(goldens.GoldenMismatch):
        check("a", linear + np.float32(1), srgb8)
    assert (out / "a/obtained.png").exists()
    check("a", linear, srgb8)
    assert not (out / "a").exists()


@pytest.mark.parametrize("name", ["../escape", "/abs", "a//b", "", "a b"])
def test_unusable_golden_names_are_refused(store, name):
    check, _, _ = store
    with pytest.raises(PbrlabError, match="golden name"):
        check(name, *_render())
