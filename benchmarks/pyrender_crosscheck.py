"""Cross-check against pyrender 0.1.45 (issue 4): render the sphere grid with pyrender and
with pbrlab through EGL and OSMesa, print the agreement figures and write
docs/pyrender_vs_pbrlab.png. A measurement, not a test (tests/checking/test_pyrender_crosscheck.py
asserts the tolerances).

    .venv/bin/python benchmarks/pyrender_crosscheck.py [--size 480x160] [--backends egl,osmesa]
        [--figure docs/pyrender_vs_pbrlab.png]

The figure (from the first backend, pbrlab.checking.pyrender.figure) stacks four titled panels:
pyrender's output | pbrlab composing pyrender's terms (encoded with pyrender's gamma 2.2) |
pbrlab's defaults (high tier, its sRGB output) | relative linear difference pyrender vs pbrlab
default with a colour bar (black 0, red, yellow, white at 50 %; grey: not compared); rows
and columns are labelled (base colour; metallic x roughness).
"""

from __future__ import annotations

import argparse
from pathlib import Path

from pbrlab.checking.pyrender import check as pc
from pbrlab.checking.pyrender import figure as pyrender_figure

ROOT = Path(__file__).resolve().parent.parent


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--size", default="480x160", help="WxH of each panel")
    parser.add_argument("--backends", default="egl,osmesa")
    parser.add_argument("--figure", type=Path, default=ROOT / "docs" / "pyrender_vs_pbrlab.png")
    args = parser.parse_args(argv)
    size = tuple(int(v) for v in args.size.lower().split("x"))
    backends = args.backends.split(",")
    status = 0
    for i, backend in enumerate(backends):
        results = pc.crosscheck(backend, size)
        print(pc.report(results))
        ok, message = pc.TOLERANCE[backend].check(results["pyrender"], results["matched"], results["mask"])
        print(f"  tolerance ({backend}): {'PASS' if ok else 'FAIL'}: {message}")
        status |= 0 if ok else 1
        if i == 0 and args.figure:
            args.figure.parent.mkdir(parents=True, exist_ok=True)
            pyrender_figure.write(args.figure, results)
            print(f"  figure: {args.figure}")
    return status


if __name__ == "__main__":
    raise SystemExit(main())
