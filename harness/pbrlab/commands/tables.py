"""`pbrlab tables --out DIR`: write the library's lookup tables as image files an engine loads.

DIR/pbrlab_dfg.exr and .png: the split-sum DFG table (R = A, the F0 weight; G = B, the F90
weight), 256 x 256; DIR/pbrlab_sheen_albedo.exr and .png: the sheen lobe's directional
albedo E, 128 x 128. EXR: float32, the library's values exactly; PNG: 16-bit, value = code /
65535 (the sheen's x 4). Sample them at the library's own coordinates (pbr_dfg_lut_uv,
pbr_sheen_lut_uv), bilinear, clamped to the edge, with the image's bottom row at v = 0
(Direct3D and Vulkan: 1 - v). DIR/pbrlab_tables.glsl and .hlsl: a header that samples them
so, for an engine without the library. The docs' "Engine-ready tables" page has the details.
"""

from __future__ import annotations

import argparse
import shutil
from pathlib import Path

from ..foundation.errors import PbrlabError
from ..foundation.locations import engine_snippets

# The sampling header, copied beside the tables (the wheel ships it: setup.py's DATA_TREES).
SNIPPETS = ("pbrlab_tables.glsl", "pbrlab_tables.hlsl")


def run(args) -> int:
    from ..foundation import console
    from ..gpu.engine_tables import write_tables

    out = Path(args.out)
    try:
        out.mkdir(parents=True, exist_ok=True)
    except FileExistsError:
        raise PbrlabError(f"--out {out}: exists and is not a directory") from None
    except OSError as exc:
        raise PbrlabError(f"--out {out}: cannot create the folder: {exc.strerror or exc}") from None
    for path in write_tables(out):
        console.note(f"wrote {path}")
    for name in SNIPPETS:
        shutil.copyfile(engine_snippets() / name, out / name)
        console.note(f"wrote {out / name}")
    return 0


def register(sub, common):
    p = sub.add_parser("tables", parents=[common], help="Write the DFG and sheen albedo tables as EXR and 16-bit PNG.",
                       description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--out", required=True, help="output folder")
    p.set_defaults(run=run)
