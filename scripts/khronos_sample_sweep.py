"""Renders every model variant of Khronos' glTF sample set that a reader can get, as a
new user would (`pbrlab render FILE -o out.png`), and reports N of M rendered, refused
(exit 2: the message) and failed (any other exit, or past the time limit).

The models are not part of this repository (their licences vary): give a folder holding
them (`--models DIR`, with DIR/<Model>/<variant>/<file>), or a git directory of a
glTF-Sample-Assets snapshot (`--git DIR`, e.g. the DRx3D/glTF-Sample-Assets-OLD mirror),
from which every file whose blob is present is written to a temporary folder; a variant
that refers to a file the snapshot lacks is counted apart, as "not available".

    .venv/bin/python scripts/khronos_sample_sweep.py --git /path/to/repo.git --json out.json --markdown out.md
"""

from __future__ import annotations

import argparse
import json
import re
import subprocess
import sys
import tempfile
import time
from collections import Counter
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path
from urllib.parse import unquote

MODEL_SUFFIXES = (".gltf", ".glb")
SIZE = "160x120"
ENVIRONMENT = "0.3,0.3,0.3"  # a constant sky: every model visible without a light of its own
TIME_LIMIT_S = 600
CLI = "import sys; from pbrlab.commands import cli; sys.exit(cli.main(sys.argv[1:]))"  # `pbrlab` itself


def extract(git_dir: Path, out: Path) -> list[str]:
    """Every blob under Models/ present in the git directory, written below ``out``; the
    paths of the model files (.gltf, .glb) whose blob is absent."""
    listing = subprocess.run(["git", "--git-dir", str(git_dir), "ls-tree", "-r", "HEAD", "Models"],
                             capture_output=True, text=True, check=True).stdout.splitlines()
    absent = []
    for line in listing:
        meta, path = line.split("\t", 1)
        sha = meta.split()[2]
        blob = subprocess.run(["git", "--git-dir", str(git_dir), "cat-file", "blob", sha], capture_output=True)
        if blob.returncode != 0:  # absent from the snapshot (its largest files)
            if Path(path).suffix.lower() in MODEL_SUFFIXES:
                absent.append(path)
            continue
        target = out / path
        target.parent.mkdir(parents=True, exist_ok=True)
        target.write_bytes(blob.stdout)
    return absent


def referenced_files(model: Path) -> list[str]:
    """The external files a .gltf names (buffers and images with a relative uri)."""
    if model.suffix.lower() != ".gltf":
        return []
    doc = json.loads(model.read_text(encoding="utf-8"))
    uris = [item.get("uri") for key in ("buffers", "images") for item in doc.get(key, [])]
    return [unquote(u) for u in uris if isinstance(u, str) and not u.startswith("data:")]


def models(root: Path) -> list[Path]:
    return sorted(p for p in (root / "Models").rglob("*") if p.suffix.lower() in MODEL_SUFFIXES)


def _name(model: Path, root: Path) -> str:
    return model.relative_to(root / "Models").as_posix()


def render(model: Path, root: Path, out_dir: Path) -> dict:
    name = _name(model, root)
    missing = [u for u in referenced_files(model) if not (model.parent / u).is_file()]
    if missing:
        return {"model": name, "result": "not available", "reason": f"the snapshot lacks {missing[0]}"}
    png = out_dir / (re.sub(r"[^A-Za-z0-9]+", "_", name) + ".png")
    start = time.perf_counter()
    try:
        run = subprocess.run([sys.executable, "-c", CLI, "render", str(model), "-o", str(png), "--size", SIZE,
                              "--environment", ENVIRONMENT], capture_output=True, text=True, timeout=TIME_LIMIT_S)
    except subprocess.TimeoutExpired:
        return {"model": name, "result": "failed", "reason": f"over {TIME_LIMIT_S} s"}
    seconds = round(time.perf_counter() - start, 1)
    lines = [line for line in run.stderr.splitlines() if line.strip()]
    warnings = [line[len("warning: "):] for line in lines if line.startswith("warning: ")]
    result = {0: "rendered", 2: "refused"}.get(run.returncode, "failed")
    errors = [line for line in lines if not line.startswith("warning: ")]
    reason = "" if result == "rendered" else (errors[-1] if errors else f"exit {run.returncode}")
    reason = reason.replace(f"{model}: ", "").replace("pbrlab render: error: ", "")
    return {"model": name, "result": result, "reason": reason, "warnings": warnings, "seconds": seconds}


def markdown(rows: list[dict]) -> str:
    counts = Counter(r["result"] for r in rows)
    available = len(rows) - counts["not available"]
    lines = [f"**{counts['rendered']} of {available}** variants rendered, {counts['refused']} refused, "
             f"{counts['failed']} failed ({counts['not available']} more not available in the snapshot).", "",
             "| model / variant / file | result | reason |", "|---|---|---|"]
    for r in rows:
        if r["result"] != "rendered":
            lines.append(f"| {r['model']} | {r['result']} | {r['reason'].replace('|', '/')} |")
    return "\n".join(lines) + "\n"


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    source = parser.add_mutually_exclusive_group(required=True)
    source.add_argument("--models", type=Path, help="a folder holding Models/<Model>/<variant>/<file>")
    source.add_argument("--git", type=Path, help="a git directory of a glTF-Sample-Assets snapshot")
    parser.add_argument("--json", type=Path, help="write every row here")
    parser.add_argument("--markdown", type=Path, help="write the summary table here")
    parser.add_argument("--jobs", type=int, default=1, help="renders at once (default 1)")
    args = parser.parse_args(argv)
    with tempfile.TemporaryDirectory() as tmp:
        root, absent = args.models, []
        if args.git is not None:
            root = Path(tmp) / "snapshot"
            absent = extract(args.git, root)
        out_dir = Path(tmp) / "renders"
        out_dir.mkdir()
        files = models(root)
        with ThreadPoolExecutor(max(1, args.jobs)) as pool:
            rows = [{"model": path.removeprefix("Models/"), "result": "not available",
                     "reason": "the snapshot lacks the file itself"} for path in absent]
            for row in pool.map(lambda m: render(m, root, out_dir), files):
                print(f"{row['result']:>13}  {row['model']}  {row['reason']}", file=sys.stderr)
                rows.append(row)
    if args.json:
        args.json.write_text(json.dumps(rows, indent=1) + "\n", encoding="utf-8")
    table = markdown(rows)
    if args.markdown:
        args.markdown.write_text(table, encoding="utf-8")
    print(table)
    return 0 if not Counter(r["result"] for r in rows)["failed"] else 1


if __name__ == "__main__":
    sys.exit(main())
