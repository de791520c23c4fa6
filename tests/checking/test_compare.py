"""The comparison module and its command, `pbrlab diff`: what passes, what fails, and that
nothing odd slips through (exit 0 within tolerance, 1 over it, 2 for bad files)."""

import json

import numpy as np
import pytest

from pbrlab.commands import cli
from pbrlab.checking import compare
from pbrlab.foundation import images
from pbrlab.checking.compare import GOLDEN_TOLERANCE, Tolerance, diff

TIGHT = Tolerance(1e-6, 0.0, "test: any visible change fails")


def _ramp(height=16, width=24, channels=4) -> np.ndarray:
    y, x, c = np.meshgrid(np.arange(height), np.arange(width), np.arange(channels), indexing="ij")
    return ((x + 2 * y + 3 * c) / 100.0).astype(np.float32)


def test_identical_images_pass_with_zero_error():
    result = diff(_ramp(), _ramp(), TIGHT)
    assert result.passed
    assert (result.max_abs, result.rmse, result.pixels_over, result.worst_pixel) == (0, 0, 0, None)


def test_one_changed_pixel_fails_and_is_located():
    obtained = _ramp()
    obtained[5, 9, 2] += 1e-3
    result = diff(_ramp(), obtained, TIGHT)
    assert not result.passed
    assert result.pixels_over == 1 and result.worst_pixel == (5, 9)
    assert result.max_abs == pytest.approx(1e-3, rel=1e-3)
    assert result.fraction_over == pytest.approx(1 / (16 * 24))


def test_max_fraction_allows_exactly_that_many_pixels_over():
    obtained = _ramp(10, 10, 3)
    obtained[0, :2] += 0.5  # 2 of 100 pixels over
    assert diff(_ramp(10, 10, 3), obtained, Tolerance(1e-6, 0.02, "test")).passed
    assert not diff(_ramp(10, 10, 3), obtained, Tolerance(1e-6, 0.01, "test")).passed


def test_difference_within_max_abs_passes():
    obtained = _ramp() + np.float32(4e-7)
    result = diff(_ramp(), obtained, TIGHT)
    assert result.passed and 0 < result.max_abs <= 1e-6


@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf])
def test_a_nonfinite_obtained_pixel_fails_even_when_the_fraction_would_allow_it(bad):
    obtained = _ramp()
    obtained[3, 4, 1] = bad
    result = diff(_ramp(), obtained, Tolerance(1.0, 0.5, "test: lenient on purpose"))
    assert not result.passed
    assert result.nonfinite_obtained == 1 and result.worst_pixel == (3, 4)
    assert np.isfinite(result.max_abs) and np.isfinite(result.rmse)  # metrics of the rest


def test_nan_in_both_images_is_not_equal():
    expected, obtained = _ramp(), _ramp()
    expected[0, 0, 0] = obtained[0, 0, 0] = np.nan
    result = diff(expected, obtained, TIGHT)
    assert not result.passed and result.nonfinite_expected == 1


@pytest.mark.parametrize("shape", [(16, 23, 4), (15, 24, 4), (16, 24, 3)])
def test_shape_mismatch_is_a_failure_not_an_exception(shape):
    result = diff(_ramp(), np.zeros(shape, np.float32), TIGHT)
    assert not result.passed
    assert "shape mismatch" in result.problem and "shape mismatch" in result.summary()
    assert result.heatmap().shape == (16, 24, 3)
    json.dumps(result.to_dict())


def test_uint8_images_compare_in_code_values():
    expected = np.full((4, 4, 3), 100, np.uint8)
    obtained = expected.copy()
    obtained[1, 2, 0] = 101
    one_code = Tolerance(1, 0.0, "test: one code")
    assert diff(expected, obtained, one_code).passed
    obtained[1, 2, 0] = 98  # 2 codes below: no uint8 wrap-around
    result = diff(expected, obtained, one_code)
    assert not result.passed and result.max_abs == 2 and result.units == compare.UNITS_CODES


def test_mixing_8bit_and_float_images_is_refused():
    with pytest.raises(TypeError, match="cannot compare"):
        diff(np.zeros((2, 2, 3), np.uint8), np.zeros((2, 2, 3), np.float32), TIGHT)


def test_tolerance_rejects_nonsense():
    for bad in [(-1, 0, "r"), (np.nan, 0, "r"), (1, 1.5, "r"), (1, 0, " ")]:
        with pytest.raises(ValueError):
            Tolerance(*bad)


def test_golden_tolerances_state_units_and_reasons():
    assert compare.GOLDEN_TOLERANCE.max_abs < compare.SRGB_SMALLEST_STEP_LINEAR / 10
    assert compare.GOLDEN_SRGB_TOLERANCE.max_abs == 1
    assert compare.GOLDEN_TOLERANCE.reason and compare.GOLDEN_SRGB_TOLERANCE.reason


def test_heatmap_colours_identical_within_over_and_nonfinite_pixels():
    expected = np.zeros((1, 4, 3), np.float32)
    obtained = np.array([[[0, 0, 0], [5e-7, 0, 0], [1e-3, 0, 0], [np.nan, 0, 0]]], np.float32)
    heat = diff(expected, obtained, TIGHT).heatmap()
    assert heat.dtype == np.uint8 and heat.shape == (1, 4, 3)
    black, within, over, nonfinite = heat[0]
    assert black.tolist() == [0, 0, 0]
    assert within[0] == 0 and within[2] > 0  # blue
    assert over[0] >= 160 and over[2] == 0   # red to yellow
    assert nonfinite.tolist() == [255, 0, 255]


