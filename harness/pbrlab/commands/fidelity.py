"""`pbrlab fidelity [--scenarios FILE] [--scene KEY ...] [--render R ...] [--update-references] [--out DIR]`:
the glTF Render Fidelity benchmark (docs/fidelity.md). Every scene of
benchmarks/fidelity/scenarios.json (or --scenarios FILE, whose references lie beside it in a
folder named for it: heldout_scenarios.json -> heldout_references) under each of its lightings is rendered by pbrlab and
scored with the protocol's metric (dB, lower is closer; -22 dB its pass line) against Cycles,
beside three.js and the Khronos Sample Viewer. The references are committed at a quarter of
the protocol's size; --render cycles threejs sample_viewer cycles_seed1 makes them anew
(Cycles needs a Python with PyPI's bpy: PBRLAB_BPY_PYTHON). Writes OUT/results.json,
OUT/results.md and per scene OUT/<scene>/{<renderer>.exr,.png, side_by_side.png}.
Exit 1 when pbrlab is worse than its bound on a scene (the worst peer, widened by the
reference's noise).
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path


def run(args) -> int:
    import os

    from ..checking.fidelity import benchmark, staging
    from ..foundation import console, outputs
    from ..foundation.errors import PbrlabError

    if args.backend:
        os.environ["PBRLAB_GL_BACKEND"] = args.backend

    render = tuple(dict.fromkeys(["pbrlab", *args.render]))
    scenarios_file = Path(args.scenarios) if args.scenarios else staging.SCENARIOS_FILE
    scenarios = staging.read_scenarios(scenarios_file)  # its errors name the file
    references = benchmark.references_for(scenarios_file)
    if not args.update_references and not references.is_dir():
        raise PbrlabError(f"{scenarios_file}: no references folder {references} (render them: --render cycles "
                          "cycles_seed1 threejs sample_viewer --update-references)")
    rows = benchmark.run(scenarios, keys=args.scene or None, scale=args.scale,
                         render=render, references=references,
                         update_references=args.update_references, out=Path(args.out).resolve(),
                         render_block={**benchmark.PBRLAB_RENDER, "antialias": args.antialias},
                         samples=args.samples, log=console.note)
    summary = benchmark.summary(rows)
    failures = [r.key for r in rows if r.bound_db() is not None and r.scores.get("pbrlab", -1e9) > r.bound_db()]
    results = {"summary": summary, "over_bound": failures,
               "rows": [{"key": r.key, "size": list(r.size), "scores_db": r.scores, "noise_db": r.noise_db,
                         "bound_db": r.bound_db(), "seconds": r.seconds} for r in rows]}
    out = Path(args.out)
    outputs.write_file(out / "results.json", (json.dumps(results, indent=1) + "\n").encode())
    outputs.write_file(out / "results.md", (benchmark.table(rows) + "\n" + json.dumps(summary, indent=1) + "\n").encode())
    print(benchmark.table(rows))
    print(json.dumps(summary, indent=1))
    if failures:
        print(f"pbrlab is over its bound on {len(failures)} scene(s): {', '.join(failures)}")
    return 1 if failures else 0


def register(sub, common):
    p = sub.add_parser("fidelity", parents=[common],
                       help="Score pbrlab against a path tracer (Cycles) on the glTF Render Fidelity protocol, "
                            "beside three.js and the Sample Viewer.",
                       description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--scenarios", metavar="FILE",
                   help="a scenarios file (default: benchmarks/fidelity/scenarios.json); its references are the "
                        "folder beside it named for it (heldout_scenarios.json: heldout_references)")
    p.add_argument("--scene", action="append", metavar="KEY",
                   help="one scene@lighting (repeatable; default: all)")
    p.add_argument("--render", nargs="+", default=[], metavar="RENDERER",
                   choices=["cycles", "cycles_seed1", "threejs", "sample_viewer"],
                   help="also render these now instead of reading the committed images")
    p.add_argument("--update-references", action="store_true",
                   help="write what --render made into the references folder (default: benchmarks/fidelity/references)")
    p.add_argument("--scale", type=float, default=0.25,
                   help="image size over the protocol's (default 0.25, the committed references')")
    p.add_argument("--samples", type=int, default=256, help="Cycles samples per pixel (default 256)")
    p.add_argument("--antialias", type=int, default=4,
                   help="pbrlab's samples per pixel (the render block's antialias; default 4, 1 = off; the "
                        "benchmark's Blackman-Harris resolve and 2x supersampling stay)")
    p.add_argument("--out", default="out/fidelity", help="output folder (default: out/fidelity)")
    p.set_defaults(run=run)
