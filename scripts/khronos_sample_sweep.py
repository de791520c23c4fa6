"""Renders every model variant of Khronos' glTF sample set that a reader can get, as a
new user would (`pbrlab render FILE -o out.png --hdr out.exr`), checks what each image shows,
and reports N of M by verdict:

    drawn                 exit 0, surfaces cover pixels and some covered pixel is lit (over
                          pbrlab.checking.content.BLACK_CODE), and, where three.js runs, its
                          render of the same camera covers the same pixels away from
                          silhouettes and its mean colour is within COLOUR_SCREEN_CODES
    differs from three.js exit 0 and drawn, but three.js covers other pixels away from every
                          silhouette, or its mean colour is further off (the figures say which)
    empty                 exit 0 and no covered pixel (pbrlab render also warns)
    black                 exit 0, pixels covered, none lit
    refused               exit 2 (the message)
    failed                any other exit, or past the time limit
    not available         the snapshot lacks the file or a file it names

The comparison with three.js r187 (tools/threejs_gltf, headless Chromium; `--no-threejs` to
leave it out, and it is left out with a note where its setup is missing) renders the camera
pbrlab chose, with pbrlab's near and far planes, under the same constant sky, one sample per
pixel (as pbrlab's default), glass over nothing showing that sky (THREEJS_VIEW), with the
Draco, KTX2 and meshopt decoders three.js ships, and compares linear images (pbrlab's EXR,
three.js's float output) through the plain sRGB encode: no exposure or tonemap on either side.
Where three.js logs an error (a part it could not load) or an unknown required extension, the
variant is drawn but not compared, and the row says why. `--sample-viewer` adds a third
opinion where the two differ (the Khronos Sample Viewer, tools/sample_viewer), `--images DIR`
keeps each pair's images to look at.

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

import numpy as np

MODEL_SUFFIXES = (".gltf", ".glb")
SIZE = "160x120"
ENVIRONMENT = "0.3,0.3,0.3"  # a constant sky: every model visible without a light of its own
TIME_LIMIT_S = 600
CLI = "import sys; from pbrlab.commands import cli; sys.exit(cli.main(sys.argv[1:]))"  # `pbrlab` itself
# A screen, not an accuracy bound: the largest channel's mean over the jointly covered pixels.
# Renderers that implement the same glTF material agree far closer (pbrlab, three.js and the
# Sample Renderer within 2.7 codes mean on corpus/gltf/khronos, test_khronos_models.py); a
# mean 8 codes off (3 % of the range) is a material or texture drawn differently, to look at.
COLOUR_SCREEN_CODES = 8.0
# What three.js's tool is asked beyond the camera (tools/threejs_gltf/render.mjs):
THREEJS_VIEW = {
    # one sample at each pixel centre, as pbrlab render's default --antialias 1: under 4x MSAA
    # three.js's coverage (alpha > 0: any of 4 samples) took in bars thinner than a pixel that
    # pbrlab's centre sample misses (AnisotropyRotationTest: 2 pixels "off silhouettes")
    "msaa": 0,
    # glass over nothing shows the sky (KHR_materials_transmission: the light from behind; pbrlab
    # and the Sample Viewer), not three.js's white stand-in for a page behind the canvas
    "transmissionBackground": [float(v) for v in ENVIRONMENT.split(",")],
}
VERDICTS = ("drawn", "differs from three.js", "empty", "black", "refused", "failed", "not available")


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


def _size() -> tuple[int, int]:
    width, height = SIZE.split("x")
    return int(width), int(height)


def side_by_side(ours: np.ndarray, theirs: np.ndarray) -> np.ndarray:
    """pbrlab | three.js | where coverage differs (red: pbrlab only, blue: three.js only), as
    sRGB8 RGB over a dark grey ground: both linear STRAIGHT images through the plain encode."""
    from pbrlab.checking import content
    from pbrlab.maths import srgb8

    def shown(linear):
        rgb = srgb8.encode(np.clip(linear[..., :3], 0, None)).astype(np.uint8)
        return np.where(content.covered(linear)[..., None], rgb, np.uint8(40))
    a, b = content.covered(ours), content.covered(theirs)
    diff = np.full(ours.shape[:2] + (3,), 40, np.uint8)
    diff[a & b] = 128
    diff[a & ~b] = (255, 0, 0)
    diff[b & ~a] = (0, 0, 255)
    gap = np.full((ours.shape[0], 2, 3), 255, np.uint8)
    return np.concatenate([shown(ours), gap, shown(theirs), gap, diff], axis=1)


def _view(model: Path, sky: dict) -> dict:
    """The view spec (pbrlab.checking.fidelity) of the camera pbrlab chooses for ``model``,
    with pbrlab's own near and far planes, under ``sky`` ({"environment": exr, ...})."""
    from pbrlab.importers.gltf import load_gltf
    from pbrlab.render.depth_range import scene_frame
    from pbrlab.scene.model import Environment

    scene = load_gltf(model, size=_size(), environment=Environment(color=_sky_colour()), emit_warnings=False).scene
    camera, frame = scene.camera, scene_frame(scene)
    return {"gltf": str(model), "size": list(_size()), **sky,
            "camera": {"eye": [float(x) for x in camera.position], "target": [float(x) for x in camera.target],
                       "up": [float(x) for x in camera.up], "yfov_deg": float(camera.fov_y_deg),
                       "znear": float(frame.near), "zfar": float(frame.far)},
            "samples": 1, "seed": 0, "denoise": False}


