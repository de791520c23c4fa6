"""KHR_texture_basisu (KTX2, Basis Universal ETC1S and UASTC + Zstandard, transcoded by
opengl_basisu) and EXT_texture_webp (Pillow): scenes/gltf/make_texture_format_assets.py
encodes one 64 x 64 base colour (formats_base.png) each way; formats_png.gltf is the twin.
Each decoded image is compared with its PNG source, and each file's render with the render
of a PNG holding exactly the texels the importer decoded (bit for bit) and with the twin."""

from __future__ import annotations

import json
import shutil

import numpy as np
import pytest
from PIL import Image

from pbrlab.checking.compare import Tolerance, diff
from pbrlab.checking.golden_scenes import GLTF_DIR
from pbrlab.importers.gltf import ktx2, load_gltf, webp
from pbrlab.render.renderer import render_scene
from pbrlab.scene.model import Environment
from test_gltf_errors import _refused

ENV = Environment(color=np.array([0.3, 0.3, 0.35]))
SIZE = (96, 96)
SOURCE = np.asarray(Image.open(GLTF_DIR / "formats_base.png").convert("RGB"))
# The codecs' error on this image, in 8-bit codes per channel, measured with basis_universal
# v2_50's transcoder (opengl_basisu 0.1.0a2) on the committed files:
# ETC1S (4x4 blocks of two endpoint colours and a shared palette, quality 50): mean 3.84,
# 3.1 % of texels over 32 codes, at the disc's and the checker's edges (worst 145: yellow
# beside dark blue in one block). UASTC (near-lossless, no RDO): mean 0.38, worst 4.
TEXEL_ERROR = {
    "etc1s": (4.0, Tolerance(32, 0.032, "8-bit codes: ETC1S's two-colour blocks across hard edges, measured 3.1 %")),
    "uastc": (0.4, Tolerance(4, 0.0, "8-bit codes: UASTC LDR 4x4 without RDO, measured worst 4")),
    "webp": (0.0, Tolerance(0, 0.0, "lossless WebP: exact")),
}
# The lit quad's render against the PNG twin's (codes, RGB): the texel error through the
# lighting (ETC1S 4.4 % over 32 codes measured, UASTC worst 4, WebP none).
RENDER_ERROR = {
    "etc1s": Tolerance(32, 0.045, "8-bit codes: ETC1S's texel error lit, measured 4.4 % over 32"),
    "uastc": Tolerance(4, 0.0, "8-bit codes: UASTC's texel error lit, measured worst 4"),
    "webp": Tolerance(0, 0.0, "lossless WebP: the twin's texels exactly"),
}


def _load(path, **kw):
    return load_gltf(path, size=SIZE, environment=ENV, emit_warnings=False, **kw)


def _albedo(result):
    return next(iter(result.scene.materials.values())).textures["albedo"]


def _srgb(result) -> np.ndarray:
    return render_scene(result.scene).srgb8[..., :3]


@pytest.mark.parametrize("codec", sorted(TEXEL_ERROR))
def test_a_decoded_image_is_its_png_source_within_the_codec_error(codec):
    result = _load(GLTF_DIR / f"formats_{codec}.gltf")
    assert result.warnings == []
    decoded = _albedo(result).pixels()
    assert decoded.shape == SOURCE.shape and decoded.dtype == np.uint8
    mean, tolerance = TEXEL_ERROR[codec]
    error = np.abs(decoded.astype(int) - SOURCE.astype(int))
    assert error.mean() <= mean, error.mean()
    assert diff(SOURCE, decoded, tolerance).passed
    # row order: against the source upside down the same comparison fails (KTX2's "rd")
    assert not diff(SOURCE[::-1], decoded, tolerance).passed


@pytest.mark.parametrize("codec", ["etc1s", "uastc"])
def test_a_ktx2_file_renders_as_a_png_of_its_decoded_texels(tmp_path, codec):
    result = _load(GLTF_DIR / f"formats_{codec}.gltf")
    Image.fromarray(_albedo(result).pixels()).save(tmp_path / "decoded.png")
    twin = json.loads((GLTF_DIR / "formats_png.gltf").read_text())
    twin["images"][0]["uri"] = "decoded.png"
    (tmp_path / "twin.gltf").write_text(json.dumps(twin))
    np.testing.assert_array_equal(render_scene(result.scene).linear,
                                  render_scene(_load(tmp_path / "twin.gltf").scene).linear)


@pytest.mark.parametrize("codec", sorted(RENDER_ERROR))
def test_a_delivered_texture_renders_as_its_png_twin_within_the_codec_error(codec):
    expected = _srgb(_load(GLTF_DIR / "formats_png.gltf"))
    result = diff(expected, _srgb(_load(GLTF_DIR / f"formats_{codec}.gltf")), RENDER_ERROR[codec])
    assert result.passed, result


@pytest.mark.parametrize("codec, module, extension, core",
                         [("uastc", ktx2, "KHR_texture_basisu", 0), ("webp", webp, "EXT_texture_webp", 0)])
def test_the_extension_source_is_read_and_the_core_source_is_the_fallback(monkeypatch, codec, module, extension,
                                                                          core):
    path = GLTF_DIR / f"formats_{codec}.gltf"
    read = _albedo(_load(path))
    assert read.key[-2] == 1  # the extension's image, not the core source's
    monkeypatch.setattr(module, "available", lambda: False)
    fallback = _load(path)
    assert fallback.warnings == [f"{extension} ignored in texture 0 (its decoder is not installed: {module.INSTALL}; "
                                 f"the core source, images[{core}], is drawn) (material \"base_{codec}\")"]
    assert _albedo(fallback).key[-2] == core
    np.testing.assert_array_equal(_albedo(fallback).pixels(), SOURCE)


def test_a_required_ktx2_file_without_the_transcoder_is_refused_naming_what_to_install(monkeypatch, tmp_path,
                                                                                      capsys):
    monkeypatch.setattr(ktx2, "available", lambda: False)
    _refused(tmp_path, capsys, GLTF_DIR / "formats_etc1s.gltf", "extensionsRequired: KHR_texture_basisu is required by "
             f"the file and its decoder is not installed ({ktx2.INSTALL})")


def test_a_ktx2_image_without_the_transcoder_is_refused_naming_what_to_install(monkeypatch, tmp_path, capsys):
    monkeypatch.setattr(ktx2, "available", lambda: False)
    for name in ("formats_etc1s.gltf", "formats_base_etc1s.ktx2"):
        shutil.copy(GLTF_DIR / name, tmp_path / name)
    doc = json.loads((tmp_path / "formats_etc1s.gltf").read_text())
    del doc["extensionsRequired"]  # the file then reaches the texture: no core source to fall back to
    _refused(tmp_path, capsys, doc, "textures[0]: has only a KHR_texture_basisu source and no core source, and the "
             f"decoder is not installed ({ktx2.INSTALL})")