def test_flip_is_reported_for_8bit_images_only():
    # flip-evaluator is pinned in requirements.txt; compare runs without it (flip_mean None).
    assert compare.flip_available()
    rng = np.random.default_rng(3)
    expected = rng.integers(0, 256, (16, 16, 3), dtype=np.uint8)
    obtained = expected.copy()
    obtained[4:8, 4:8] = 255 - obtained[4:8, 4:8]
    assert diff(expected, expected, TIGHT, flip=True).flip_mean == 0
    assert diff(expected, obtained, TIGHT, flip=True).flip_mean > 0
    assert diff(_ramp(), _ramp(), TIGHT, flip=True).flip_mean is None


# `pbrlab diff` --------------------------------------------------------------


@pytest.fixture
def exr_pair(tmp_path):
    expected = np.linspace(0, 2, 8 * 8 * 3, dtype=np.float32).reshape(8, 8, 3)
    images.write_exr(tmp_path / "a.exr", expected)
    return tmp_path, expected


def test_identical_exr_exits_0_and_prints_metrics(exr_pair, capsys):
    folder, _ = exr_pair
    assert cli.main(["diff", str(folder / "a.exr"), str(folder / "a.exr")]) == 0
    out = capsys.readouterr().out
    for line in ("max abs       0 (linear)", "RMSE", "over          0 of 64 pixels",
                 "FLIP mean", "verdict       within tolerance"):
        assert line in out, line


def test_exr_over_the_golden_tolerance_exits_1(exr_pair, capsys):
    folder, expected = exr_pair
    obtained = expected.copy()
    obtained[2, 5, 0] += 10 * GOLDEN_TOLERANCE.max_abs
    images.write_exr(folder / "b.exr", obtained)
    heatmap = folder / "heat.png"
    assert cli.main(["diff", str(folder / "a.exr"), str(folder / "b.exr"),
                     "--heatmap", str(heatmap)]) == 1
    out = capsys.readouterr().out
    assert "at (y=2, x=5)" in out and "OVER TOLERANCE" in out
    heat = images.read_image(heatmap)
    assert heat.shape == (8, 8, 3) and heat[2, 5, 0] > 0 and heat[0, 0].tolist() == [0, 0, 0]
    # The same pair passes when the tolerance given on the command line allows it.
    assert cli.main(["diff", str(folder / "a.exr"), str(folder / "b.exr"),
                     "--max-fraction", "0.02"]) == 0
    assert cli.main(["diff", str(folder / "a.exr"), str(folder / "b.exr"),
                     "--max-abs", "1e-3"]) == 0


def test_png_is_compared_in_code_values_with_flip(tmp_path, capsys):
    codes = np.full((6, 6, 3), 120, np.uint8)
    images.write_png(tmp_path / "a.png", codes)
    codes[1, 1] = 130
    images.write_png(tmp_path / "b.png", codes)
    assert cli.main(["diff", str(tmp_path / "a.png"), str(tmp_path / "b.png")]) == 1
    out = capsys.readouterr().out
    assert "max abs       10 (8-bit code values)" in out
    assert "FLIP mean     " in out and "n/a" not in out


def test_missing_file_exits_2_naming_it(exr_pair, capsys):
    folder, _ = exr_pair
    assert cli.main(["diff", str(folder / "a.exr"), str(folder / "missing.exr")]) == 2
    assert "missing.exr: no such file" in capsys.readouterr().err


def test_png_against_exr_exits_2(exr_pair, capsys):
    folder, _ = exr_pair
    images.write_png(folder / "a.png", np.zeros((8, 8, 3), np.uint8))
    assert cli.main(["diff", str(folder / "a.exr"), str(folder / "a.png")]) == 2
    assert "compare PNG with PNG" in capsys.readouterr().err


def test_bad_tolerance_and_unwritable_heatmap_exit_2(exr_pair, capsys):
    folder, _ = exr_pair
    a = str(folder / "a.exr")
    assert cli.main(["diff", a, a, "--max-fraction", "2"]) == 2
    assert cli.main(["diff", a, a, "--heatmap", str(folder / "no" / "heat.png")]) == 2
    assert "does not exist" in capsys.readouterr().err


def test_shape_mismatch_exits_1(exr_pair, capsys):
    folder, _ = exr_pair
    images.write_exr(folder / "small.exr", np.zeros((4, 8, 3), np.float32))
    assert cli.main(["diff", str(folder / "a.exr"), str(folder / "small.exr")]) == 1
    assert "shape mismatch" in capsys.readouterr().out


def test_float32_ulps_counts_roundings_of_the_expected_value():
    one = np.float32(1.0)
    ulps = compare.float32_ulps
    assert ulps([one, 2 * one, 0.0], [np.nextafter(one, 2 * one), 2 * one, 0.0]).tolist() == [1.0, 0.0, 0.0]
    # in spacings above the expected value: the float below 1 is half a spacing of 1 away
    assert ulps([one], [np.nextafter(one, 0 * one)]).tolist() == [0.5]
    assert ulps([1e8], [1e8 + 24])[0] == 3.0  # float32 spacing 8 at 1e8