def _peer_image(renderer: str, view: dict) -> tuple[np.ndarray | None, dict]:
    """(``renderer``'s straight linear image, its tool's report) or (None, {"error": line})."""
    from pbrlab.checking.fidelity import renderers
    from pbrlab.foundation.errors import PbrlabError

    try:
        return renderers.render(renderer, view)
    except PbrlabError as exc:
        lines = [line.strip() for line in str(exc).splitlines() if line.strip()]
        named = [line for line in lines if "Error" in line] or lines[-1:] or ["no message"]
        return None, {"error": named[0][:300]}  # the JS error's own line, not the stack under it


def _figures(ours: np.ndarray, theirs: np.ndarray) -> dict:
    from pbrlab.checking import content
    from pbrlab.maths import srgb8

    return {"coverage_pixels": content.coverage_disagreement(ours, theirs),
            "mean_codes": content.mean_colour_difference(ours, theirs, srgb8.encode)}


def threejs_comparison(model: Path, linear: np.ndarray, sky_exr: Path, keep: Path | None = None) -> dict:
    """three.js's render of the camera pbrlab chooses for ``model``, compared with pbrlab's
    ``linear`` image (pbrlab.checking.content): off-silhouette coverage pixels, mean colour.
    ``keep``: write KEEP.png (pbrlab | three.js | coverage), KEEP.npz (both straight linear
    images) and three.js's console messages."""
    from pbrlab.checking import content
    from pbrlab.checking.fidelity import renderers

    theirs, meta = _peer_image("threejs", {**_view(model, {"environment": str(sky_exr)}), **THREEJS_VIEW})
    if theirs is None:
        return meta
    ours = renderers.straight(linear)
    # three.js draws on where GLTFLoader could not read a part (a texture it has no decoder
    # for, a buffer it cannot fetch) and where the file requires an extension it does not
    # know (it warns 'Unknown extension "NAME".' and draws the fallback, e.g. r147 on for
    # KHR_materials_pbrSpecularGlossiness): its image is then of another model.
    errors = [m.split(": ", 1)[1] for m in meta.get("messages", [])
              if m.startswith("error: ") or (m.startswith("warning: ") and "Unknown extension" in m)]
    if keep is not None:
        from pbrlab.foundation.images import write_png
        write_png(keep.with_suffix(".png"), side_by_side(ours, theirs))
        np.savez_compressed(keep.with_suffix(".npz"), pbrlab=ours, threejs=theirs)
        keep.with_suffix(".threejs.json").write_text(json.dumps(meta.get("messages", []), indent=1) + "\n")
    return {**({"error": f"three.js logged: {errors[0][:300]}"} if errors else {}), **_figures(ours, theirs),
            "threejs_coverage": round(float(content.covered(theirs).mean()), 4), "image": theirs}


