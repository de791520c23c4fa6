"""KHR_texture_basisu: KTX2 images with a Basis Universal payload (ETC1S with BasisLZ, or
UASTC, optionally with Zstandard supercompression) transcoded to RGBA8 by ``opengl_basisu``
(Binomial's basis_universal transcoder, tag v2_50, and the Zstandard decoder it bundles,
compiled unmodified; wheels for CPython 3.10 to 3.14).

The extension's README, "KTX v2 Images with Basis Universal Supercompression": the image
is top-left first (KTXorientation "rd"), the same row order as PNG, so level 0 transcoded
to RGBA8 is what the texture upload takes; pbrlab builds its own mipmaps from it. The
transcoder returns the stored codes, not decoded colour: a base colour stays sRGB-encoded
and the material's slot says how it is read, as for PNG.
"""

from __future__ import annotations

import importlib.util

import numpy as np

EXTENSION = "KHR_texture_basisu"
PACKAGE = "opengl_basisu"
INSTALL = "pip install opengl_basisu==0.1.0a2"
MIME_TYPE = "image/ktx2"
SIGNATURE = b"\xabKTX 20\xbb\r\n\x1a\n"  # KTX 2.0 specification, section 3.1


def available() -> bool:
    return importlib.util.find_spec(PACKAGE) is not None


def decode(data: bytes, fail) -> np.ndarray:
    """KTX2 bytes -> level 0 as top-row-first uint8 (h, w, 3), or (h, w, 4) when the file
    stores alpha. ``fail(message)`` refuses the image."""
    if not available():
        fail(f"is a KTX2 image ({EXTENSION}, Basis Universal), and its transcoder is not "
             f"installed ({INSTALL}, or pip install 'pbrlab[gltf-compressed]')")
    import opengl_basisu

    try:
        texture = opengl_basisu.open(bytes(data))
        if texture.faces != 1 or texture.layers != 1:
            fail(f"is a KTX2 image with {texture.faces} faces and {texture.layers} layers; "
                 f"{EXTENSION} allows one 2D image")
        pixels = np.asarray(texture.transcode(opengl_basisu.Target.RGBA8, level=0).data, np.uint8)
    except opengl_basisu.BasisuError as exc:
        fail(f"is not a KTX2 image with a Basis Universal payload ({EXTENSION}) that the transcoder reads ({exc})")
    return pixels if texture.has_alpha else pixels[..., :3].copy()
