"""A normal map as Unity's editor stores it on desktop, so a Unity program reads its texels as it
would in Unity:

    source = stored_normal_map(path)       # for ContextCache.texture: key + pixels()
    normal_map_property(prop)              # True: [Normal], or the default texture "bump"

Unity imports a texture whose type is Normal map into DXT5nm on desktop: x in alpha, y in green,
red and blue 1, the layout ``(1, y, 1, x)`` UnityCG.cginc's comments name (beside BC5's
``(x, y, 0, 1)``, the high-quality format). Both read the same through Unity's desktop
UnpackNormal (UnpackNormalmapRGorAG: ``x = r * a``, ``y = g``); UnpackNormalDXT5nm reads ``.wy``
and so only the DXT5nm layout, and a program that reads ``.rgb`` sees ``(1, y, 1)``, as in Unity.
pbrlab's programs unpack as that desktop branch (generate.UNITY_LIBRARY_DEFINES), and a file
given for a property pbrlab knows is a normal map is uploaded in the DXT5nm layout: its red and
green channels are the tangent-space x and y, encoded ``* 0.5 + 0.5`` (its blue, the z that
DXT5nm drops, is rebuilt by the unpack).

A property is a normal map where Unity's material inspector treats it as one: the ``[Normal]``
attribute (Unity's manual, "Properties": "indicates that a texture property expects a
normal-map") or the default texture "bump"; or where the shader's own file unpacks it,
``UnpackNormal*(tex2D(_X, ...))`` (or ``UnpackScaleNormal``, ``UNITY_SAMPLE_TEX2D``,
``SAMPLE_TEXTURE2D``), a map its author imported as a normal map for that unpack to read it
(an unpack in an include file is not seen). A default texture is Unity's global one, not an
imported normal map, and binds as its RGBA (properties.DEFAULT_TEXELS).
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ...foundation.errors import PbrlabError
from ...foundation.file_identity import file_key
from ...foundation.images import read_image
from . import model as M


# an unpack of a texture read in its argument: the texture's name
_UNPACKED = re.compile(r"\bUnpack(?:Scale)?Normal\w*\s*\(\s*(?:tex2D\w*|UNITY_SAMPLE_TEX2D\w*|SAMPLE_TEXTURE2D\w*)"
                       r"\s*\(\s*(\w+)")


def normal_map_property(prop: M.Property, unpacked: frozenset = frozenset()) -> bool:
    """Whether ``prop`` is a normal map (module doc); ``unpacked``: unpacked_textures' names."""
    return prop.default == "bump" or "Normal" in prop.attributes or prop.name in unpacked


def unpacked_textures(path) -> frozenset:
    """The textures the shader file at ``path`` hands to an UnpackNormal* read (module doc)."""
    try:
        text = Path(path).read_text(encoding="utf-8", errors="replace")
    except (OSError, TypeError):
        return frozenset()
    return frozenset(_UNPACKED.findall(text))


def dxt5nm_layout(image: np.ndarray, where: str) -> np.ndarray:
    """``(1, y, 1, x)`` of an image whose first two channels hold the map's x and y (uint8 or
    float; 1 is 255 in a uint8 image)."""
    if image.ndim != 3 or image.shape[2] < 2:
        raise PbrlabError(f"{where}: a normal map needs its x and y in the red and green channels; this "
                          "image has one channel (Unity's \"Create from Grayscale\" is an import option "
                          "pbrlab does not run)")
    one = 255 if image.dtype == np.uint8 else 1.0
    out = np.full(image.shape[:2] + (4,), one, image.dtype)
    out[..., 1] = image[..., 1]
    out[..., 3] = image[..., 0]
    return out


@dataclass(frozen=True)
class StoredNormalMap:
    """A normal-map file as the texture cache's in-memory source (``key``, ``pixels()``)."""
    path: Path

    @property
    def key(self) -> tuple:
        return ("unity dxt5nm", *file_key(self.path))

    def pixels(self) -> np.ndarray:
        image = read_image(self.path)
        if image.dtype != np.uint8 and not np.isfinite(image).all():  # as resource_cache's files
            raise PbrlabError(f"texture {self.path}: texels are NaN or Inf; textures must be finite")
        return dxt5nm_layout(image, f"texture {self.path}")


def stored_normal_map(path: Path) -> StoredNormalMap:
    return StoredNormalMap(Path(path))
