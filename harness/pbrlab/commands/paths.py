"""`pbrlab paths`: print where pbrlab finds its shader library, HLSL twins and example scenes.

One line per folder: its name, its path and how it was found (an environment variable, the
package data of an installed wheel, or the checkout). Point an engine's include path, or
`pbrlab render`, at these folders.
"""

from __future__ import annotations

import argparse

from ..foundation.errors import PbrlabError
from ..foundation.locations import TREES, locate, origin


def lines() -> list[str]:
    """``name: path (how it was found)`` for each folder, or why it is missing."""
    out = []
    for tree in TREES:
        try:
            out.append(f"{tree}: {locate(tree)} ({origin(tree)})")
        except PbrlabError as exc:
            out.append(f"{tree}: missing: {exc}")
    return out


def run(args) -> int:
    for line in lines():
        print(line)
    return 0


def register(sub, common):
    p = sub.add_parser("paths", parents=[common], help="Print where the shader library, its HLSL twins and the example scenes are.",
                       description=__doc__,
                       formatter_class=argparse.RawDescriptionHelpFormatter)
    p.set_defaults(run=run)
