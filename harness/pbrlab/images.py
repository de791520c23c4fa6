"""Lossless image I/O through OpenImageIO, and the one atomic-write helper.

Arrays are numpy, top row first, shaped ``(height, width, channels)``:

* PNG holds already-encoded sRGB bytes: ``write_png`` takes uint8 and ``read_image``
  gives uint8 back, byte for byte (no colour conversion on either side).
* EXR holds linear data as 32-bit float ('float', never 'half'), ZIP-compressed, so
  every bit survives: NaN, Inf, denormals and -0 included. ``write_exr`` stores
  ``metadata`` as string attributes under a ``pbrlab:`` prefix, ``read_metadata`` gives
  them back with the prefix removed.

Both writers are deterministic (the EXR ``capDate`` timestamp that OpenEXR would add is
suppressed), so re-writing an unchanged golden leaves the same bytes for git.

Every writer goes through ``atomic_output``: the image is written to a temporary file in
the target's directory and moved over the target only when complete, so a failed write
never leaves a partial file or destroys a good one. Problems a user can fix (a missing or
unwritable directory, a missing or unreadable input) raise ``PbrlabError`` naming the
path; a wrongly shaped array from calling code is a ``ValueError`` (a bug, not a message).
"""

from __future__ import annotations

import contextlib
import os
import secrets
from pathlib import Path
from typing import Iterator

import numpy as np
import OpenImageIO as oiio

from .errors import PbrlabError

METADATA_PREFIX = "pbrlab:"
EXR_COMPRESSION = "zip"  # lossless; 'zip' compresses 16 scanlines per block
# PNG stores colour and alpha independently; without this OpenImageIO would treat the
# array as premultiplied and divide (or, reading, multiply) colour by alpha.
_UNASSOCIATED_ALPHA = "oiio:UnassociatedAlpha"
_CHANNEL_NAMES = {1: ("Y",), 2: ("Y", "A"), 3: ("R", "G", "B"), 4: ("R", "G", "B", "A")}


def _check_writable_target(path: Path) -> None:
    """Raise PbrlabError when ``path`` cannot be written as a file."""
    parent = path.parent
    if not parent.exists():
        raise PbrlabError(f"cannot write {path}: directory {parent} does not exist")
    if not parent.is_dir():
        raise PbrlabError(f"cannot write {path}: {parent} is not a directory")
    if not os.access(parent, os.W_OK | os.X_OK):
        raise PbrlabError(f"cannot write {path}: directory {parent} is not writable")
    if path.is_dir():
        raise PbrlabError(f"cannot write {path}: it is a directory")


@contextlib.contextmanager
def atomic_output(path) -> Iterator[Path]:
    """Yield a temporary path beside ``path``; move it onto ``path`` when the block succeeds.

    The temporary name keeps the target's extension (OpenImageIO picks the format from it).
    If the block raises, the temporary file is removed, the target is left untouched and
    the exception propagates unchanged.
    """
    path = Path(path)
    _check_writable_target(path)
    tmp = path.with_name(f".{path.name}.{os.getpid()}-{secrets.token_hex(4)}.tmp{path.suffix}")
    try:
        yield tmp
        if not tmp.exists():
            raise PbrlabError(f"cannot write {path}: the writer produced no file")
        try:
            os.replace(tmp, path)
        except OSError as exc:
            raise PbrlabError(f"cannot write {path}: {exc.strerror or exc}") from None
    finally:
        with contextlib.suppress(FileNotFoundError):
            tmp.unlink()


def _as_hwc(array: np.ndarray, what: str) -> np.ndarray:
    if array.ndim == 2:
        array = array[:, :, np.newaxis]
    if array.ndim != 3 or array.shape[2] not in _CHANNEL_NAMES or 0 in array.shape:
        raise ValueError(f"{what} must be a non-empty HxWxC array with C in 1..4, got shape {array.shape}")
    return np.ascontiguousarray(array)


def _write(path, pixels: np.ndarray, fmt: str, attributes: dict) -> None:
    """Write ``pixels`` (HxWxC, already in the file's pixel type) atomically to ``path``."""
    height, width, channels = pixels.shape
    spec = oiio.ImageSpec(width, height, channels, fmt)
    spec.channelnames = _CHANNEL_NAMES[channels]
    if channels in (2, 4):
        spec.alpha_channel = channels - 1
    for key, value in attributes.items():
        spec.attribute(key, value)
    with atomic_output(path) as tmp:
        _encode(tmp, spec, pixels, Path(path))


