"""`pbrlab bench [--family NAME] [--quick] [--out DIR]`: accuracy versus cost of every
variant and quality tier (error against float64, instructions and time per evaluation,
frame cost per tier; AMD GPU instructions and registers from Mesa's RADV/ACO for RDNA3,
RDNA2 and GCN5 on a null device, which needs libvulkan1 and mesa-vulkan-drivers: without
them the report says the GPU columns were not measured). Writes accuracy_cost.md,
accuracy_cost.json and a Pareto plot per family. A benchmark: it asserts nothing about time.
"""

from __future__ import annotations

import argparse


def run(args) -> int:
    import os

    from ..bench import run as run_bench
    if args.backend:  # the measurement workers inherit it
        os.environ["PBRLAB_GL_BACKEND"] = args.backend
    run_bench(args.out, family=args.family, quick=args.quick)
    return 0


def register(sub, common):
    from ..bench.families import BY_NAME
    p = sub.add_parser("bench", parents=[common], help="Measure accuracy against cost for every variant and tier, and write the report.",
                       description=__doc__,
                       formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--family", choices=sorted(BY_NAME), default=None,
                   help="measure one family only (the tier frame cost and image error always run)")
    p.add_argument("--quick", action="store_true",
                   help="few samples and rounds (CI: checks the bench works; figures not for conclusions)")
    p.add_argument("--out", default="out/bench", help="output folder (default: out/bench)")
    p.set_defaults(run=run)
