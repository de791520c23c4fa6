"""One view of the benchmark rendered LINEAR by each renderer: pbrlab (in this process),
Blender's Cycles (the path-traced reference, tools/cycles/render.py run by a Python that has
PyPI's ``bpy``), three.js (tools/threejs_gltf/render.mjs) and the Khronos Sample Viewer
(tools/sample_viewer/render.mjs), the last two in headless Chromium.

Every renderer is given the same view spec (staging.view_spec) and ``render`` returns an HxWx4
float32 image: rows top to bottom, linear radiance (no exposure, tonemap or encode), STRAIGHT
colour (premultiplied outputs divided by alpha: PREMULTIPLIED), alpha = coverage. The benchmark puts every one through the same display transform.
"""

from __future__ import annotations

import json
import os
import shutil
import signal
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np

from ...foundation.errors import PbrlabError
from .staging import REPO

RENDERERS = ("pbrlab", "cycles", "threejs", "sample_viewer")
PEERS = ("threejs", "sample_viewer")
REFERENCE = "cycles"
TOOLS = {"cycles": REPO / "tools" / "cycles" / "render.py",
         "threejs": REPO / "tools" / "threejs_gltf" / "render.mjs",
         "sample_viewer": REPO / "tools" / "sample_viewer" / "render.mjs"}
TIMEOUT_S = {"cycles": 3600, "threejs": 600, "sample_viewer": 600}
# what each tool is given beyond the view: the Sample Viewer multisamples as model-viewer's
# canvas and three.js do (tools/sample_viewer/render.mjs "msaa"; three.js's tool always does)
VIEW_EXTRAS = {"sample_viewer": {"msaa": 4}}
# whose linear output holds colour premultiplied by alpha (pbrlab's target is cleared to 0 and
# blended ONE / ONE_MINUS_SRC_ALPHA, its multisample resolve averages over the cleared samples;
# Cycles' film is premultiplied: tools/cycles/README.md); the peers' tools divide it out already
PREMULTIPLIED = ("pbrlab", "cycles")


def straight(linear: np.ndarray) -> np.ndarray:
    """Colour divided by alpha where alpha > 0: what display.display_rgba8 takes."""
    alpha = linear[..., 3:4]
    colour = np.where(alpha > 0, linear[..., :3] / np.where(alpha > 0, alpha, 1.0), linear[..., :3])
    return np.concatenate([colour, alpha], axis=-1).astype(np.float32)
# where a Python with PyPI's bpy (Blender as a module; Python 3.11) is found
BPY_PYTHON_ENV = "PBRLAB_BPY_PYTHON"
BPY_PYTHON_DEFAULT = REPO / ".venv-bpy" / "bin" / "python"
BPY_SETUP = ("run `bash scripts/setup_cycles.sh` in the checkout (a Python 3.11 virtualenv .venv-bpy with "
             f"PyPI's bpy 5.0.1), or point {BPY_PYTHON_ENV} at a Python that can `import bpy`")


def bpy_python() -> Path:
    path = Path(os.environ.get(BPY_PYTHON_ENV) or BPY_PYTHON_DEFAULT)
    if not path.is_file():
        raise PbrlabError(f"Cycles references need Blender's bpy, and {path} does not exist: {BPY_SETUP}")
    return path


def missing_setup(renderer: str) -> list[str]:
    """What ``renderer`` needs and does not find here (empty when it can run)."""
    if renderer == "pbrlab":
        return []
    missing = [] if TOOLS[renderer].is_file() else [f"{TOOLS[renderer]} is missing"]
    if renderer == "cycles":
        path = Path(os.environ.get(BPY_PYTHON_ENV) or BPY_PYTHON_DEFAULT)
        if not path.is_file():
            missing.append(f"no Python with bpy at {path} ({BPY_SETUP})")
    else:
        if shutil.which("node") is None:
            missing.append("node (Debian package nodejs) is not on PATH")
        if not (TOOLS[renderer].parent / "node_modules").is_dir():
            missing.append(f"{TOOLS[renderer].parent}/node_modules is missing (in a pbrlab checkout: "
                           "bash scripts/setup.sh; elsewhere npm ci in that folder)")
    return missing


