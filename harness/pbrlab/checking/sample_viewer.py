"""Khronos' glTF Sample Renderer as a second, independent renderer of glTF files.

    linear = render_with_sample_viewer("model.gltf", camera, environment="sky.hdr", size=(256, 128))

runs ``tools/sample_viewer/render.mjs`` (node, playwright-core, Debian's chromium with
WebGL2 on SwiftShader started by ``tools/chromium/launch.mjs``, npm ``@khronosgroup/gltf-viewer``) and returns its image as an
HxWx4 float32 array: linear radiance, rows top to bottom, alpha 0 where no surface is.
The viewer's own switch LINEAR_OUTPUT is on, so the values are read before its exposure,
tonemap and pow(1/2.2) encode; they are written to an RGBA32F target (no multisampling).

What the viewer is given: the glTF file itself (its materials, textures and
KHR_lights_punctual lights, read by the viewer's own importer), the camera (a pbrlab
``Camera``: position, target, up, vertical field of view; or a glTF camera index) and
the environment: a Radiance .hdr equirectangular image that the viewer prefilters itself
(Lambertian and GGX cubes, its GGX LUT), or None for punctual lights only. The viewer's
generated key and fill lights are off. With an environment its background is drawn into
the viewer's transmission copy, as the viewer does when it shows the environment, so that a
transmissive surface sees the environment where nothing opaque lies behind it; it is kept out
of the returned image (tools/sample_viewer/page/viewer.mjs), whose alpha still marks coverage.

``write_radiance_hdr`` writes an image as .hdr and returns the values the viewer decodes
from it (mantissa * 2^(exponent - 136)), so pbrlab can be given exactly the same radiance.

Set-up: ``bash scripts/setup.sh`` (apt-get install chromium; npm ci in tools/sample_viewer).
"""

from __future__ import annotations

import json
import math
import os
import shutil
import signal
import subprocess
import tempfile
from pathlib import Path

import numpy as np

from ..foundation import outputs
from ..foundation.errors import PbrlabError

SAMPLE_VIEWER_DIR = Path(os.environ.get("PBRLAB_SAMPLE_VIEWER_DIR")
                         or Path(__file__).resolve().parents[3] / "tools" / "sample_viewer")
CHROMIUM = Path(os.environ.get("PBRLAB_CHROMIUM", "/usr/bin/chromium"))
RENDER_TIMEOUT_S = 120  # one render takes a few seconds (browser start included)
# Depth range the viewer is given around the camera distance: a 24-bit depth buffer keeps
# ~1e-4 of the distance at these ratios, far below a pixel's footprint.
NEAR_FRACTION, FAR_FACTOR = 1e-3, 100.0
# The viewer's environment orientation (renderingParameters.environmentRotation, degrees)
# that matches pbrlab's equirect convention (pbrlab.scene.environment: the image centre looks
# at +Z); see tests/importers/gltf/test_sample_viewer_agreement.py for the check.
ENVIRONMENT_ROTATION_DEG = 90.0


def missing_setup() -> list[str]:
    """What the sample viewer needs and does not find (empty when it can run)."""
    missing = []
    if shutil.which("node") is None:
        missing.append("node (Debian package nodejs) is not on PATH")
    if not CHROMIUM.is_file():
        missing.append(f"{CHROMIUM} is missing (Debian package chromium)")
    for package in ("@khronosgroup/gltf-viewer", "playwright-core"):
        if not (SAMPLE_VIEWER_DIR / "node_modules" / package / "package.json").is_file():
            missing.append(f"npm package {package} is not installed in {SAMPLE_VIEWER_DIR}")
    if not (SAMPLE_VIEWER_DIR.parent / "chromium" / "launch.mjs").is_file():
        missing.append(f"{SAMPLE_VIEWER_DIR.parent / 'chromium' / 'launch.mjs'} (Chromium's start-up, "
                       "imported by render.mjs) is missing")
    return missing


def check_setup() -> None:
    missing = missing_setup()
    if missing:
        raise PbrlabError("the glTF Sample Viewer cannot run: " + "; ".join(missing)
                          + f". In a pbrlab checkout, run `bash scripts/setup.sh` (as root it installs chromium "
                          f"with apt-get and runs `npm ci` in {SAMPLE_VIEWER_DIR}); elsewhere install "
                          "chromium and nodejs, copy the checkout's tools/sample_viewer and tools/chromium side by "
                          "side, run `npm ci` in the copy of tools/sample_viewer and point "
                          "PBRLAB_SAMPLE_VIEWER_DIR at it. Then try again.")


def camera_spec(camera, size) -> dict:
    """The render.mjs camera of a pbrlab Camera (perspective): its camera-to-world matrix
    (the same basis as pbrlab.maths.camera.camera_frame), vertical field of view and planes."""
    if camera.ortho_half_height is not None:
        raise PbrlabError("the sample viewer front end takes perspective cameras only")
    position = np.asarray(camera.position, np.float64)
    forward = np.asarray(camera.target, np.float64) - position
    distance = float(np.linalg.norm(forward))
    forward /= distance
    right = np.cross(forward, np.asarray(camera.up, np.float64))
    right /= np.linalg.norm(right)
    up = np.cross(right, forward)
    to_world = np.eye(4)
    to_world[:3, 0], to_world[:3, 1], to_world[:3, 2], to_world[:3, 3] = right, up, -forward, position
    return {"cameraToWorld": to_world.T.reshape(-1).tolist(),  # column-major
            "yfovRad": math.radians(camera.fov_y_deg),
            "znear": distance * NEAR_FRACTION, "zfar": distance * FAR_FACTOR}


