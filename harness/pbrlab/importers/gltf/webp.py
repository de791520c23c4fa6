"""EXT_texture_webp: WebP images (lossy or lossless, with or without alpha) decoded by
Pillow, whose wheels bundle libwebp. The extension's README: the image's ``mimeType`` is
``image/webp``; decoded like PNG and JPEG to top-row-first 8-bit codes."""

from __future__ import annotations

EXTENSION = "EXT_texture_webp"
MIME_TYPE = "image/webp"
INSTALL = "a Pillow built with WebP (pip install Pillow: its wheels include libwebp)"


def available() -> bool:
    from PIL import features
    return bool(features.check("webp"))


def is_webp(data: bytes) -> bool:
    """The RIFF container's signature with the WEBP form type (RFC 9649, section 2.5)."""
    return len(data) >= 12 and data[:4] == b"RIFF" and data[8:12] == b"WEBP"
