"""glTF as it is delivered (issue 24): 16-bit and palette PNGs, files outside the model's
folder, outputs that are the model's own files, corrupt KTX2 images. The PNGs are written here
(OpenImageIO, Pillow) and their expected decoded values computed from the arrays written."""

from __future__ import annotations

import io
import json

import numpy as np
import OpenImageIO as oiio
import pytest
from PIL import Image

from gltf_helpers import blob, quad_document, write
from pbrlab.commands import cli
from pbrlab.foundation.errors import SceneError
from pbrlab.importers.gltf import load_gltf
from pbrlab.importers.gltf.images import KTX2_SIGNATURE

RNG = np.random.default_rng(24)


def _textured(tmp_path, uri: str, **image):
    doc = quad_document()
    doc["images"] = [{"uri": uri, **image}]
    doc["textures"] = [{"source": 0}]
    doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {"index": 0}
    return write(tmp_path, doc)


def _albedo(path) -> np.ndarray:
    scene = load_gltf(path, emit_warnings=False).scene
    return next(iter(scene.materials.values())).textures["albedo"].pixels()


def _write_png16(path, pixels: np.ndarray) -> None:
    out = oiio.ImageOutput.create(str(path))
    h, w, c = pixels.shape
    assert out.open(str(path), oiio.ImageSpec(w, h, c, "uint16")) and out.write_image(pixels) and out.close()


