"""`pbrlab eval 'EXPR' --var NAME=start:stop:count ...`: a GLSL expression as a table.

Several --var options form a grid (every combination), one row per sample. Values may
also be listed: --var x=0,0.5,1. Vector inputs take --vec3 NAME=r,g,b (a constant).
"""

from __future__ import annotations

import argparse

import itertools
import math
from pathlib import Path

import numpy as np

from ..foundation.errors import PbrlabError

MAX_ROWS = 10000


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
            if not 1 <= int(count) <= MAX_ROWS:
                raise PbrlabError(f"--var {text!r}: count must be 1..{MAX_ROWS}")
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
    rows = math.prod(len(values) for _, values in grid)
    if rows > MAX_ROWS:
        raise PbrlabError(f"the grid has {rows} rows; a table is limited to {MAX_ROWS}")
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
    table = [[_format(v) for v in row] + [_format(float(r)) for r in res]
             for row, res in zip(combos if names else [[]], result)]
    widths = [max(len(h), *(len(r[i]) for r in table)) for i, h in enumerate(header)]
    print("  ".join(h.rjust(w) for h, w in zip(header, widths)))
    for r in table:
        print("  ".join(c.rjust(w) for c, w in zip(r, widths)))
    return 0


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
    p.set_defaults(run=run)
