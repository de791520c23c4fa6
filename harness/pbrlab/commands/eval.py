"""`pbrlab eval 'EXPR' --var NAME=start:stop:count ...`: a GLSL expression as a table.

Several --var options form a grid (every combination), one row per sample. Values may
also be listed: --var x=0,0.5,1. Vector inputs take --vec3 NAME=r,g,b (a constant).
The table is printed (at most 10,000 rows), or written with -o to a .csv file (the same
columns, comma-separated) or a .npz file (one float64 array per column, named as the
header; the values are the evaluator's float32 results), up to 2^24 rows.
"""

from __future__ import annotations

import argparse

import itertools
import math
from pathlib import Path

import numpy as np

from ..foundation import console, outputs
from ..foundation.errors import PbrlabError

MAX_ROWS = 10000  # printed: a table a person reads
# Written to a file (-o): 2^24 rows, four evaluator draws (evaluator.CHUNK); the grid's inputs
# as float64 and the results take about 0.5 GiB at four columns, under a render's 2 GiB.
MAX_FILE_ROWS = 1 << 24
FILE_FORMATS = (".csv", ".npz")


def _number(text: str) -> float:
    """A float from the command line; a finite literal that overflows (1e400) is refused
    ('inf' and 'nan' spelled out are values the evaluator takes)."""
    value = float(text)
    if math.isinf(value) and "inf" not in text.strip().lower():
        raise PbrlabError(f"{text.strip()} overflows to infinity; write inf if you mean it")
    return value


def _parse_var(text: str):
    name, sep, spec = text.partition("=")
    if not sep or not name:
        raise PbrlabError(f"--var {text!r}: expected NAME=start:stop:count or NAME=v1,v2,...")
    try:
        if ":" in spec:
            start, stop, count = spec.split(":")
            if not 1 <= int(count) <= MAX_FILE_ROWS:
                raise PbrlabError(f"--var {text!r}: count must be 1..{MAX_FILE_ROWS}")
            values = np.linspace(_number(start), _number(stop), int(count))
        else:
            values = np.array([_number(v) for v in spec.split(",")])
    except ValueError:
        raise PbrlabError(f"--var {text!r}: expected NAME=start:stop:count or NAME=v1,v2,...") from None
    if values.size == 0:
        raise PbrlabError(f"--var {text!r}: no values")
    return name.strip(), values


def _parse_vec(text: str, n: int):
    name, sep, spec = text.partition("=")
    try:
        values = [_number(v) for v in spec.split(",")]
    except ValueError:
        values = []
    if not sep or len(values) != n:
        raise PbrlabError(f"--vec{n} {text!r}: expected NAME=" + ",".join("x" * n))
    return name.strip(), np.array(values, np.float64)  # the evaluator checks the float32 range


def _format(value: float) -> str:
    return f"{value:.9g}" if math.isfinite(value) else str(value)


