"""Draw, run and count a hidden sample of public Unity shaders (issue 34's done-when).

A hidden sample is drawn before anything is changed for it and run once, as it stands:

    python scripts/unity_hidden_sample.py draw OUT GITDIR...    # extract, classify, sample
    python scripts/unity_hidden_sample.py run OUT [--jobs 2]    # render each in both languages
    python scripts/unity_hidden_sample.py count OUT             # the figures and the failures

``draw`` takes bare git directories (one per repository, named ``owner+name``, as the
``fetch`` tool leaves them), copies each one's shader sources (``.shader`` and what they
include) to ``OUT/src/owner+name/``, classifies each ``.shader``:

* URP: its text names ``UniversalPipeline`` or ``render-pipelines.universal``;
* built-in vertex/fragment: a ``CGPROGRAM`` with ``#pragma vertex``, no ``#pragma surface``
  and no ``HLSLPROGRAM``;

and draws at most CAP of each per repository with ``random.Random(seed)``, repositories in
name order, so that no repository dominates (``OUT/urp.txt``, ``OUT/builtin.txt``,
``OUT/protocol.json``). ``run`` renders each listed shader in GLSL and HLSL through
``pbrlab.checking.unity_corpus.run_shader`` (the corpus scene), each shader in its own process
killed after TIMEOUT seconds, and appends one JSON line per shader to ``OUT/LIST.jsonl`` (a
shader already there is not run again, so a stopped run goes on). ``count`` prints, per list,
how many render in both languages, how many of those are black, and every other shader with
both languages' first lines.
"""

from __future__ import annotations

import argparse
import json
import random
import re
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

SOURCES = (".shader", ".hlsl", ".cginc", ".cg", ".glslinc", ".compute", ".inc", ".h")
CAP = 8
TIMEOUT = 900
LISTS = ("urp", "builtin")


def _git(gitdir: Path, *args: str, data: bytes | None = None) -> bytes:
    return subprocess.run(["git", f"--git-dir={gitdir}", *args], input=data, check=True,
                          capture_output=True).stdout


def extract(gitdir: Path, dest: Path) -> int:
    """Copy the shader sources of ``gitdir``'s HEAD to ``dest``; Git LFS pointers are skipped."""
    rows = _git(gitdir, "ls-tree", "-r", "HEAD").decode("utf-8", "replace").splitlines()
    wanted = []
    for row in rows:
        meta, path = row.split("\t", 1)
        if meta.split()[1] == "blob" and path.lower().endswith(SOURCES):
            wanted.append((meta.split()[2], path))
    if not wanted:
        return 0
    batch = _git(gitdir, "cat-file", "--batch", data="".join(f"{sha}\n" for sha, _ in wanted).encode())
    at, count = 0, 0
    for _, path in wanted:
        header_end = batch.index(b"\n", at)
        size = int(batch[at:header_end].split()[2])
        body = batch[header_end + 1:header_end + 1 + size]
        at = header_end + 1 + size + 1
        if body.startswith(b"version https://git-lfs"):
            continue
        target = dest / path
        target.parent.mkdir(parents=True, exist_ok=True)
        target.write_bytes(body)
        count += 1
    return count


def classify(text: str) -> str | None:
    if "UniversalPipeline" in text or "render-pipelines.universal" in text:
        return "urp"
    if ("CGPROGRAM" in text and re.search(r"#\s*pragma\s+vertex\b", text)
            and not re.search(r"#\s*pragma\s+surface\b", text) and "HLSLPROGRAM" not in text):
        return "builtin"
    return None


def draw(out: Path, gitdirs: list[Path], seed: int, cap: int) -> None:
    if out.exists() and any(out.iterdir()):
        sys.exit(f"{out}: exists and is not empty (a sample is drawn once)")
    rng = random.Random(seed)
    chosen = {name: [] for name in LISTS}
    repos = []
    for gitdir in sorted(gitdirs, key=lambda g: _repo_name(g).lower()):
        name = _repo_name(gitdir)
        dest = out / "src" / name
        files = extract(gitdir, dest)
        head = _git(gitdir, "rev-parse", "HEAD").decode().strip()
        kinds = {k: [] for k in LISTS}
        for shader in sorted(dest.rglob("*.shader")) if dest.exists() else []:
            kind = classify(shader.read_text("utf-8", "replace"))
            if kind:
                kinds[kind].append(shader)
        picked = {k: sorted(rng.sample(v, min(cap, len(v)))) for k, v in kinds.items()}
        for k in LISTS:
            chosen[k] += picked[k]
        repos.append({"repo": name, "commit": head, "files": files,
                      **{f"{k}_found": len(kinds[k]) for k in LISTS},
                      **{f"{k}_drawn": len(picked[k]) for k in LISTS}})
    for k in LISTS:
        (out / f"{k}.txt").write_text("".join(f"{p}\n" for p in chosen[k]))
    (out / "protocol.json").write_text(json.dumps(
        {"drawn_utc": time.strftime("%Y-%m-%d %H:%M:%S", time.gmtime()), "seed": seed, "cap": cap,
         "classification": classify.__doc__ or "see module docstring", "repos": repos,
         "counts": {k: len(chosen[k]) for k in LISTS}}, indent=1))
    print({k: len(chosen[k]) for k in LISTS}, f"from {len(repos)} repositories")


