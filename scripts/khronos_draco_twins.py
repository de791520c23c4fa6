"""Every Khronos sample model with a glTF-Draco variant and an uncompressed glTF variant in a
glTF-Sample-Assets git snapshot, both rendered by pbrlab from the same camera (the
uncompressed variant's: its own, or the framing view) and compared: what the Draco data
changes, and that the Draco variant is drawn at all.

Per model: the pixels each covers (pbrlab.checking.content), the pixels covered by one only
away from every silhouette of both (Draco's quantisation moves vertices by far less than a
pixel, so 0 is expected), the mean |difference| in 8-bit sRGB codes over the whole image and
the fraction of pixels more than 4 codes apart. ``--time T`` poses both at T seconds (their
first animation), where the joints and weights decide the shape.

    .venv/bin/python scripts/khronos_draco_twins.py --git /path/to/glTF-Sample-Assets.git [--time 1]
"""

from __future__ import annotations

import argparse
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np

SIZE = (160, 120)
SKY = (0.3, 0.3, 0.3)
CODES = 4


def _git(git_dir: Path, *args) -> subprocess.CompletedProcess:
    return subprocess.run(["git", "--git-dir", str(git_dir), *args], capture_output=True, check=False)


def twins(git_dir: Path) -> list[str]:
    """Models with both a glTF-Draco and a glTF folder."""
    listing = _git(git_dir, "ls-tree", "-r", "--name-only", "HEAD", "Models").stdout.decode().splitlines()
    folders = {tuple(p.split("/")[1:3]) for p in listing if p.count("/") >= 3}
    return sorted(m for m, v in folders if v == "glTF-Draco" and (m, "glTF") in folders)


def extract(git_dir: Path, model: str, variant: str, out: Path) -> Path | None:
    """The variant's files under ``out``; None when a blob is absent from the snapshot."""
    names = _git(git_dir, "ls-tree", "--name-only", "HEAD", f"Models/{model}/{variant}/").stdout.decode().split()
    for name in names:
        blob = _git(git_dir, "cat-file", "blob", f"HEAD:{name}")
        if blob.returncode != 0:
            return None
        (out / name).parent.mkdir(parents=True, exist_ok=True)
        (out / name).write_bytes(blob.stdout)
    found = [out / n for n in names if n.endswith((".gltf", ".glb"))]
    return found[0] if found else None


def compare(plain_path: Path, draco_path: Path, time) -> dict:
    from pbrlab.checking import content
    from pbrlab.foundation.errors import PbrlabError
    from pbrlab.importers.gltf import load_gltf
    from pbrlab.render.renderer import render_scene
    from pbrlab.scene.model import Environment

    environment = Environment(color=np.array(SKY))
    try:
        plain = load_gltf(plain_path, size=SIZE, environment=environment, emit_warnings=False, time=time).scene
        draco = load_gltf(draco_path, size=SIZE, environment=environment, emit_warnings=False, time=time).scene
    except PbrlabError as exc:
        return {"error": str(exc).splitlines()[0]}
    draco.camera = plain.camera  # the same view of both
    a, b = render_scene(plain), render_scene(draco)
    codes = np.abs(a.srgb8[..., :3].astype(np.int32) - b.srgb8[..., :3]).max(axis=-1)
    return {"covered": int(content.covered(a.linear).sum()), "draco_covered": int(content.covered(b.linear).sum()),
            "off_silhouette": content.coverage_disagreement(a.linear, b.linear),
            "mean_codes": float(np.abs(a.srgb8[..., :3].astype(np.float64) - b.srgb8[..., :3]).mean()),
            "over_codes": float((codes > CODES).mean()),
            "draco": content.content(b.linear, b.srgb8).verdict}


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--git", type=Path, required=True, help="a git directory of a glTF-Sample-Assets snapshot")
    parser.add_argument("--time", type=float, default=None, help="pose both at T seconds (their first animation)")
    args = parser.parse_args(argv)
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for model in twins(args.git):
            paths = [extract(args.git, model, v, Path(tmp)) for v in ("glTF", "glTF-Draco")]
            if None in paths:
                print(f"{model}: not available in the snapshot", file=sys.stderr)
                continue
            time = args.time
            if time is not None and b'"animations"' not in paths[0].read_bytes():
                time = None  # a file without animations is drawn as written
            row = {"model": model, "time": time, **compare(*paths, time)}
            print(row, file=sys.stderr)
            rows.append(row)
    drawn = [r for r in rows if r.get("draco") == "drawn"]
    print(f"{len(drawn)} of {len(rows)} Draco variants drawn; coverage off silhouettes differs on "
          f"{sum(1 for r in drawn if r['off_silhouette'])} of them; mean |difference| at most "
          f"{max((r['mean_codes'] for r in drawn), default=0):.2f} codes, at most "
          f"{max((r['over_codes'] for r in drawn), default=0):.2%} of pixels over {CODES} codes")
    for r in rows:
        print(f"| {r['model']} | " + (r["error"] if "error" in r else
              f"{r['draco']} | {r['covered']} / {r['draco_covered']} | {r['off_silhouette']} | "
              f"{r['mean_codes']:.2f} | {r['over_codes']:.2%} |"))
    return 0 if len(drawn) == len(rows) else 1


if __name__ == "__main__":
    sys.exit(main())
