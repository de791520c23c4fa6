"""`pbrlab hardcases [--json]`: run the hard-case catalogue through the GPU evaluator.

Prints one row per case: function (and variant), case, value, expected bound (and the
decided value where the maths has none), status. Exit 0 when every case holds, 1 otherwise.
"""

from __future__ import annotations

import argparse

import json
import math

from ..foundation.errors import PbrlabError


def _json_value(x):
    x = [float(v) for v in (x if hasattr(x, "__len__") else [x])]
    return [v if math.isfinite(v) else str(v) for v in x]  # JSON has no NaN/Inf


def run(args) -> int:
    from ..checking.hardcases import catalogue, run as hardcases_run

    cases = catalogue.catalogue()
    if args.function:
        known = sorted({c.function.name for c in cases})
        unknown = [name for name in args.function if name not in known]
        if unknown:
            raise PbrlabError(f"--function {unknown[0]}: no hard case covers it; the catalogue "
                              f"covers {', '.join(known)}")
        cases = [c for c in cases if c.function.name in args.function]
    from functools import partial

    from ..gpu import evaluator

    results = hardcases_run.run_catalogue(cases, evaluate=partial(evaluator.evaluate, backend=args.backend))
    failures = [r for r in results if not r.ok]
    shown = failures if args.failures_only else results
    if args.json:
        print(json.dumps([{
            "function": r.case.function.name, "variant": r.case.function.variant, "case": r.case.name,
            "why": r.case.why, "value": _json_value(r.value), "bound": r.case.function.bound.text,
            "decided": None if r.expected is None else _json_value(r.expected), "status": r.status,
        } for r in shown], indent=1, ensure_ascii=False))
    else:
        rows = [(r.case.function.label, r.case.name, r.value_text(), r.expected_text(), r.status) for r in shown]
        header = ("function", "case", "value", "expected", "status")
        widths = [max([len(h)] + [len(row[i]) for row in rows]) for i, h in enumerate(header)]
        for row in [header] + rows:
            print("  ".join(cell.ljust(w) for cell, w in zip(row, widths)).rstrip())
        print(f"{len(results)} cases, {len(failures)} failed")
    return 1 if failures else 0


def register(sub, common):
    p = sub.add_parser("hardcases", parents=[common], help="Run the hard-case catalogue on the GPU; exit 1 when a case fails.",
                       description=__doc__,
                       formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--json", action="store_true", help="print the results as JSON")
    p.add_argument("--function", action="append", default=[], metavar="NAME",
                   help="only this GLSL function (repeatable), e.g. pbr_D_GGX")
    p.add_argument("--failures-only", action="store_true", help="print only the failing cases")
    p.set_defaults(run=run)
