"""`pbrlab schema`: print the JSON Schema (draft 2020-12) of scene files.

Point an editor at it to validate and complete scenes, e.g. in VS Code's settings:
``"json.schemas": [{"fileMatch": ["scenes/*.json"], "url": "./scene.schema.json"}]`` after
``pbrlab schema -o scene.schema.json``. It is written from the parser's own field tables
(pbrlab.scene.fields); `pbrlab render` remains the full check (files exist, materials are
defined, ...), and its messages name the field.
"""

from __future__ import annotations

import argparse
import json

from ..foundation import console, output_targets, outputs


def run(args) -> int:
    from ..scene.schema import scene_schema

    text = json.dumps(scene_schema(), indent=2) + "\n"
    if args.output == "-":
        print(text, end="")
        return 0
    with outputs.transaction([args.output], []) as tx:
        tx.write_text(args.output, text)
    if not output_targets.names_a_stream(args.output):  # -o /dev/stdout: the schema alone
        console.note(f"wrote {args.output}")
    return 0


def register(sub, common):
    p = sub.add_parser("schema", parents=[common], help="Print the JSON Schema of scene files.",
                       description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("-o", "--output", default="-", help="output file (default: stdout)")
    p.set_defaults(run=run)
