"""A texture's core ``source`` names a PNG or JPEG image (glTF 2.0, 5.18 images: "image/jpeg"
or "image/png"); KTX2 and WebP images come through KHR_texture_basisu and EXT_texture_webp on
the texture. pbrlab reads an image by its bytes' signature, so a file that names a KTX2 image
as a core source (AnisotropyBarnLamp's KTX2 variant in the 2023 Khronos sample set) is drawn
with its textures, where three.js r187, following the rule, draws the material without them
(82.6 codes apart in the Khronos sweep). The file is not valid: the import says so in a
warning naming the texture and the image (issue 39: nothing silent); main said nothing."""

from __future__ import annotations

import json
import shutil

import numpy as np
import pytest

from pbrlab.checking.golden_scenes import GLTF_DIR
from pbrlab.importers.gltf import load_gltf
from pbrlab.scene.model import Environment


def _load(path):
    return load_gltf(path, size=(32, 32), environment=Environment(color=np.array([0.3, 0.3, 0.3])),
                     emit_warnings=False)


def _albedo(result) -> np.ndarray:
    return next(iter(result.scene.materials.values())).textures["albedo"].pixels()


@pytest.mark.parametrize("codec, extension, name", [("uastc", "KHR_texture_basisu", "KTX2"),
                                                    ("webp", "EXT_texture_webp", "WebP")])
def test_a_core_source_that_is_not_png_or_jpeg_is_drawn_and_named_in_a_warning(tmp_path, codec, extension, name):
    source = GLTF_DIR / f"formats_{codec}.gltf"
    doc = json.loads(source.read_text())
    for image in doc["images"]:
        shutil.copy(GLTF_DIR / image["uri"], tmp_path / image["uri"])
    texture = doc["textures"][0]
    texture["source"] = texture.pop("extensions")[extension]["source"]  # the extension's image, as a core source
    doc.pop("extensionsRequired", None)
    doc["extensionsUsed"] = [e for e in doc.get("extensionsUsed", []) if e != extension]
    (tmp_path / "core.gltf").write_text(json.dumps(doc))
    core = _load(tmp_path / "core.gltf")
    assert core.warnings == [
        f"texture 0's core source images[{texture['source']}] is {name}, not valid glTF without {extension} on the "
        f"texture (core images are PNG or JPEG); drawn as {name}, which viewers that follow the extension's rule, "
        f"as three.js r187, do not (material \"base_{codec}\")"]
    # control: the valid file, the same image through the extension, draws the same texels silently
    valid = _load(source)
    assert valid.warnings == []
    np.testing.assert_array_equal(_albedo(core), _albedo(valid))