def sample_viewer_opinion(model: Path, ours: np.ndarray, threejs: np.ndarray | None, sky: dict,
                          keep: Path | None = None) -> dict:
    """The Khronos Sample Renderer's image of the same view (tools/sample_viewer; one sample
    per pixel is asked, the tool's VIEW_EXTRAS make it 4x MSAA as the benchmark's), a third
    opinion where pbrlab and three.js differ (each one's figures against it), or the second
    where three.js could not render the file (``threejs`` None). ``sky``: the constant sky as
    EXR and as the Radiance HDR the viewer reads (RGBE keeps 0.3 as 0.3008: the same 8-bit
    sRGB code, 149)."""
    from pbrlab.checking.fidelity import renderers

    theirs, meta = _peer_image("sample_viewer", {**_view(model, sky), "msaa": 0})
    if theirs is None:
        return meta
    if keep is not None:
        from pbrlab.foundation.images import write_png
        write_png(keep.with_name(keep.name + ".sample_viewer.png"), side_by_side(renderers.straight(ours), theirs))
    return {"pbrlab": _figures(renderers.straight(ours), theirs),
            **({} if threejs is None else {"threejs": _figures(threejs, theirs)})}


def render(model: Path, root: Path, out_dir: Path, sky: dict | None, at_time: str | None = None,
           images: Path | None = None) -> dict:
    from pbrlab.checking import content
    from pbrlab.foundation.images import read_image

    name = _name(model, root)
    missing = [u for u in referenced_files(model) if not (model.parent / u).is_file()]
    if missing:
        return {"model": name, "result": "not available", "reason": f"the snapshot lacks {missing[0]}"}
    stem = out_dir / re.sub(r"[^A-Za-z0-9]+", "_", name)
    png, exr = stem.with_suffix(".png"), stem.with_suffix(".exr")
    start = time.perf_counter()
    try:
        run = subprocess.run([sys.executable, "-c", CLI, "render", str(model), "-o", str(png), "--hdr", str(exr),
                              "--size", SIZE, "--environment", ENVIRONMENT]
                             + (["--time", at_time] if at_time is not None and _animated(model) else []),
                             capture_output=True, text=True, timeout=TIME_LIMIT_S)
    except subprocess.TimeoutExpired:
        return {"model": name, "result": "failed", "reason": f"over {TIME_LIMIT_S} s"}
    seconds = round(time.perf_counter() - start, 1)
    lines = [line for line in run.stderr.splitlines() if line.strip()]
    warnings = [line[len("warning: "):] for line in lines if line.startswith("warning: ")]
    result = {0: "rendered", 2: "refused"}.get(run.returncode, "failed")
    errors = [line for line in lines if not line.startswith("warning: ")]
    reason = "" if result == "rendered" else (errors[-1] if errors else f"exit {run.returncode}")
    reason = reason.replace(f"{model}: ", "").replace("pbrlab render: error: ", "")
    row = {"model": name, "result": result, "reason": reason, "warnings": warnings, "seconds": seconds}
    if result != "rendered":
        return row
    linear = read_image(exr)
    shown = content.content(linear, read_image(png))
    row.update(result=shown.verdict, coverage=round(shown.coverage, 4), lit=round(shown.lit_fraction, 4))
    if shown.verdict == "empty":
        row["reason"] = "no covered pixel"
    elif shown.verdict == "black":
        row["reason"] = f"{shown.coverage:.1%} covered, every covered pixel at or under code {content.BLACK_CODE}"
    elif sky is not None:
        keep = None if images is None else images / stem.name
        peer = threejs_comparison(model, linear, Path(sky["environment"]), keep)
        threejs_image = peer.pop("image", None)
        row["threejs"] = peer
        if "error" in peer:
            row["reason"] = f"not compared with three.js: {peer['error']}"
            if "environment_hdr" in sky:  # the Sample Viewer's opinion in its place
                row["sample_viewer"] = sample_viewer_opinion(model, linear, None, sky, keep)
                row["reason"] += "; " + _third_opinion_text(row["sample_viewer"])
        elif peer["coverage_pixels"] > 0 or (peer["mean_codes"] or 0.0) > COLOUR_SCREEN_CODES:
            row["result"] = "differs from three.js"
            mean = "none shared" if peer["mean_codes"] is None else f"{peer['mean_codes']:.1f} codes"
            row["reason"] = (f"{peer['coverage_pixels']} pixels covered by one only, off silhouettes; "
                             f"mean colour {mean} apart (coverage {shown.coverage:.1%} / three.js "
                             f"{peer['threejs_coverage']:.1%})")
            if "environment_hdr" in sky:
                third = sample_viewer_opinion(model, linear, threejs_image, sky, keep)
                row["sample_viewer"] = third
                row["reason"] += "; " + _third_opinion_text(third)
    return row