def render_with_sample_viewer(gltf_path, camera, environment=None, size=(256, 128), *,
                              environment_intensity: float = 1.0, keep: Path | None = None) -> np.ndarray:
    """The sample viewer's render of ``gltf_path`` (HxWx4 float32, linear, top row first).

    camera: a pbrlab Camera, or an int (the file's glTF camera of that index).
    environment: a Radiance .hdr file (see write_radiance_hdr), or None for punctual lights
        only. keep: a folder to leave OUT.png / OUT.f32 / OUT.json in (for looking at)."""
    check_setup()
    width, height = int(size[0]), int(size[1])
    spec = {"gltf": str(Path(gltf_path).resolve()), "size": [width, height],
            "camera": {"index": camera} if isinstance(camera, int) else camera_spec(camera, size),
            "environment": str(Path(environment).resolve()) if environment else None,
            "environmentIntensity": float(environment_intensity),
            "environmentRotationDeg": ENVIRONMENT_ROTATION_DEG}
    if environment and Path(environment).suffix.lower() != ".hdr":
        raise PbrlabError(f"{environment}: the sample viewer reads Radiance .hdr environments only "
                          "(pbrlab.checking.sample_viewer.write_radiance_hdr writes one)")
    with tempfile.TemporaryDirectory(prefix="pbrlab-sample-viewer-") as tmp:
        folder = Path(keep) if keep else Path(tmp)
        folder.mkdir(parents=True, exist_ok=True)
        spec_path, out = Path(tmp) / "spec.json", folder / Path(gltf_path).stem
        spec_path.write_text(json.dumps(spec), encoding="utf-8")
        # its own process group: a timeout ends node and the browser it started together
        node = subprocess.Popen(["node", str(SAMPLE_VIEWER_DIR / "render.mjs"), str(spec_path), str(out)],
                                stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                                start_new_session=True)
        try:
            stdout, stderr = node.communicate(timeout=RENDER_TIMEOUT_S)
        except subprocess.TimeoutExpired:
            os.killpg(node.pid, signal.SIGKILL)
            node.communicate()
            raise PbrlabError(f"the sample viewer did not finish {gltf_path} within {RENDER_TIMEOUT_S} s") from None
        run = subprocess.CompletedProcess(node.args, node.returncode, stdout, stderr)
        if run.returncode != 0:
            raise PbrlabError(f"the sample viewer failed on {gltf_path} (exit {run.returncode}):\n"
                              f"{(run.stderr or run.stdout).strip()}")
        meta = json.loads(out.with_suffix(".json").read_text(encoding="utf-8"))
        problems = [m for m in meta["messages"] if m.startswith("pageerror")]
        if problems:
            raise PbrlabError(f"the sample viewer reported errors on {gltf_path}:\n" + "\n".join(problems))
        pixels = np.fromfile(out.with_suffix(".f32"), np.float32)
    if pixels.size != width * height * 4:
        raise PbrlabError(f"the sample viewer returned {pixels.size} floats, expected {width * height * 4}")
    return pixels.reshape(height, width, 4)


def rgbe_encode(rgb: np.ndarray) -> np.ndarray:
    """Radiance RGBE bytes (HxWx4 uint8) of linear RGB (HxWx3), mantissas rounded to nearest."""
    rgb = np.maximum(np.nan_to_num(np.asarray(rgb, np.float64)[..., :3]), 0.0)
    peak = rgb.max(axis=-1)
    _, exponent = np.frexp(peak)  # peak = f * 2^exponent, f in [0.5, 1)
    scale = np.ldexp(1.0, 8 - exponent)  # mantissa = value * 256 / 2^exponent
    mantissa = np.rint(rgb * scale[..., None])
    overflow = mantissa.max(axis=-1) > 255  # rounding reached 256: one exponent up
    exponent = np.where(overflow, exponent + 1, exponent)
    mantissa = np.where(overflow[..., None], np.rint(rgb * (scale / 2)[..., None]), mantissa)
    out = np.zeros(rgb.shape[:-1] + (4,), np.uint8)
    lit = peak >= 1e-32
    out[..., :3] = np.where(lit[..., None], mantissa, 0).astype(np.uint8)
    out[..., 3] = np.where(lit, exponent + 128, 0).astype(np.uint8)
    return out


def rgbe_decode(rgbe: np.ndarray) -> np.ndarray:
    """What the viewer's _rgbeToFloat decodes: mantissa * 2^(exponent - 136), float32."""
    scale = np.ldexp(1.0, rgbe[..., 3].astype(np.int64) - 136)
    return (rgbe[..., :3] * scale[..., None]).astype(np.float32)


def write_radiance_hdr(path, rgb: np.ndarray) -> np.ndarray:
    """Write linear RGB (HxWx3) as an uncompressed Radiance .hdr; returns the decoded
    radiance (HxWx3 float32) the viewer will see, to give pbrlab the same values."""
    rgbe = rgbe_encode(rgb)
    height, width = rgbe.shape[:2]
    header = f"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y {height} +X {width}\n".encode("ascii")
    outputs.write_file(path, header + rgbe.tobytes())
    return rgbe_decode(rgbe)
