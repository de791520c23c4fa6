"""The default display of a glTF file in physical light units (pbrlab/maths/exposure.py,
gltf/settings.py light_units_default): Khronos PBR Neutral and a metered exposure that
darkens just enough that at most 1 % of the model's pixels reach code 255, applied by
`pbrlab render` only when the user chose neither tonemap nor exposure. The scene is
LightsPunctualLamp-like: a 60 cd point light 0.1 m in front of a white quad (the lamp's
15 cd bulb sits 0.2 m inside its shade)."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from PIL import Image

from gltf_helpers import quad_document, write
from pbrlab.commands import cli
from pbrlab.maths import srgb8
from pbrlab.maths.exposure import CLIPPED_FRACTION, NEUTRAL_SATURATES_AT, metered_exposure
from pbrlab.maths.reference.tonemap import tonemap

SIZE = "96x96"


def _lamp_like() -> dict:
    doc = quad_document()
    doc["materials"][0]["pbrMetallicRoughness"]["baseColorFactor"] = [0.9, 0.85, 0.8, 1.0]
    doc["extensionsUsed"] = ["KHR_lights_punctual"]
    doc["extensions"] = {"KHR_lights_punctual": {"lights": [{"type": "point", "intensity": 60.0}]}}
    doc["nodes"].append({"translation": [0.0, 0.0, 0.1], "extensions": {"KHR_lights_punctual": {"light": 0}}})
    doc["scenes"][0]["nodes"].append(1)
    return doc


def _render(tmp_path, doc, side=None, name="lamp"):
    model = write(tmp_path, doc, f"{name}.gltf")
    if side is not None:
        (tmp_path / f"{name}.pbrlab.json").write_text(json.dumps(side))
    out, hdr = tmp_path / f"{name}.png", tmp_path / f"{name}.exr"
    assert cli.main(["render", str(model), "-o", str(out), "--hdr", str(hdr), "--size", SIZE]) == 0
    from pbrlab.foundation.images import read_image
    return np.asarray(Image.open(out))[..., :3], read_image(hdr)


def _clipped(png, linear) -> float:
    covered = linear[..., 3] > 0
    return float((png[covered] >= 255).any(axis=-1).mean())


def test_the_saturating_input_is_where_the_neutral_reaches_code_255():
    """Differential: the constant, derived from the neutral's formula, against the float64
    reference tonemap and the exact encode."""
    below = tonemap(np.full(3, NEUTRAL_SATURATES_AT * (1 - 1e-9)), "KHRONOS_NEUTRAL")
    above = tonemap(np.full(3, NEUTRAL_SATURATES_AT * (1 + 1e-9)), "KHRONOS_NEUTRAL")
    assert srgb8.encode(below).max() == 254 and srgb8.encode(above).min() == 255


def test_metered_exposure_darkens_only_what_would_clip():
    image = np.zeros((10, 100, 4), np.float32)
    image[..., 3] = 1.0
    image[..., :3] = 2.0  # nothing would clip: no change
    assert metered_exposure(image) == 0.0
    image[..., :3] = 8 * NEUTRAL_SATURATES_AT  # all of it would: three stops down
    assert metered_exposure(image) == pytest.approx(-3.0, abs=1e-6)
    rng = np.random.default_rng(24)
    image[..., :3] = rng.lognormal(2.0, 2.0, (10, 100, 1))
    image[:5, :, 3] = 0.0  # uncovered pixels do not count, however bright
    image[:5, :, :3] = 1e6
    ev = metered_exposure(image)
    shown = tonemap(image[5:, :, :3].astype(np.float64) * 2.0 ** ev, "KHRONOS_NEUTRAL")
    clipped = (srgb8.encode(shown) >= 255).any(axis=-1).mean()
    assert ev < 0 and 0 < clipped <= CLIPPED_FRACTION


def test_a_lamp_like_file_is_not_blown_out_by_default(tmp_path, capsys):
    png, linear = _render(tmp_path, _lamp_like())
    chosen, _ = _render(tmp_path, _lamp_like(), side={"render": {"tonemap": "none"}}, name="chosen")
    default_clipped, before_clipped = _clipped(png, linear), _clipped(chosen, linear)
    assert before_clipped > 0.2  # tonemap none, exposure 0: a blown-out hot spot
    assert default_clipped <= CLIPPED_FRACTION + 2 / (linear[..., 3] > 0).sum()
    out = capsys.readouterr().out
    assert "(metered), tonemap khronos_neutral" in out and "EV" in out
    ev = float(out.split("exposure ")[1].split(" EV")[0])
    assert ev < -1.0


def test_the_user_s_choice_and_files_without_lights_are_left_alone(tmp_path, capsys):
    _render(tmp_path, _lamp_like(), side={"render": {"exposure": 0.5}}, name="exposed")
    png_quad, linear_quad = _render(tmp_path, quad_document(), side={"environment": {"color": [2.0, 2.0, 2.0]}},
                                    name="unlit")
    out = capsys.readouterr().out
    assert "metered" not in out
    # tonemap none, exposure 0: the display is the encode of the linear radiance, clipped
    assert (png_quad == 255).any()
    np.testing.assert_array_equal(png_quad, srgb8.encode(linear_quad[..., :3]))


def test_metering_is_independent_of_the_linear_image(tmp_path):
    """The EXR holds the radiance before exposure: the metered and the chosen renders agree."""
    _, metered = _render(tmp_path, _lamp_like())
    _, chosen = _render(tmp_path, _lamp_like(), side={"render": {"tonemap": "none"}}, name="chosen")
    np.testing.assert_array_equal(metered, chosen)
    assert math.isfinite(float(metered[..., :3].max()))