def _third_opinion_text(third: dict) -> str:
    if "error" in third:
        return f"the Sample Viewer did not render it: {third['error']}"

    def figures(f):
        mean = "none shared" if f["mean_codes"] is None else f"{f['mean_codes']:.1f} codes"
        return f"{f['coverage_pixels']} pixels, {mean}"
    text = f"from the Sample Viewer: pbrlab {figures(third['pbrlab'])}"
    return text + (f", three.js {figures(third['threejs'])}" if "threejs" in third else "")


def _sky_colour() -> np.ndarray:
    return np.array([float(v) for v in ENVIRONMENT.split(",")])


def _animated(model: Path) -> bool:
    """Whether the file has animations (its JSON: the .gltf, or a .glb's first chunk)."""
    data = model.read_bytes()
    if model.suffix.lower() == ".glb":
        length = int.from_bytes(data[12:16], "little")
        data = data[20:20 + length]
    try:
        return bool(json.loads(data).get("animations"))
    except (ValueError, AttributeError):
        return False


def markdown(rows: list[dict]) -> str:
    counts = Counter(r["result"] for r in rows)
    available = len(rows) - counts["not available"]
    compared = sum(1 for r in rows if "threejs" in r and "error" not in r["threejs"])
    lines = [f"**{counts['drawn']} of {available}** variants drawn ("
             + ", ".join(f"{counts[v]} {v}" for v in VERDICTS[1:-1])
             + f"; {counts['not available']} more not available in the snapshot); "
               f"{compared} compared with three.js.", "",
             "| model / variant / file | result | reason |", "|---|---|---|"]
    for r in rows:
        if r["result"] != "drawn" or r.get("reason"):
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
    parser.add_argument("--no-threejs", action="store_true", help="leave out the comparison with three.js")
    parser.add_argument("--images", type=Path, default=None, metavar="DIR",
                        help="write each compared variant's pbrlab | three.js | coverage image here (PNG), "
                             "both linear straight images (NPZ) and three.js's console messages")
    parser.add_argument("--sample-viewer", action="store_true",
                        help="where pbrlab and three.js differ, or three.js could not render the file, render "
                             "the Khronos Sample Viewer's image of the same view too and give each one's figures "
                             "against it (a third opinion)")
    parser.add_argument("--only", default=None, metavar="MODEL,...",
                        help="only these models (names of Models/ folders, comma-separated)")
    parser.add_argument("--time", default=None, metavar="T",
                        help="render animated files at T seconds (pbrlab render --time: their first animation); "
                             "three.js, which draws the nodes as written, is then left out")
    args = parser.parse_args(argv)
    from pbrlab.checking.fidelity import renderers
    from pbrlab.foundation import images

    args.no_threejs = args.no_threejs or args.time is not None
    missing = [] if args.no_threejs else renderers.missing_setup("threejs")
    if args.sample_viewer and not args.no_threejs:
        missing += renderers.missing_setup("sample_viewer")
    if missing:
        print("three.js left out: " + "; ".join(missing), file=sys.stderr)
    if args.images is not None:
        args.images.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory() as tmp:
        root, absent = args.models, []
        if args.git is not None:
            root = Path(tmp) / "snapshot"
            absent = extract(args.git, root)
        out_dir = Path(tmp) / "renders"
        out_dir.mkdir()
        sky = None  # the constant sky as an equirect image for three.js (and the Sample Viewer)
        if not args.no_threejs and not missing:
            sky = {"environment": str(Path(tmp) / "sky.exr")}
            equirect = np.ascontiguousarray(np.broadcast_to(_sky_colour().astype(np.float32), (16, 32, 3)))
            images.write_exr(sky["environment"], equirect)
            if args.sample_viewer:
                from pbrlab.checking.sample_viewer import write_radiance_hdr
                sky["environment_hdr"] = str(Path(tmp) / "sky.hdr")
                write_radiance_hdr(sky["environment_hdr"], equirect)
        files = models(root)
        if args.only:
            chosen = set(args.only.split(","))
            files = [f for f in files if f.relative_to(root / "Models").parts[0] in chosen]
            absent = [a for a in absent if a.split("/")[1] in chosen]
        with ThreadPoolExecutor(max(1, args.jobs)) as pool:
            rows = [{"model": path.removeprefix("Models/"), "result": "not available",
                     "reason": "the snapshot lacks the file itself"} for path in absent]
            for row in pool.map(lambda m: render(m, root, out_dir, sky, args.time, args.images), files):
                print(f"{row['result']:>22}  {row['model']}  {row['reason']}", file=sys.stderr)
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