def _repo_name(gitdir: Path) -> str:
    for part in reversed(Path(gitdir).parts):
        if "+" in part:
            return part
    return Path(gitdir).name


_ONE = r"""
import json, sys, numpy as np
from pathlib import Path
from pbrlab.checking.unity_corpus import run_shader, draws_black, agreement
path = Path(sys.argv[1])
row = {"path": str(path)}
images = {}
for language in ("glsl", "hlsl"):
    o = run_shader(path, language)
    row[language] = {"status": o.status, "message": o.message[:2000], "warnings": o.warnings[:20]}
    if o.image is not None:
        rgb = np.asarray(o.image, np.float64)[..., :3]
        row[language]["rgb_max"] = float(np.nanmax(np.where(np.isfinite(rgb), rgb, -1)))
        row[language]["black"] = draws_black(o.image)
        images[language] = o.image
if all(row[l]["status"] == "rendered" for l in ("glsl", "hlsl")):
    row["glsl_hlsl_max_rel"] = agreement(images["glsl"], images["hlsl"])
print("ROW " + json.dumps(row))
"""


def _run_one(path: str, timeout: int) -> dict:
    start = time.time()
    try:
        done = subprocess.run([sys.executable, "-c", _ONE, path], capture_output=True, text=True,
                              timeout=timeout)
    except subprocess.TimeoutExpired:
        return {"path": path, "glsl": {"status": "timeout"}, "hlsl": {"status": "timeout"},
                "seconds": timeout}
    line = next((l for l in done.stdout.splitlines() if l.startswith("ROW ")), None)
    if line is None:
        crash = {"status": "crash", "message": (done.stderr or done.stdout)[-1500:]}
        return {"path": path, "glsl": crash, "hlsl": crash, "seconds": time.time() - start}
    row = json.loads(line[4:])
    row["seconds"] = round(time.time() - start, 1)
    return row


def run(out: Path, jobs: int, timeout: int) -> None:
    for k in LISTS:
        listed = [l for l in (out / f"{k}.txt").read_text().splitlines() if l]
        log = out / f"{k}.jsonl"
        done = {json.loads(l)["path"] for l in log.read_text().splitlines()} if log.exists() else set()
        todo = [p for p in listed if p not in done]
        with ThreadPoolExecutor(jobs) as pool, log.open("a") as sink:
            for row in pool.map(lambda p: _run_one(p, timeout), todo):
                sink.write(json.dumps(row) + "\n")
                sink.flush()
                print(k, row["glsl"]["status"], row["hlsl"]["status"], row["path"], flush=True)


def count(out: Path) -> None:
    for k in LISTS:
        log = out / f"{k}.jsonl"
        listed = [l for l in (out / f"{k}.txt").read_text().splitlines() if l]
        rows = {r["path"]: r for r in map(json.loads, log.read_text().splitlines())} if log.exists() else {}
        both = [r for r in rows.values() if r["glsl"]["status"] == r["hlsl"]["status"] == "rendered"]
        black = [r for r in both if r["glsl"].get("black") and r["hlsl"].get("black")]
        hlsl_only = [r for r in rows.values() if r["hlsl"]["status"] == "rendered" and r not in both]
        print(f"{k}: {len(both)} of {len(listed)} render in both languages "
              f"({100 * len(both) / max(len(listed), 1):.1f} %), {len(black)} of them black; "
              f"{len(hlsl_only)} more in HLSL only; {len(rows)} of {len(listed)} run")
        for r in sorted(rows.values(), key=lambda r: r["path"]):
            if r in both:
                continue
            print(f"  {Path(r['path']).relative_to(out / 'src') if (out / 'src') in Path(r['path']).parents else r['path']}")
            for language in ("glsl", "hlsl"):
                o = r[language]
                first = (o.get("message") or "").strip().splitlines()[:1]
                print(f"    {language} {o['status']}: {first[0][:400] if first else ''}")
        for r in black:
            print(f"  black: {r['path']}")


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    sub = parser.add_subparsers(dest="command", required=True)
    d = sub.add_parser("draw")
    d.add_argument("out", type=Path)
    d.add_argument("gitdirs", type=Path, nargs="+")
    d.add_argument("--seed", type=int, required=True)
    d.add_argument("--cap", type=int, default=CAP)
    r = sub.add_parser("run")
    r.add_argument("out", type=Path)
    r.add_argument("--jobs", type=int, default=1)
    r.add_argument("--timeout", type=int, default=TIMEOUT)
    c = sub.add_parser("count")
    c.add_argument("out", type=Path)
    args = parser.parse_args(argv)
    if args.command == "draw":
        draw(args.out, args.gitdirs, args.seed, args.cap)
    elif args.command == "run":
        run(args.out, args.jobs, args.timeout)
    else:
        count(args.out)


if __name__ == "__main__":
    main()
