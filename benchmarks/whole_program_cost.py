"""Whole-program cost per glTF material class (issue 35): for each class's generated glTF file
(pbrlab.bench.peer_gltf: the same textured sphere and directional lights, one extension per
class), pbrlab's specialised production program and its checking program (`pbrlab render`'s),
three.js r187's and the Khronos Sample Viewer's fragment programs for the same file (captured
in headless Chromium, committed in benchmarks/peer_programs/), compiled by Mesa RADV/ACO on
the null device: static instructions, VGPRs and RADV's waves per SIMD for RDNA3 / RDNA2 /
GCN5, one Markdown table per case, the cheapest of pbrlab production and the peers that
implement the class (RDNA3 instructions) in bold. pbrlab.bench.peer_programs says how the
peers' programs are picked and rewritten. A benchmark: it prints figures and asserts nothing.

    python benchmarks/whole_program_cost.py                 # every class, 1 light + environment
    python benchmarks/whole_program_cost.py --extras        # and 0 / 4 lights, no environment
    python benchmarks/whole_program_cost.py --class sheen   # one class
    python benchmarks/whole_program_cost.py --capture       # recapture the peers (Chromium, node)
    python benchmarks/whole_program_cost.py --json docs/bench/whole_program_cost.json
        # also write the figures, from which python -m pbrlab.bench.class_headline writes the
        # README's table
"""

from __future__ import annotations

import argparse
import datetime
import json
from pathlib import Path

from pbrlab.bench import gpu, peer_gltf, peer_programs
from pbrlab.foundation.errors import PbrlabError

ROOT = Path(__file__).resolve().parents[1]
FOLDER = ROOT / "benchmarks" / "peer_programs"


def summary(results: dict) -> str:
    """One line per case: RDNA3 instructions of the four columns and the cheapest."""
    lines = ["| case | " + " | ".join(peer_programs.COLUMNS) + " | cheapest |", "|---|" + "---|" * 5]
    for key, row in results.items():
        cells = []
        for column in peer_programs.COLUMNS:
            f = row[column]["families"]["rdna3"]
            cells.append(f"{f['instructions']} / {f['vgprs']}" + ("" if row[column]["honoured"] else " (n/i)"))
        lines.append(f"| {key} | " + " | ".join(cells) + f" | {peer_programs.cheapest(row)} |")
    return "\n".join(lines)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--class", dest="classes", action="append", choices=tuple(peer_gltf.CLASSES),
                        help="a material class (repeatable; default: all)")
    parser.add_argument("--extras", action="store_true", help="also 0 and 4 lights, and no environment")
    parser.add_argument("--capture", action="store_true", help="recapture the peers' programs first (Chromium)")
    parser.add_argument("--folder", type=Path, default=FOLDER, help="the captured programs (default: %(default)s)")
    parser.add_argument("--json", type=Path, help="also write the figures to this JSON file")
    args = parser.parse_args()
    selected = peer_programs.cases(tuple(args.classes or peer_gltf.CLASSES), extras=args.extras)
    try:
        if args.capture:
            peer_programs.capture(ROOT, args.folder, selected)
        gpu.require_null_device()
        results = peer_programs.measure(args.folder, selected)
    except PbrlabError as exc:
        raise SystemExit(f"whole_program_cost: {exc}") from None
    if args.json:
        manifest = json.loads((args.folder / "manifest.json").read_text(encoding="utf-8"))
        versions = manifest.get("versions", {})
        for row in results.values():  # sources as paths in the repository, not this machine's
            for entry in row.values():
                source = Path(entry["source"])
                entry["source"] = (source.relative_to(ROOT).as_posix() if source.is_absolute()
                                   and source.is_relative_to(ROOT) else entry["source"])
        args.json.write_text(json.dumps({
            "date": datetime.date.today().isoformat(),
            "versions": {"three.js": versions.get("three", "?"), "Sample Viewer": versions.get("gltf-viewer", "?")},
            "results": results}, indent=1) + "\n", encoding="utf-8")
    print(gpu.ACO_NOTE)
    print()
    print("RDNA3 instructions / VGPRs per case ((n/i): the peer does not implement the class; "
          "not counted as cheapest):")
    print()
    print(summary(results))
    for key, row in results.items():
        print()
        print(peer_programs.markdown_table(key, row))


if __name__ == "__main__":
    main()
