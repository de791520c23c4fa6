"""How far the fidelity benchmark's volume rows depend on the reference's absorption: Cycles
rendered again with KHR_materials_volume's coefficient sigma = -ln(attenuationColor) /
attenuationDistance (tools/cycles/extension_absorption.py) instead of Blender's importer's
(1 - attenuationColor) / attenuationDistance, and every image scored against it: pbrlab with the
material's thickness (the benchmark's render block) and with render.volume_chord, three.js and
the Sample Viewer (their committed images), and the committed Cycles reference itself
(docs/fidelity.md, "The volume step"). Needs Blender's bpy (scripts/setup_cycles.sh, or
PBRLAB_BPY_PYTHON). A measurement: it prints figures and asserts nothing.

    python benchmarks/volume_absorption_reference.py [KEY ...] [--out DIR]

KEY: rows of the benchmark (default: AttenuationTest under both lightings).
"""

from __future__ import annotations

import argparse
import tempfile
from pathlib import Path

from pbrlab.checking.fidelity import benchmark, metric, renderers
from pbrlab.foundation import images

ROOT = Path(__file__).resolve().parents[1]
DEFAULT_KEYS = ("khronos-AttenuationTest@sunrise", "khronos-AttenuationTest@courtyard")
RENDER_BLOCKS = {"thickness": benchmark.PBRLAB_RENDER,
                 "volume_chord": {**benchmark.PBRLAB_RENDER, "volume_chord": True}}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("keys", nargs="*", default=list(DEFAULT_KEYS))
    parser.add_argument("--out", type=Path, default=None, help="keep the renders here (default: a temporary folder)")
    args = parser.parse_args()
    renderers.TOOLS["cycles"] = ROOT / "tools" / "cycles" / "extension_absorption.py"
    with tempfile.TemporaryDirectory(prefix="pbrlab-volume-absorption-") as scratch:
        out = args.out or Path(scratch)
        references = out / "references"  # the extension-absorption Cycles images, as the benchmark lays them out
        scores = {}
        for label, block in RENDER_BLOCKS.items():
            rows = benchmark.run(keys=args.keys, render=("pbrlab", "cycles") if label == "thickness" else ("pbrlab",),
                                 out=out / label, render_block=block, references=references,
                                 update_references=label == "thickness", log=lambda line: None)
            for row in rows:
                scores.setdefault(row.key, {})[f"pbrlab ({label})"] = row.scores["pbrlab"]
        for key in args.keys:
            golden = images.read_image(benchmark.reference_path(key, "cycles", references))
            for name in ("threejs", "sample_viewer", "cycles"):
                path = benchmark.reference_path(key, name)
                label = "the committed Cycles reference" if name == "cycles" else name
                scores[key][label] = metric.score_db(images.read_image(path), golden)
            print(f"{key}, against Cycles with the extension's absorption: "
                  + ", ".join(f"{name} {db:.2f} dB" for name, db in scores[key].items()))


if __name__ == "__main__":
    main()
