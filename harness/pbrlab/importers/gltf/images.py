"""glTF images decoded to what the texture upload takes: top-row-first uint8 RGB or RGBA.

* 8-bit PNG and JPEG through Pillow; grey images as RGB (a slot reads R, G or B, spec 3.8.3).
* A PNG's tRNS chunk (transparency of a palette entry, or of one grey or RGB colour) becomes
  the alpha channel (Pillow's P, L and RGB modes ignore it unless asked for RGBA).
* 16-bit PNGs through OpenImageIO: Pillow clips 16-bit grey to white (its convert takes the
  numbers as 8-bit) and truncates 16-bit RGB to the high byte; the 16-bit value v becomes the
  nearest 8-bit code, round(v * 255 / 65535), the precision the texture upload keeps.
* KTX2 with Basis Universal (KHR_texture_basisu, mimeType image/ktx2) through gltf.ktx2's
  transcoder; WebP (EXT_texture_webp) through Pillow (gltf.webp). Each is recognised by its
  bytes' signature, whatever the mimeType says (AnisotropyBarnLamp's KTX2 variant gives none);
  a texture whose core source is such an image is drawn with a warning (not valid glTF:
  extension_of_bytes, gltf.materials), as viewers that follow the rule do not draw it.
"""

from __future__ import annotations

import io
import os
import tempfile

import numpy as np

from . import ktx2, webp

PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"
KTX2_SIGNATURE = ktx2.SIGNATURE
# The core specification's two types and the two an image-format extension adds.
MIME_TYPES = ("image/jpeg", "image/png", ktx2.MIME_TYPE, webp.MIME_TYPE)


FORMAT_NAMES = {ktx2.EXTENSION: "KTX2", webp.EXTENSION: "WebP"}


def extension_of_bytes(data: bytes) -> str | None:
    """The image-format extension that must name these bytes (KTX2, WebP), None for PNG and
    JPEG, the core's: a texture's core source may only be those (glTF 2.0, 5.18 images)."""
    if data.startswith(KTX2_SIGNATURE):
        return ktx2.EXTENSION
    return webp.EXTENSION if webp.is_webp(data) else None


def check_mime_type(spec) -> None:
    """images[i].mimeType: PNG, JPEG, KTX2 or WebP."""
    if spec.has("mimeType"):
        spec.enum("mimeType", MIME_TYPES)


def _file_named(spec) -> str:
    """"<uri> " for an image in a file of its own, else "" (the message names images[i])."""
    uri = spec.data.get("uri")
    return f"{uri} " if isinstance(uri, str) and uri and not uri.startswith("data:") else ""


def decode_image(doc, data: bytes, spec) -> np.ndarray:
    """PNG, JPEG, WebP or KTX2 bytes of image ``spec`` -> top-row-first uint8 (h, w, 3 or 4)."""
    from PIL import Image, UnidentifiedImageError

    where = spec.path
    if data.startswith(KTX2_SIGNATURE):
        return ktx2.decode(data, lambda message: doc.fail(where, _file_named(spec) + message))
    if webp.is_webp(data) and not webp.available():
        doc.fail(where, f"is a WebP image ({webp.EXTENSION}), and Pillow here cannot read WebP ({webp.INSTALL})")
    if data.startswith(PNG_SIGNATURE) and len(data) > 25 and data[12:16] == b"IHDR" and data[24] == 16:
        return _decode_png16(doc, data, where)
    try:
        with Image.open(io.BytesIO(data)) as image:
            if image.format not in ("PNG", "JPEG", "WEBP"):
                doc.fail(where, f"is {image.format}; glTF images are PNG or JPEG (or WebP, KTX2 by extension)")
            alpha = "A" in image.getbands() or "transparency" in image.info
            image = image.convert("RGBA" if alpha else "RGB")
            return np.asarray(image, np.uint8)
    except UnidentifiedImageError:
        doc.fail(where, f"is not a readable PNG, JPEG or WebP image (it starts with bytes {data[:8].hex(' ')})")
    except (Image.DecompressionBombError, OSError, ValueError) as exc:
        doc.fail(where, f"is not a readable PNG, JPEG or WebP image ({exc})")


def _decode_png16(doc, data: bytes, where: str) -> np.ndarray:
    """A 16-bit PNG through OpenImageIO (it reads files: a temporary one), to 8-bit codes."""
    import OpenImageIO as oiio

    handle, name = tempfile.mkstemp(suffix=".png")
    try:
        with os.fdopen(handle, "wb") as f:
            f.write(data)
        config = oiio.ImageSpec()
        config.attribute("oiio:UnassociatedAlpha", 1)  # the colour as stored, not premultiplied
        inp = oiio.ImageInput.open(name, config)
        if inp is None:
            doc.fail(where, f"is not a readable 16-bit PNG image ({oiio.geterror().replace(name, 'the image')})")
        try:
            channels = inp.spec().nchannels
            pixels = inp.read_image(0, 0, 0, channels, "uint16")
            error = inp.geterror() if pixels is None else ""
        finally:
            inp.close()
    finally:
        os.unlink(name)
    if pixels is None:
        doc.fail(where, f"is not a readable 16-bit PNG image ({error.replace(name, 'the image')})")
    pixels = np.asarray(pixels, np.uint32).reshape(pixels.shape[0], pixels.shape[1], -1)
    codes = ((pixels * 255 + 32767) // 65535).astype(np.uint8)  # round(v * 255 / 65535)
    if codes.shape[2] in (1, 2):  # grey (and alpha) as RGB(A)
        codes = np.concatenate([codes[..., :1]] * 3 + [codes[..., 1:]], axis=2)
    return codes
