"""Image I/O: lossless round trips, clear errors, and atomic writes that never half-write."""

import os

import numpy as np
import pytest

from pbrlab.foundation import images, outputs
from pbrlab.foundation.errors import PbrlabError


def _special_floats(shape=(5, 7, 4)) -> np.ndarray:
    rng = np.random.default_rng(1)
    image = rng.standard_normal(shape).astype(np.float32)
    specials = np.array([np.nan, np.inf, -np.inf, -0.0, 1e-42, 65504.0, 1e30,
                         np.nextafter(np.float32(1), np.float32(2))], np.float32)
    image.reshape(-1)[: specials.size] = specials
    return image


def test_exr_round_trip_keeps_every_bit_including_nan_inf_denormals(tmp_path):
    image = _special_floats()
    images.write_exr(tmp_path / "a.exr", image)
    back = images.read_image(tmp_path / "a.exr")
    assert back.dtype == np.float32 and back.shape == image.shape
    np.testing.assert_array_equal(back.view(np.uint32), image.view(np.uint32))


@pytest.mark.parametrize("channels", [1, 3, 4])
def test_png_round_trip_keeps_every_code_value(tmp_path, channels):
    codes = np.arange(256, dtype=np.uint8)
    image = np.stack([np.roll(codes, 17 * c) for c in range(channels)], axis=-1)
    image = np.broadcast_to(image, (3, 256, channels)).copy()
    images.write_png(tmp_path / "a.png", image)
    back = images.read_image(tmp_path / "a.png")
    assert back.dtype == np.uint8
    np.testing.assert_array_equal(back, image)


def test_top_row_is_first_row_of_the_array(tmp_path):
    image = np.zeros((4, 2, 3), np.uint8)
    image[0] = 255
    images.write_png(tmp_path / "a.png", image)
    assert images.read_image(tmp_path / "a.png")[0].min() == 255


def test_exr_metadata_round_trips_as_strings(tmp_path):
    images.write_exr(tmp_path / "a.exr", np.zeros((2, 2, 3), np.float32),
                     {"GL_RENDERER": "llvmpipe (LLVM 15.0.6, 256 bits)", "mesa": None, "n": 3})
    assert images.read_metadata(tmp_path / "a.exr") == {
        "GL_RENDERER": "llvmpipe (LLVM 15.0.6, 256 bits)", "mesa": "None", "n": "3"}


def test_writers_are_deterministic_so_unchanged_goldens_keep_their_bytes(tmp_path):
    image = _special_floats()
    for name in ("a.exr", "b.exr"):
        images.write_exr(tmp_path / name, image, {"k": "v"})
    codes = (np.arange(48).reshape(4, 4, 3) * 5).astype(np.uint8)
    for name in ("a.png", "b.png"):
        images.write_png(tmp_path / name, codes)
    assert (tmp_path / "a.exr").read_bytes() == (tmp_path / "b.exr").read_bytes()
    assert (tmp_path / "a.png").read_bytes() == (tmp_path / "b.png").read_bytes()


def test_writers_reject_the_wrong_pixel_type():
    with pytest.raises(ValueError, match="uint8"):
        images.write_png("x.png", np.zeros((2, 2, 3), np.float32))
    with pytest.raises(ValueError, match="float32"):
        images.write_exr("x.exr", np.zeros((2, 2, 3), np.float64))
    with pytest.raises(ValueError, match="HxWxC"):
        images.write_png("x.png", np.zeros((2, 2, 5), np.uint8))


def test_missing_directory_is_a_clear_error(tmp_path):
    target = tmp_path / "no" / "such" / "x.png"
    with pytest.raises(PbrlabError, match=r"cannot write .*x\.png: directory .* does not exist"):
        images.write_png(target, np.zeros((2, 2, 3), np.uint8))


def test_parent_that_is_a_file_is_a_clear_error(tmp_path):
    (tmp_path / "file").write_text("")
    with pytest.raises(PbrlabError, match="is not a directory"):
        images.write_exr(tmp_path / "file" / "x.exr", np.zeros((2, 2, 3), np.float32))


def test_unwritable_directory_is_a_clear_error(tmp_path, monkeypatch):
    # root may write anywhere, so the permission check is driven through os.access.
    real_access = os.access
    monkeypatch.setattr(outputs.os, "access",
                        lambda p, mode: False if str(p) == str(tmp_path) else real_access(p, mode))
    with pytest.raises(PbrlabError, match=r"cannot write .*x\.png: directory .* is not writable"):
        images.write_png(tmp_path / "x.png", np.zeros((2, 2, 3), np.uint8))
    assert list(tmp_path.iterdir()) == []


def test_failed_write_leaves_the_old_file_intact_and_no_temporary(tmp_path, monkeypatch):
    target = tmp_path / "chart.png"
    images.write_png(target, np.full((4, 4, 3), 7, np.uint8))
    good = target.read_bytes()

    def encode_half_then_fail(tmp, spec, pixels, final):
        tmp.write_bytes(good[: len(good) // 2])  # a partial file exists when the failure hits
        raise OSError("disk full")

    monkeypatch.setattr(images, "_encode", encode_half_then_fail)
    with pytest.raises(PbrlabError, match=r"cannot write .*chart\.png: disk full"):
        images.write_png(target, np.full((4, 4, 3), 200, np.uint8))
    assert target.read_bytes() == good
    assert [p.name for p in tmp_path.iterdir()] == ["chart.png"]


def test_atomic_output_replaces_only_on_success(tmp_path):
    target = tmp_path / "a.txt"
    target.write_text("old")
    with pytest.raises(RuntimeError):
        with images.atomic_output(target) as tmp:
            assert tmp.parent == tmp_path and tmp.suffix == ".txt"
            tmp.write_text("new but broken")
            raise RuntimeError("bug in the writer")
    assert target.read_text() == "old"
    with images.atomic_output(target) as tmp:
        tmp.write_text("new")
    assert target.read_text() == "new"
    assert [p.name for p in tmp_path.iterdir()] == ["a.txt"]


def test_missing_or_unreadable_input_names_the_path(tmp_path):
    with pytest.raises(PbrlabError, match=r"cannot read .*nope\.exr: no such file"):
        images.read_image(tmp_path / "nope.exr")
    (tmp_path / "broken.png").write_bytes(b"\x89PNG\r\n\x1a\n garbage")
    with pytest.raises(PbrlabError, match=r"cannot read .*broken\.png"):
        images.read_image(tmp_path / "broken.png")
    with pytest.raises(PbrlabError, match="it is a directory"):
        images.read_image(tmp_path)


def test_unknown_file_type_is_a_clear_error_and_leaves_nothing(tmp_path):
    with pytest.raises(PbrlabError, match=r"cannot write .*x\.foo: OpenImageIO has no writer"):
        images.write_exr(tmp_path / "x.foo", np.zeros((2, 2, 3), np.float32))
    assert list(tmp_path.iterdir()) == []