@pytest.mark.parametrize("channels", [1, 3])
def test_a_16_bit_png_reads_to_the_nearest_8_bit_code(tmp_path, channels):
    # dark values, as the base colour (mean 0.12): Pillow clipped 16-bit grey to white
    values = RNG.integers(0, 65536 // 4, (6, 5, channels)).astype(np.uint16)
    _write_png16(tmp_path / "base.png", values)
    got = _albedo(_textured(tmp_path, "base.png"))
    expected = np.floor(values.astype(np.float64) * 255 / 65535 + 0.5).astype(np.uint8)
    assert got.shape == (6, 5, 3)
    np.testing.assert_array_equal(got, np.repeat(expected, 3 // channels, axis=2))
    assert abs(got.mean() / 255 - values.mean() / 65535) < 1 / 255


def test_a_palette_png_keeps_its_trns_alpha(tmp_path):
    palette = RNG.integers(0, 256, (4, 3)).astype(np.uint8)
    alphas = np.array([0, 77, 255, 130], np.uint8)  # tRNS: one alpha per palette entry
    index = RNG.integers(0, 4, (3, 7)).astype(np.uint8)
    image = Image.new("P", (index.shape[1], index.shape[0]))
    image.putdata(index.reshape(-1).tolist())
    image.putpalette(palette.reshape(-1).tolist())
    image.save(tmp_path / "palette.png", transparency=alphas.tobytes())
    got = _albedo(_textured(tmp_path, "palette.png"))
    np.testing.assert_array_equal(got, np.concatenate([palette[index], alphas[index][..., None]], axis=2))


def test_an_rgb_png_with_a_trns_colour_key_has_alpha(tmp_path):
    pixels = RNG.integers(0, 256, (4, 4, 3)).astype(np.uint8)
    pixels[1, 2] = pixels[3, 0] = (10, 20, 30)
    Image.fromarray(pixels).save(tmp_path / "key.png", transparency=(10, 20, 30))
    got = _albedo(_textured(tmp_path, "key.png"))
    alpha = np.where((pixels == (10, 20, 30)).all(axis=2), 0, 255).astype(np.uint8)
    np.testing.assert_array_equal(got, np.concatenate([pixels, alpha[..., None]], axis=2))


# --- files outside the model's folder --------------------------------------------------

def _cli(argv, capsys):
    status = cli.main([str(a) for a in argv])
    err = capsys.readouterr().err
    assert "Traceback" not in err, err
    return status, err


def _model_with_buffer_file(folder, uri: str):
    doc = quad_document()
    data = blob(doc)
    (folder / "quad.bin").write_bytes(data)
    doc["buffers"][0]["uri"] = uri
    return doc, data


@pytest.mark.parametrize("where", ["parent", "absolute"])
def test_a_buffer_outside_the_models_folder_is_refused(tmp_path, capsys, where):
    model_dir = tmp_path / "model"
    model_dir.mkdir()
    doc, _ = _model_with_buffer_file(tmp_path, "../quad.bin" if where == "parent" else str(tmp_path / "quad.bin"))
    path = write(model_dir, doc)
    status, err = _cli(["render", path, "-o", tmp_path / "out.png", "--size", "8x8"], capsys)
    assert status == 2
    assert "buffers[0]: only files beside the glTF (in its folder or below it) and data: URIs are read" in err
    assert "(pass --allow-outside to read files outside it)" in err
    assert not (tmp_path / "out.png").exists()


@pytest.mark.parametrize("where", ["parent", "absolute"])
def test_allow_outside_reads_a_buffer_outside_the_models_folder(tmp_path, capsys, where):
    model_dir = tmp_path / "model"
    model_dir.mkdir()
    doc, data = _model_with_buffer_file(tmp_path, "../quad.bin" if where == "parent" else str(tmp_path / "quad.bin"))
    path = write(model_dir, doc)
    status, err = _cli(["render", path, "-o", tmp_path / "out.png", "--size", "8x8", "--allow-outside"], capsys)
    assert status == 0, err
    inside_dir = tmp_path / "inside"  # the same model with its buffer beside it: the same image
    inside_dir.mkdir()
    (inside_dir / "quad.bin").write_bytes(data)
    doc["buffers"][0]["uri"] = "quad.bin"
    status, err = _cli(["render", write(inside_dir, doc), "-o", tmp_path / "inside.png", "--size", "8x8"], capsys)
    assert status == 0, err
    assert (tmp_path / "out.png").read_bytes() == (tmp_path / "inside.png").read_bytes()


def test_an_output_over_a_buffer_read_from_outside_is_refused(tmp_path, capsys):
    model_dir = tmp_path / "model"
    model_dir.mkdir()
    doc, data = _model_with_buffer_file(tmp_path, "../quad.bin")
    (tmp_path / "quad.exr").write_bytes(data)
    doc["buffers"][0]["uri"] = "../quad.exr"
    path = write(model_dir, doc)
    status, err = _cli(["render", path, "--hdr", tmp_path / "quad.exr", "--size", "8x8", "--allow-outside"], capsys)
    assert status == 2, err
    assert "buffers[0] of model.gltf" in err
    assert (tmp_path / "quad.exr").read_bytes() == data


def test_allow_outside_also_takes_a_json_scene(tmp_path, capsys):
    """Issue 39: a JSON scene's links out of its folder are refused too, so the flag that allows
    them is no longer for glTF files only (tests/hostile/test_paths_round_three.py)."""
    scene = tmp_path / "scene.json"
    scene.write_text(json.dumps({"camera": {"position": [0, 0, 3], "target": [0, 0, 0]}, "objects": [
        {"sphere": {"center": [0, 0, 0], "radius": 1}, "material": "m"}], "materials": {"m": {}}}))
    status, err = _cli(["render", scene, "-o", tmp_path / "out.png", "--size", "8x8", "--allow-outside"], capsys)
    assert status == 0, err


@pytest.mark.parametrize("uri", ["../x.png", "/etc/x.png", "C:/x.png", "sub/..\\..\\x.png"])
def test_an_image_outside_the_models_folder_is_refused(tmp_path, uri):
    with pytest.raises(SceneError, match=r"images\[0\]: only files beside the glTF"):
        load_gltf(_textured(tmp_path, uri), emit_warnings=False)


def test_a_file_in_a_subfolder_is_read(tmp_path):
    (tmp_path / "textures").mkdir()
    Image.fromarray(np.full((2, 2, 3), 40, np.uint8)).save(tmp_path / "textures" / "a.png")
    assert (_albedo(_textured(tmp_path, "textures/a.png")) == 40).all()


# --- outputs are not the model's inputs ------------------------------------------------

def _textured_model(tmp_path):
    doc, data = _model_with_buffer_file(tmp_path, "quad.exr")  # a buffer under an image's name
    Image.fromarray(np.full((2, 2, 3), 200, np.uint8)).save(tmp_path / "tex.png")
    doc["images"] = [{"uri": "tex.png"}]
    doc["textures"] = [{"source": 0}]
    doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {"index": 0}
    (tmp_path / "quad.exr").write_bytes(data)
    return write(tmp_path, doc)


@pytest.mark.parametrize("flag, name, role", [("-o", "tex.png", "images[0] of model.gltf"),
                                              ("--hdr", "quad.exr", "buffers[0] of model.gltf")])
@pytest.mark.parametrize("through", ["gltf", "json scene"])
def test_an_output_that_is_the_models_image_or_buffer_is_refused(tmp_path, capsys, flag, name, role, through):
    path = _textured_model(tmp_path)
    if through == "json scene":
        path = tmp_path / "scene.json"
        camera = {"position": [0, 0, 3], "target": [0, 0, 0], "fov_y_deg": 40, "size": [8, 8]}
        path.write_text(json.dumps({"camera": camera, "objects": [{"gltf": "model.gltf"}]}))
    before = {p.name: p.read_bytes() for p in tmp_path.iterdir()}
    status, err = _cli(["render", path, flag, tmp_path / name, "--size", "8x8"], capsys)
    assert status == 2, err
    assert f"refusing to write {tmp_path / name}: it is also an input of this command ({role}" in err
    assert {p.name: p.read_bytes() for p in tmp_path.iterdir()} == before


# --- KTX2 (KHR_texture_basisu) ---------------------------------------------------------

def _ktx2_model(tmp_path, how: str):
    (tmp_path / "base.ktx2").write_bytes(KTX2_SIGNATURE + bytes(64))
    doc = quad_document()
    doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {"index": 0}
    doc["extensionsUsed"] = ["KHR_texture_basisu"]
    if how == "source is KTX2":  # AnisotropyBarnLamp's glTF-KTX2-Basisu: no mimeType, KTX2 bytes
        doc["images"] = [{"uri": "base.ktx2"}]
        doc["textures"] = [{"source": 0}]
    elif how == "mimeType":
        doc["images"] = [{"uri": "base.ktx2", "mimeType": "image/ktx2"}]
        doc["textures"] = [{"source": 0}]
    else:  # the extension's own form, without a PNG fallback
        doc["images"] = [{"uri": "base.ktx2", "mimeType": "image/ktx2"}]
        doc["textures"] = [{"extensions": {"KHR_texture_basisu": {"source": 0}}}]
    return write(tmp_path, doc)


@pytest.mark.parametrize("how", ["source is KTX2", "mimeType", "extension only"])
def test_a_corrupt_ktx2_image_is_refused_by_its_file_and_extensions_name(tmp_path, capsys, how):
    """Read by the transcoder however the file points at it (gltf/ktx2.py; the committed
    KTX2 assets are tests/importers/gltf/test_gltf_texture_formats.py's)."""
    path = _ktx2_model(tmp_path, how)
    where = "images[0]: base.ktx2 is not a KTX2 image with a Basis Universal payload (KHR_texture_basisu)"
    status, err = _cli(["render", path, "-o", tmp_path / "out.png", "--size", "8x8"], capsys)
    assert status == 2
    assert f"model.gltf: {where}" in err and "KHR_texture_basisu" in err and "KTX2" in err, err
    assert "object at 0x" not in err and not (tmp_path / "out.png").exists()


def test_an_unreadable_image_names_its_bytes_not_a_python_object(tmp_path):
    (tmp_path / "x.png").write_bytes(b"no image here" + bytes(20))
    with pytest.raises(SceneError) as info:
        load_gltf(_textured(tmp_path, "x.png"), emit_warnings=False)
    assert "images[0]: is not a readable PNG, JPEG or WebP image (it starts with bytes 6e 6f 20" in str(info.value)
    assert "object at 0x" not in str(info.value)
