"""Which image a glTF texture reads: an image-format extension's ``source`` or the core one.

KHR_texture_basisu and EXT_texture_webp define the same rule (their READMEs, "Extending
Textures"): a client that supports the extension reads the extension object's ``source``;
one that does not falls back to the texture's core ``source``, which a file may omit only
when it lists the extension in ``extensionsRequired``. Both are supported when their decoder
is installed (``ktx2.available()``, ``webp.available()``); with both on one texture the
first of PREFERENCE wins (KTX2: the file's own choice of GPU format, usually the smaller).
"""

from __future__ import annotations

from . import ktx2, webp

PREFERENCE = (ktx2, webp)  # image-format extensions, in the order a texture's sources are tried
BY_NAME = {module.EXTENSION: module for module in PREFERENCE}


def texture_source(texture, texture_index: int, warn) -> int:
    """The image index texture ``texture`` (a FieldReader) reads; warns for the extensions
    it does not read, refuses a texture left with no image it can read."""
    present = dict(texture.extensions())
    for name in present:
        if name not in BY_NAME:
            warn(f"{name} ignored in texture {texture_index}")
    core = texture.index("source", "images")
    for module in PREFERENCE:
        spec = present.get(module.EXTENSION)
        if spec is None:
            continue
        if module.available():
            return spec.index("source", "images", required=True)
        if core is not None:
            warn(f"{module.EXTENSION} ignored in texture {texture_index} (its decoder is not installed: "
                 f"{module.INSTALL}; the core source, images[{core}], is drawn)")
    if core is None:
        missing = [m for m in PREFERENCE if m.EXTENSION in present]
        if missing:
            texture.fail(f"has only a {missing[0].EXTENSION} source and no core source, and the decoder is "
                         f"not installed ({missing[0].INSTALL})")
        texture.fail("has no source image")
    return core
