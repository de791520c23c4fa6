"""`pbrlab amalgamate ENTRY -o single.glsl`: inline every include into one file.

With --strip-comments the file keeps no comment but the licence notice, which it opens with
(pbrlab.gpu.glsl_comments): the same program in a third of the text.
"""

from __future__ import annotations

import argparse

from pathlib import Path

from ..foundation import console, outputs
from ..gpu import glsl_comments, shaders
from ..foundation.errors import PbrlabError


def run(args) -> int:
    from ..foundation import safe_paths

    # The entry and -I folders are the user's own, named on the command line: includes follow
    # links anywhere (the folder rule is for the files a model names: docs/faults.md).
    with safe_paths.allowing_outside():
        return _amalgamate(args)


def _amalgamate(args) -> int:
    entry = Path(args.entry)
    if not entry.is_file():
        candidate = shaders.resolve_include(args.entry, shaders.include_path(args.include_dir))
        if candidate is None:
            raise PbrlabError(f"{args.entry}: no such file (also searched the include path)")
        entry = candidate
    source = shaders.expand_file(entry, args.include_dir, line_directives=False)
    text = glsl_comments.strip_comments(source.text) if args.strip_comments else source.text
    if args.output == "-":
        print(text, end="")
        return 0
    inputs = [(path, "a file it amalgamates") for path in source.paths]
    with outputs.transaction([args.output], inputs) as tx:
        tx.write_text(args.output, text)
    console.note(f"wrote {args.output} ({len(text.splitlines())} lines)")
    return 0


def register(sub, common):
    p = sub.add_parser("amalgamate", parents=[common], help="Write one self-contained GLSL file with every include inlined.",
                       description=__doc__,
                       formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("entry", help="a GLSL file, or an include name such as pbr/pbr.glsl")
    p.add_argument("-o", "--output", default="-", help="output file (default: stdout)")
    p.add_argument("-I", "--include-dir", action="append", default=[],
                   help="another include directory, searched before glsl/")
    p.add_argument("--strip-comments", action="store_true",
                   help="leave out every comment but the licence notice (the same program, shorter)")
    p.set_defaults(run=run)
