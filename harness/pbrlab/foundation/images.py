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

Every writer goes through ``outputs.transaction``: the image is written to a temporary
file in the target's directory, fsync'ed, read back and compared pixel for pixel, and
moved over the target only then, so a failed write (a full disk included) never leaves a
partial file or destroys a good one. Pass ``tx`` to make several files one
all-or-nothing set (``pbrlab render -o a.png --hdr a.exr``). Problems a user can fix (a missing or
unwritable directory, a missing or unreadable input) raise ``PbrlabError`` naming the
path; a wrongly shaped array from calling code is a ``ValueError`` (a bug, not a message).
"""

from __future__ import annotations

import contextlib
from pathlib import Path
from typing import Iterator

import numpy as np
import OpenImageIO as oiio

from . import outputs
from .errors import PbrlabError

METADATA_PREFIX = "pbrlab:"
EXR_COMPRESSION = "zip"  # lossless; 'zip' compresses 16 scanlines per block
# PNG stores colour and alpha independently; without this OpenImageIO would treat the
# array as premultiplied and divide (or, reading, multiply) colour by alpha.
_UNASSOCIATED_ALPHA = "oiio:UnassociatedAlpha"
_CHANNEL_NAMES = {1: ("Y",), 2: ("Y", "A"), 3: ("R", "G", "B"), 4: ("R", "G", "B", "A")}


@contextlib.contextmanager
def atomic_output(path, inputs=()) -> Iterator[Path]:
    """Yield a temporary path beside ``path``; move it onto ``path`` when the block succeeds.

    A one-file ``outputs.transaction``: the temporary name keeps the target's extension
    (OpenImageIO picks the format from it), the file is fsync'ed and must be non-empty
    before the rename. If the block raises, the temporary file is removed, the target is
    left untouched and the exception propagates unchanged.
    """
    path = Path(path)
    with outputs.transaction([path], inputs) as tx:
        yield tx.temp(path)


def _as_hwc(array: np.ndarray, what: str) -> np.ndarray:
    if array.ndim == 2:
        array = array[:, :, np.newaxis]
    if array.ndim != 3 or array.shape[2] not in _CHANNEL_NAMES or 0 in array.shape:
        raise ValueError(f"{what} must be a non-empty HxWxC array with C in 1..4, got shape {array.shape}")
    return np.ascontiguousarray(array)


def _write(path, pixels: np.ndarray, fmt: str, attributes: dict, tx=None) -> None:
    """Write ``pixels`` (HxWxC, already in the file's pixel type) atomically to ``path``,
    read it back and compare before the rename; with ``tx`` (an outputs.Transaction
    holding ``path``) the file becomes part of that all-or-nothing set."""
    height, width, channels = pixels.shape
    spec = oiio.ImageSpec(width, height, channels, fmt)
    spec.channelnames = _CHANNEL_NAMES[channels]
    if channels in (2, 4):
        spec.alpha_channel = channels - 1
    for key, value in attributes.items():
        spec.attribute(key, value)
    if tx is None:
        with outputs.transaction([path]) as own:
            _write(path, pixels, fmt, attributes, own)
        return
    target = Path(path)
    try:
        _encode(tx.temp(target), spec, pixels, target)
    except OSError as exc:  # the device refused a write (ENOSPC, EIO) inside the encoder
        raise PbrlabError(f"cannot write {target}: {exc.strerror or exc}") from None
    tx.verify(target, lambda tmp: _verify_readback(tmp, pixels, target))


def _verify_readback(tmp: Path, pixels: np.ndarray, target: Path) -> None:
    """The file on disk decodes to exactly ``pixels`` (bit for bit: NaN, -0 included) and,
    for PNG, ends with its IEND trailer."""
    if tmp.suffix.lower() == ".png":
        outputs.check_png_complete(tmp, target)
    try:
        back = read_image(tmp)
    except PbrlabError as exc:
        detail = str(exc).replace(f"cannot read {tmp}: ", "").splitlines()[0]
        raise PbrlabError(f"cannot write {target}: the file written does not read back, the "
                          f"disk may be full ({detail}); the old file is kept") from None
    if back.shape != pixels.shape or back.view(np.uint8).tobytes() != pixels.view(np.uint8).tobytes():
        raise PbrlabError(f"cannot write {target}: the file written reads back different pixels "
                          "(a full disk or a failing device?); the old file is kept")


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


def write_png(path, rgba8: np.ndarray, tx=None) -> None:
    """Write already-encoded sRGB bytes (uint8, HxWx{1,2,3,4}) as a lossless PNG
    (``tx``: an outputs.Transaction that holds ``path``)."""
    rgba8 = np.asarray(rgba8)
    if rgba8.dtype != np.uint8:
        raise ValueError(f"write_png takes uint8 sRGB code values, got {rgba8.dtype}")
    _write(path, _as_hwc(rgba8, "PNG image"), "uint8", {_UNASSOCIATED_ALPHA: 1}, tx)


def write_exr(path, linear: np.ndarray, metadata: dict | None = None, tx=None) -> None:
    """Write linear float data (HxWx{1,2,3,4}) as a 32-bit float, ZIP-compressed EXR.

    ``metadata`` values are stored as strings (``str(value)``) under ``pbrlab:KEY``.
    """
    linear = np.asarray(linear)
    if linear.dtype != np.float32:
        raise ValueError(f"write_exr takes float32 linear values, got {linear.dtype}")
    attributes = {"compression": EXR_COMPRESSION, "DateTime": ""}  # "" = no capDate
    for key, value in (metadata or {}).items():
        attributes[METADATA_PREFIX + str(key)] = value if isinstance(value, str) else str(value)
    _write(path, _as_hwc(linear, "EXR image"), "float", attributes, tx)


# The first bytes of each format pbrlab reads, by file extension: a file whose content
# does not match its name is refused (PNG bytes named sky.exr once rendered 150x too
# bright). Sources: PNG spec section 5.2; OpenEXR "Technical Introduction", magic
# 20000630 little-endian; Radiance RGBE header ("#?RADIANCE", "#?RGBE"); JPEG SOI marker.
MAGIC = {
    ".png": (b"\x89PNG\r\n\x1a\n",),
    ".exr": (b"\x76\x2f\x31\x01",),
    ".hdr": (b"#?RADIANCE", b"#?RGBE"),
    ".jpg": (b"\xff\xd8\xff",),
    ".jpeg": (b"\xff\xd8\xff",),
}
_FORMAT_NAMES = {".png": "PNG", ".exr": "OpenEXR", ".hdr": "Radiance HDR", ".jpg": "JPEG", ".jpeg": "JPEG"}


def sniff_format(head: bytes) -> str | None:
    """The extension whose magic bytes ``head`` starts with (None: none of ours)."""
    for suffix, magics in MAGIC.items():
        if any(head.startswith(m) for m in magics):
            return suffix
    return None


def _check_readable_image_file(path: Path) -> None:
    """Refuse a missing, unreadable or misnamed image file before OpenImageIO sees it."""
    try:
        with open(path, "rb") as f:
            head = f.read(16)
    except IsADirectoryError:
        raise PbrlabError(f"cannot read {path}: it is a directory") from None
    except FileNotFoundError:
        raise PbrlabError(f"cannot read {path}: no such file") from None
    except OSError as exc:  # permission, symlink loop, I/O error
        raise PbrlabError(f"cannot read {path}: {exc.strerror or exc}") from None
    suffix = path.suffix.lower()
    if suffix in MAGIC and not any(head.startswith(m) for m in MAGIC[suffix]):
        found = sniff_format(head)
        what = f"{_FORMAT_NAMES[found]} data" if found else "not a valid file of that kind"
        raise PbrlabError(f"cannot read {path}: named {suffix} but its content is {what}"
                          + (f"; rename it to {path.stem}{found}" if found else ""))


def _open(path) -> "oiio.ImageInput":
    path = Path(path)
    _check_readable_image_file(path)
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