def run(args) -> int:
    from ..gpu import evaluator

    grid = [_parse_var(v) for v in args.var]
    given = [name for name, _ in grid] + [
        spec.partition("=")[0].strip() for specs in (args.vec2, args.vec3, args.vec4) for spec in specs]
    twice = sorted({name for name in given if given.count(name) > 1})
    if twice:
        raise PbrlabError(f"input {twice[0]!r} is given more than once (--var/--vec); give each "
                          "name once (list values with --var NAME=v1,v2,...)")
    if args.output is not None and Path(args.output).suffix.lower() not in FILE_FORMATS:
        raise PbrlabError(f"-o {args.output}: the file must end in {' or '.join(FILE_FORMATS)}")
    rows = math.prod(len(values) for _, values in grid)
    if args.output is None and rows > MAX_ROWS:
        raise PbrlabError(f"the grid has {rows} rows; a printed table is limited to {MAX_ROWS} "
                          f"(write up to {MAX_FILE_ROWS} rows to a file with -o out.csv or out.npz)")
    if rows > MAX_FILE_ROWS:
        raise PbrlabError(f"the grid has {rows} rows, over the limit of {MAX_FILE_ROWS} (eval.MAX_FILE_ROWS)")
    names = [name for name, _ in grid]
    combos = np.array(list(itertools.product(*[values for _, values in grid])), np.float64)
    inputs = {name: combos[:, i] for i, name in enumerate(names)}  # float64: checked by the evaluator
    for n, specs in ((2, args.vec2), (3, args.vec3), (4, args.vec4)):
        for spec in specs:
            name, value = _parse_vec(spec, n)
            inputs[name] = getattr(evaluator, f"vec{n}")(value)
    includes = args.include or None
    include_dirs = [Path(d) for d in args.include_dir]
    for d in include_dirs:
        if not d.is_dir():
            raise PbrlabError(f"-I {d}: no such directory")
    result = evaluator.evaluate(args.expression, includes=includes, include_dirs=include_dirs,
                                backend=args.backend, language=args.language, **inputs)
    result = result.reshape(len(combos), -1) if names else result.reshape(1, -1)
    header = names + [args.expression if result.shape[1] == 1 else f"{args.expression}[{i}]"
                      for i in range(result.shape[1])]
    if args.output is not None:
        _write(Path(args.output), header, combos if names else np.zeros((1, 0)), result)
        console.note(f"wrote {args.output} ({len(result)} rows)")
        return 0
    table = [[_format(v) for v in row] + [_format(float(r)) for r in res]
             for row, res in zip(combos if names else [[]], result)]
    widths = [max(len(h), *(len(r[i]) for r in table)) for i, h in enumerate(header)]
    print("  ".join(h.rjust(w) for h, w in zip(header, widths)))
    for r in table:
        print("  ".join(c.rjust(w) for c, w in zip(r, widths)))
    return 0


def _write(path: Path, header: list, inputs: np.ndarray, result: np.ndarray) -> None:
    """The table as a .csv (header line, then rows) or a .npz (a column per header name),
    written whole or not at all (foundation.outputs)."""
    import io

    columns = np.concatenate([np.asarray(inputs, np.float64), np.asarray(result, np.float64)], axis=1)
    if path.suffix.lower() == ".npz":
        buffer = io.BytesIO()
        np.savez(buffer, **{name: columns[:, i] for i, name in enumerate(header)})
        outputs.write_file(path, buffer.getvalue())
        return
    text = io.StringIO()
    text.write(",".join('"' + h.replace('"', '""') + '"' for h in header) + "\n")
    np.savetxt(text, columns, fmt="%.9g", delimiter=",")
    outputs.write_file(path, text.getvalue())


def register(sub, common):
    p = sub.add_parser("eval", parents=[common], help="Evaluate a GLSL or HLSL expression over a grid of inputs and print a table.",
                       description=__doc__,
                       formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("expression", help="a GLSL (or HLSL) expression, e.g. 'pbr_D_GGX(NdotH, alpha)'")
    p.add_argument("--language", choices=("glsl", "hlsl"), default="glsl",
                   help="evaluate the GLSL library or its HLSL port (HLSL -> SPIR-V -> GLSL)")
    p.add_argument("--include", action="append", default=[],
                   help="an include such as pbr/brdf/d_ggx.glsl (default: the umbrella pbr/pbr.glsl or .hlsl)")
    p.add_argument("-I", "--include-dir", action="append", default=[],
                   help="a directory of your own shader files, searched before the library's (as amalgamate's -I)")
    p.add_argument("--var", action="append", default=[], metavar="NAME=SPEC",
                   help="a float input: start:stop:count or v1,v2,...")
    for n in (2, 3, 4):
        p.add_argument(f"--vec{n}", action="append", default=[], metavar="NAME=" + ",".join("x" * n),
                       help=f"a constant vec{n} input")
    p.add_argument("-o", "--output", default=None, metavar="FILE.csv|FILE.npz",
                   help=f"write the table to a .csv or .npz file instead of printing it (up to {MAX_FILE_ROWS} rows)")
    p.set_defaults(run=run)
