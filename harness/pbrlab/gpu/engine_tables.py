"""The library's lookup tables as image files an engine loads: the DFG tables (split-sum
environment BRDF, pbrlab.gpu.ibl: the warped layout HIGH and MEDIUM read, and the LOW tier's
square-root layout, PBR_DFG_LUT_LAYOUT) and the sheen albedo table (pbrlab.gpu.sheen_table), each as a
float32 EXR (the exact values) and a 16-bit PNG (for loaders without EXR). `pbrlab tables
--out DIR` writes them; docs/tables.md gives their orientation, encoding and lookup, and
examples/engine/pbrlab_tables.glsl (.hlsl; `pbrlab tables` copies them beside the tables)
samples them as the library does.

Orientation: image order, the first (top) row is the last row of the table (roughness 1),
so a loader that puts the image's bottom row at texture coordinate v = 0 (OpenGL's
glTexImage2D after the usual vertical flip, three.js's default flipY) samples the table
at the library's coordinates (pbr_dfg_lut_uv, pbr_sheen_lut_uv) unchanged; Direct3D and
Vulkan (v = 0 at the top row) sample at (u, 1 - v).

Encoding: EXR float32, linear; PNG 16-bit, value = round(table / scale * 65535), with scale
1 for the DFG table (A, B in [0, 1]) and 4 for the sheen albedo (E reaches 2.94 at grazing
views of the smoothest sheen: KHR's fitted visibility masks too little there).
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Callable

import numpy as np

PNG_MAX = 65535  # a 16-bit PNG's largest code


@dataclass(frozen=True)
class Table:
    name: str                   # the files' stem: NAME.exr, NAME.png
    load: Callable              # the library's table, image order, float32
    channels: str               # what R, G (B) hold
    png_scale: float            # table value = PNG code / 65535 * png_scale
    glsl_uv: str                # the library's texture-coordinate function


def _dfg(layout="WARPED"):
    from .ibl import dfg_lut
    table = dfg_lut(layout)
    return np.concatenate([table, np.zeros_like(table[..., :1])], axis=-1)  # RGB: A, B, 0


def _dfg_sqrt():
    return _dfg("SQRT")


def _sheen():
    from .sheen_table import sheen_lut
    return sheen_lut()[..., None]


TABLES = (
    Table("pbrlab_dfg", _dfg, "R = A (the F0 weight), G = B (the F90 weight), B = 0", 1.0, "pbr_dfg_lut_uv"),
    # the LOW tier's (PBR_DFG_LUT_LAYOUT_SQRT: x = sqrt(NdotV), y = perceptual roughness)
    Table("pbrlab_dfg_sqrt", _dfg_sqrt, "R = A (the F0 weight), G = B (the F90 weight), B = 0", 1.0,
          "pbr_dfg_lut_uv"),
    Table("pbrlab_sheen_albedo", _sheen, "R (grey) = E, the white sheen lobe's directional albedo", 4.0,
          "pbr_sheen_lut_uv"),
)


def png_codes(table: Table) -> np.ndarray:
    """The table as 16-bit PNG codes (uint16, image order)."""
    values = table.load().astype(np.float64) / table.png_scale
    if values.min() < 0.0 or values.max() > 1.0:
        raise ValueError(f"{table.name}: values beyond the PNG's range at scale {table.png_scale}")
    return np.round(values * PNG_MAX).astype(np.uint16)


def decode_png(codes: np.ndarray, table: Table) -> np.ndarray:
    """What an engine reads back from the PNG: the codes as table values (float64)."""
    return codes.astype(np.float64) / PNG_MAX * table.png_scale


def write_png16(path: Path, codes: np.ndarray, tx) -> None:
    """A 16-bit PNG of ``codes`` (HxWxC uint16), as part of the transaction ``tx``."""
    import OpenImageIO as oiio

    height, width, channels = codes.shape
    spec = oiio.ImageSpec(width, height, channels, "uint16")
    spec.channelnames = ("R", "G", "B")[:channels] if channels == 3 else ("Y",)
    with tx.writing(path) as tmp:
        out = oiio.ImageOutput.create(str(tmp))
        if out is None or not (out.open(str(tmp), spec) and out.write_image(np.ascontiguousarray(codes))):
            raise OSError(f"cannot write {path}: {oiio.geterror()}")
        out.close()


def read_png16(path: Path) -> np.ndarray:
    """A 16-bit PNG's codes (HxWxC uint16)."""
    import OpenImageIO as oiio

    inp = oiio.ImageInput.open(str(path))
    if inp is None:
        raise OSError(f"cannot read {path}: {oiio.geterror()}")
    try:
        spec = inp.spec()
        pixels = np.asarray(inp.read_image(0, 0, 0, spec.nchannels, "uint16"))
    finally:
        inp.close()
    return pixels.reshape(spec.height, spec.width, spec.nchannels)


def write_tables(out: Path) -> list[Path]:
    """Every table as OUT/NAME.exr and OUT/NAME.png, all or nothing."""
    from ..foundation import images, outputs

    paths = [out / f"{t.name}{suffix}" for t in TABLES for suffix in (".exr", ".png")]
    with outputs.transaction(paths) as tx:
        for table in TABLES:
            images.write_exr(out / f"{table.name}.exr", table.load(), tx=tx,
                             metadata={"table": table.channels, "lookup": table.glsl_uv})
            write_png16(out / f"{table.name}.png", png_codes(table), tx)
    return paths