def _encode(tmp: Path, spec, pixels: np.ndarray, target: Path) -> None:
    out = oiio.ImageOutput.create(str(tmp))
    if out is None:
        oiio.geterror()  # clear it: it names the temporary file
        raise PbrlabError(f"cannot write {target}: OpenImageIO has no writer for "
                          f"'{target.suffix or target.name}' files")
    try:
        written = out.open(str(tmp), spec) and out.write_image(pixels)
        error = "" if written else out.geterror()
    finally:
        closed = out.close()  # flushes; runs before an exception from the block propagates
    if not (written and closed):
        error = (error or out.geterror() or "write failed").replace(str(tmp), str(target))
        raise PbrlabError(f"cannot write {target}: {error}")


def write_png(path, rgba8: np.ndarray) -> None:
    """Write already-encoded sRGB bytes (uint8, HxWx{1,2,3,4}) as a lossless PNG."""
    rgba8 = np.asarray(rgba8)
    if rgba8.dtype != np.uint8:
        raise ValueError(f"write_png takes uint8 sRGB code values, got {rgba8.dtype}")
    _write(path, _as_hwc(rgba8, "PNG image"), "uint8", {_UNASSOCIATED_ALPHA: 1})


def write_exr(path, linear: np.ndarray, metadata: dict | None = None) -> None:
    """Write linear float data (HxWx{1,2,3,4}) as a 32-bit float, ZIP-compressed EXR.

    ``metadata`` values are stored as strings (``str(value)``) under ``pbrlab:KEY``.
    """
    linear = np.asarray(linear)
    if linear.dtype != np.float32:
        raise ValueError(f"write_exr takes float32 linear values, got {linear.dtype}")
    attributes = {"compression": EXR_COMPRESSION, "DateTime": ""}  # "" = no capDate
    for key, value in (metadata or {}).items():
        attributes[METADATA_PREFIX + str(key)] = value if isinstance(value, str) else str(value)
    _write(path, _as_hwc(linear, "EXR image"), "float", attributes)


def _open(path) -> "oiio.ImageInput":
    path = Path(path)
    if not path.exists():
        raise PbrlabError(f"cannot read {path}: no such file")
    if path.is_dir():
        raise PbrlabError(f"cannot read {path}: it is a directory")
    config = oiio.ImageSpec()
    config.attribute(_UNASSOCIATED_ALPHA, 1)  # give PNG bytes back as stored
    inp = oiio.ImageInput.open(str(path), config)
    if inp is None:
        raise PbrlabError(f"cannot read {path}: {oiio.geterror() or 'not an image OpenImageIO can read'}")
    return inp


def read_image(path) -> np.ndarray:
    """Read an image: uint8 for 8-bit files (PNG), float32 for float or half files (EXR)."""
    inp = _open(path)
    try:
        spec = inp.spec()
        basetype = spec.format.basetype
        if basetype == oiio.UINT8:
            dtype = "uint8"
        elif basetype in (oiio.HALF, oiio.FLOAT):
            dtype = "float"
        else:
            raise PbrlabError(
                f"cannot read {path}: pixels are {spec.format}; pbrlab reads 8-bit images "
                "(PNG, sRGB code values) and half or float images (EXR, linear)")
        pixels = inp.read_image(0, 0, 0, spec.nchannels, dtype)
        if pixels is None:
            raise PbrlabError(f"cannot read {path}: {inp.geterror()}")
    finally:
        inp.close()
    pixels = np.asarray(pixels)
    if pixels.ndim == 2:
        pixels = pixels[:, :, np.newaxis]
    return pixels.astype(np.uint8 if dtype == "uint8" else np.float32, copy=False)


def read_metadata(path) -> dict:
    """The ``pbrlab:`` string attributes of an image written by ``write_exr`` (prefix removed)."""
    inp = _open(path)
    try:
        attribs = inp.spec().extra_attribs
        return {a.name[len(METADATA_PREFIX):]: a.value
                for a in attribs if a.name.startswith(METADATA_PREFIX)}
    finally:
        inp.close()