def render_pbrlab(view: dict, render: dict | None = None) -> np.ndarray:
    """pbrlab's linear image of ``view`` (``render``: the scene's render block)."""
    from ...importers.loader import parse_scene
    from ...render.renderer import render_scene

    camera = view["camera"]
    data = {"camera": {"position": camera["eye"], "target": camera["target"], "up": camera["up"],
                       "fov_y_deg": camera["yfov_deg"], "size": list(view["size"])},
            "environment": {"path": view["environment"]},
            "objects": [{"gltf": view["gltf"]}],
            "render": dict(render or {})}
    scene = parse_scene(data, origin=f"fidelity view of {view['gltf']}", base=Path(view["gltf"]).parent)
    return np.ascontiguousarray(render_scene(scene).linear, np.float32)


def _command(renderer: str, spec_path: Path, out: Path) -> list[str]:
    if renderer == "cycles":
        return [str(bpy_python()), str(TOOLS["cycles"]), str(spec_path), str(out)]
    return ["node", str(TOOLS[renderer]), str(spec_path), str(out)]


def render_external(renderer: str, view: dict, keep: Path | None = None) -> tuple[np.ndarray, dict]:
    """``renderer``'s linear image of ``view`` and what its tool reported (OUT.json)."""
    missing = missing_setup(renderer)
    if missing:
        raise PbrlabError(f"{renderer} cannot run here: " + "; ".join(missing))
    width, height = view["size"]
    with tempfile.TemporaryDirectory(prefix=f"pbrlab-fidelity-{renderer}-") as tmp:
        folder = Path(keep) if keep else Path(tmp)
        folder.mkdir(parents=True, exist_ok=True)
        spec_path, out = Path(tmp) / "view.json", folder / renderer
        spec_path.write_text(json.dumps({**view, **VIEW_EXTRAS.get(renderer, {})}), encoding="utf-8")
        # its own process group: a timeout ends the tool and what it started (a browser)
        proc = subprocess.Popen(_command(renderer, spec_path, out), stdout=subprocess.PIPE,
                                stderr=subprocess.PIPE, text=True, start_new_session=True)
        try:
            stdout, stderr = proc.communicate(timeout=TIMEOUT_S[renderer])
        except subprocess.TimeoutExpired:
            os.killpg(proc.pid, signal.SIGKILL)
            proc.communicate()
            raise PbrlabError(f"{renderer} did not finish {view['gltf']} within {TIMEOUT_S[renderer]} s") from None
        if proc.returncode != 0:
            raise PbrlabError(f"{renderer} failed on {view['gltf']} (exit {proc.returncode}):\n"
                              f"{(stderr or stdout).strip()[-4000:]}")
        meta = json.loads(out.with_suffix(".json").read_text(encoding="utf-8"))
        pixels = np.fromfile(out.with_suffix(".f32"), np.float32)
    if pixels.size != width * height * 4:
        raise PbrlabError(f"{renderer} returned {pixels.size} floats for {view['gltf']}, "
                          f"expected {width}x{height}x4")
    return pixels.reshape(height, width, 4), meta


def render(renderer: str, view: dict, render_block: dict | None = None) -> tuple[np.ndarray, dict]:
    """(linear image with STRAIGHT colour, facts) of ``view`` by ``renderer`` (one of RENDERERS)."""
    if renderer == "pbrlab":
        from ...foundation.version import __version__
        image, facts = render_pbrlab(view, render_block), {"renderer": f"pbrlab {__version__}",
                                                           "render": dict(render_block or {})}
    elif renderer in TOOLS:
        image, facts = render_external(renderer, view)
    else:
        raise PbrlabError(f"unknown renderer {renderer!r}: expected one of {', '.join(RENDERERS)}")
    return (straight(image) if renderer in PREMULTIPLIED else image), facts


if __name__ == "__main__":  # python -m ...renderers VIEW.json RENDERER: a quick look
    view_file, name = sys.argv[1], sys.argv[2]
    image, facts = render(name, json.loads(Path(view_file).read_text()))
    print(image.shape, facts)
