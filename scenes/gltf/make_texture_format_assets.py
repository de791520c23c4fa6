"""Generates the glTF test assets of the image-format extensions (issue 24): one textured
quad under a directional and a point light, its base colour delivered four ways. Committed
next to this script; run it again to rebuild them byte for byte (alktx2 0.1.7, which
compiles Binomial's basis_universal encoder, and Pillow's libwebp encode).

    formats_base.png          the 64 x 64 source: a colour gradient, a checker of 8 cells,
                              a disc and the orientation marker of make_assets.checker
    formats_base_etc1s.ktx2   the source in KTX2, Basis Universal ETC1S (BasisLZ
                              supercompression), sRGB transfer
    formats_base_uastc.ktx2   the source in KTX2, UASTC LDR 4x4, Zstandard supercompression
    formats_base.webp         the source in lossless WebP
    formats_png.gltf          the quad with the PNG: the twin every other file is compared with
    formats_etc1s.gltf        KHR_texture_basisu required, the ETC1S image the only source
    formats_uastc.gltf        KHR_texture_basisu used (not required): the UASTC image in the
                              extension, the PNG as the core source (the fallback)
    formats_webp.gltf         EXT_texture_webp used (not required): the WebP image in the
                              extension, the PNG as the core source (the fallback)

    .venv/bin/python scenes/gltf/make_texture_format_assets.py
"""

from __future__ import annotations

import io

import alktx2
import numpy as np
from PIL import Image

from make_assets import HERE, TEX, Builder, _grid, _lit_quads_scene, _png, _quad, _srgb8

ZSTD_LEVEL = 9  # Zstandard level for UASTC (KTX2 supercompressionScheme 2)
ENCODER = dict(effort=3, threads=1, mipmaps=False, srgb=True, check_for_alpha=False)  # one thread: deterministic


def formats_base() -> np.ndarray:
    """RGB sRGB codes: smooth gradients (what block codecs keep), a checker and a disc (hard
    edges, what they blur), the red marker at the top left (row order)."""
    u, v = _grid()
    rgb = np.stack([0.15 + 0.7 * u, 0.2 + 0.6 * v, 0.8 - 0.6 * u * v], axis=-1)
    odd = ((np.floor(u * 8) + np.floor(v * 8)) % 2).astype(bool) & (v > 0.5)
    rgb = np.where(odd[..., None], rgb * 0.35, rgb)
    disc = (u - 0.7) ** 2 + (v - 0.28) ** 2 < 0.15 ** 2
    rgb = np.where(disc[..., None], (0.95, 0.85, 0.2), rgb)
    rgb = np.where(((u < 1 / 8) & (v < 1 / 8))[..., None], (0.9, 0.1, 0.05), rgb)
    return _srgb8(rgb)


def _write_images(pixels: np.ndarray) -> dict:
    """The four encodings of ``pixels``, written beside this script: {key: file name}."""
    png = _png(pixels)
    files = {"png": ("formats_base.png", png),
             "etc1s": ("formats_base_etc1s.ktx2",
                       alktx2.encode_bytes_to_ktx2(png, mime="image/png", codec="etc1s", quality=50, **ENCODER)),
             "uastc": ("formats_base_uastc.ktx2",
                       alktx2.encode_bytes_to_ktx2(png, mime="image/png", codec="uastc", quality=100,
                                                   zstd_supercompression_level=ZSTD_LEVEL, **ENCODER))}
    webp = io.BytesIO()
    Image.fromarray(pixels).save(webp, format="WEBP", lossless=True, quality=100, method=6, exact=True)
    files["webp"] = ("formats_base.webp", webp.getvalue())
    for name, data in files.values():
        (HERE / name).write_bytes(data)
    return {key: name for key, (name, _) in files.items()}


def _quad_file(name: str, texture: dict, images: list[dict], extension: str | None = None, required=False):
    """formats_<name>.gltf: the lit quad whose base colour reads ``texture``."""
    b = Builder()
    b.json["asset"]["generator"] = "pbrlab scenes/gltf/make_texture_format_assets.py"
    b.json["images"] = images
    b.json["textures"] = [texture]
    b.json["materials"] = [{"name": f"base_{name}", "pbrMetallicRoughness": {
        "baseColorTexture": {"index": 0}, "metallicFactor": 0.0, "roughnessFactor": 0.5}}]
    p, n, uv, f = _quad(1.8)
    b.json["meshes"].append({"primitives": [b.primitive(p, n, uv, f, 0)]})
    if extension:
        b.json["extensionsUsed"] = [extension]
        if required:
            b.json["extensionsRequired"] = [extension]
    _lit_quads_scene(b, [(0, (0.0, 0.0, 0.0))], yfov=0.5, aspect=1.0, distance=2.6)
    b.write_gltf(HERE / f"formats_{name}.gltf", external_bin=False)


def main():
    files = _write_images(formats_base())
    png = {"uri": files["png"], "mimeType": "image/png"}
    _quad_file("png", {"source": 0}, [png])
    _quad_file("etc1s", {"extensions": {"KHR_texture_basisu": {"source": 0}}},
               [{"uri": files["etc1s"], "mimeType": "image/ktx2"}], "KHR_texture_basisu", required=True)
    _quad_file("uastc", {"source": 0, "extensions": {"KHR_texture_basisu": {"source": 1}}},
               [png, {"uri": files["uastc"], "mimeType": "image/ktx2"}], "KHR_texture_basisu")
    _quad_file("webp", {"source": 0, "extensions": {"EXT_texture_webp": {"source": 1}}},
               [png, {"uri": files["webp"], "mimeType": "image/webp"}], "EXT_texture_webp")


if __name__ == "__main__":
    main()
