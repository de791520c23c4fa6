"""The glTF Render Fidelity protocol's scenarios, and the one view every renderer is given.

A scenario (the protocol's config.json entry; defaults from the Khronos
glTF-Render-Fidelity-Generator's src/config-reader.ts) names a model, a lighting, image
dimensions, an orbit camera (theta, phi in degrees, radius) around a target and a vertical
field of view. The camera (model-viewer's orbit; the protocol's Cycles renderer,
test/renderers/blender-cycles/render.py, parents the camera at (0, 0, radius) to an empty at
the target rotated by Euler X = phi, Z = theta in Blender's Z-up frame) sits at

    eye = target + radius * (sin(phi) sin(theta), cos(phi), sin(phi) cos(theta))   (glTF, +Y up)

looking at the target with +Y up. A radius of 0 puts the eye at the target, looking along
-(that direction) (the protocol's MetalRoughSpheresNoTextures and Sponza do this).

Differences from the protocol, each stated where the benchmark reports:
* the environments are Blender's CC0 studio lights (lighting names, ENVIRONMENTS), as linear
  RGBE-quantised radiance so every renderer sees exactly the same values;
* the background is always transparent (renderSkybox is ignored): the models are scored;
* ``scale`` multiplies the dimensions (Cycles on two CPU cores: the committed benchmark
  runs at a quarter of the protocol's size).
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ...foundation.errors import PbrlabError

# config-reader.ts: defaultScenario
DEFAULT_DIMENSIONS = (768, 768)
DEFAULT_TARGET = (0.0, 0.0, 0.0)
DEFAULT_ORBIT = {"theta": 0.0, "phi": 90.0, "radius": 1.0}
DEFAULT_FOV_DEG = 45.0
# the protocol's Cycles renderer: clip_start = 2 R / 1000 with R = max(radius, bounding radius)
NEAR_PER_RADIUS = 2.0 / 1000.0
FAR_MARGIN = 1.05  # far plane beyond the farthest point of the model's bounding sphere

REPO = Path(__file__).resolve().parents[4]
BENCHMARK_DIR = REPO / "benchmarks" / "fidelity"
SCENARIOS_FILE = BENCHMARK_DIR / "scenarios.json"


@dataclass(frozen=True)
class Scenario:
    name: str
    model: Path
    lighting: str
    dimensions: tuple[int, int]
    target: tuple[float, float, float]
    theta: float
    phi: float
    radius: float
    fov_deg: float

    @property
    def key(self) -> str:
        """scene@lighting: one row of the benchmark."""
        return f"{self.name}@{self.lighting}"

    def size(self, scale: float) -> tuple[int, int]:
        return tuple(max(1, int(round(d * scale))) for d in self.dimensions)


def orbit_direction(theta_deg: float, phi_deg: float) -> np.ndarray:
    """Unit vector from the target to the eye (glTF frame)."""
    t, p = math.radians(theta_deg), math.radians(phi_deg)
    return np.array([math.sin(p) * math.sin(t), math.cos(p), math.sin(p) * math.cos(t)])


def camera_of(scenario: Scenario, bounds: tuple[np.ndarray, np.ndarray]) -> dict:
    """The shared view spec's camera: eye, target, up, yfov_deg, znear, zfar. ``bounds``: the
    model's world-space axis-aligned bounds (for the clip planes)."""
    target = np.array(scenario.target, np.float64)
    direction = orbit_direction(scenario.theta, scenario.phi)
    eye = target + scenario.radius * direction
    look_at = target if scenario.radius > 0 else eye - direction
    lo, hi = (np.asarray(b, np.float64) for b in bounds)
    centre, bounding = (lo + hi) / 2, float(np.linalg.norm(hi - lo)) / 2
    reach = max(scenario.radius, bounding, 1e-5)
    far = (float(np.linalg.norm(eye - centre)) + bounding) * FAR_MARGIN
    return {"eye": eye.tolist(), "target": look_at.tolist(), "up": [0.0, 1.0, 0.0],
            "yfov_deg": scenario.fov_deg, "znear": NEAR_PER_RADIUS * reach, "zfar": max(far, 2 * reach)}


def _number(entry, key, default, where):
    value = entry.get(key, default)
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        raise PbrlabError(f"{where}: {key} must be a number, got {value!r}")
    return float(value)


def read_scenarios(path: Path = SCENARIOS_FILE) -> list[Scenario]:
    """Every (scenario, lighting) of a scenarios file.

    The file: {"lightings": [names], "scenarios": [protocol entries]}; an entry's "lighting"
    (a name or a list of names) replaces the file's list; "model" is relative to the file."""
    path = Path(path)
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except FileNotFoundError:
        raise PbrlabError(f"{path}: no such scenarios file") from None
    except json.JSONDecodeError as exc:
        raise PbrlabError(f"{path}:{exc.lineno}: invalid JSON: {exc.msg}") from None
    if not isinstance(data, dict) or not isinstance(data.get("scenarios"), list):
        raise PbrlabError(f"{path}: expected an object with a \"scenarios\" list")
    lightings = data.get("lightings", [])
    out, seen = [], set()
    for index, entry in enumerate(data["scenarios"]):
        where = f"{path}: scenarios[{index}]"
        if not isinstance(entry, dict) or not isinstance(entry.get("name"), str) or not entry["name"]:
            raise PbrlabError(f"{where}: expected an object with a \"name\"")
        where = f"{path}: scenario {entry['name']!r}"
        unknown = set(entry) - {"name", "model", "lighting", "dimensions", "target", "orbit", "verticalFoV",
                                "renderSkybox", "exclude", "note"}
        if unknown:
            raise PbrlabError(f"{where}: unknown keys {sorted(unknown)}")
        if not isinstance(entry.get("model"), str):
            raise PbrlabError(f"{where}: \"model\" (a path relative to the file) is missing")
        model = (path.parent / entry["model"]).resolve()
        if not model.is_file():
            raise PbrlabError(f"{where}: model {model} does not exist")
        dims = {"width": DEFAULT_DIMENSIONS[0], "height": DEFAULT_DIMENSIONS[1], **entry.get("dimensions", {})}
        target = {"x": 0.0, "y": 0.0, "z": 0.0, **entry.get("target", {})}
        orbit = {**DEFAULT_ORBIT, **entry.get("orbit", {})}
        width, height = (int(_number(dims, k, None, where)) for k in ("width", "height"))
        if width < 1 or height < 1:
            raise PbrlabError(f"{where}: dimensions must be at least 1 pixel")
        radius = _number(orbit, "radius", None, where)
        if radius < 0:
            raise PbrlabError(f"{where}: orbit radius must be >= 0, got {radius}")
        names = entry.get("lighting", lightings)
        names = [names] if isinstance(names, str) else names
        if not names or not all(isinstance(n, str) for n in names):
            raise PbrlabError(f"{where}: no lighting (give \"lighting\" or the file's \"lightings\")")
        for lighting in names:
            scenario = Scenario(
                name=entry["name"], model=model, lighting=lighting, dimensions=(width, height),
                target=tuple(_number(target, k, None, where) for k in "xyz"),
                theta=_number(orbit, "theta", None, where), phi=_number(orbit, "phi", None, where),
                radius=radius, fov_deg=_number(entry, "verticalFoV", DEFAULT_FOV_DEG, where))
            if scenario.key in seen:
                raise PbrlabError(f"{where}: {scenario.key} appears twice")
            seen.add(scenario.key)
            out.append(scenario)
    return out


ENVIRONMENTS_DIR = BENCHMARK_DIR / "environments"


def prepare_environment(name: str, folder: Path) -> dict:
    """The lighting ``name`` (ENVIRONMENTS_DIR/<name>.exr, an equirect in pbrlab's convention)
    as every renderer reads it: quantised once to Radiance RGBE (the Sample Viewer reads .hdr
    only) and the decoded values written back as a float EXR for the others, so all four see
    exactly the same radiance. Returns {"environment": exr, "environment_hdr": hdr}."""
    from ...foundation import images
    from ..sample_viewer import write_radiance_hdr

    source = ENVIRONMENTS_DIR / f"{name}.exr"
    if not source.is_file():
        known = sorted(p.stem for p in ENVIRONMENTS_DIR.glob("*.exr"))
        raise PbrlabError(f"unknown lighting {name!r}: no {source} (known: {', '.join(known)})")
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    exr, hdr = folder / f"{name}.exr", folder / f"{name}.hdr"
    if not (exr.is_file() and hdr.is_file()):
        radiance = images.read_image(source)[..., :3].astype(np.float64)
        decoded = write_radiance_hdr(hdr, radiance)
        images.write_exr(exr, np.ascontiguousarray(decoded, np.float32))
    return {"environment": str(exr), "environment_hdr": str(hdr)}


def model_bounds(model: Path) -> tuple[np.ndarray, np.ndarray]:
    """World-space bounds of the glTF's default scene, as pbrlab's importer places it."""
    from ...importers.gltf import load_gltf
    from ...importers.gltf.extent import bounds

    return bounds(load_gltf(model).scene)


def view_spec(scenario: Scenario, scale: float, environment: dict, bounds,
              samples: int = 128, seed: int = 0, denoise: bool = True) -> dict:
    """The one view every renderer is given (tools/*/render.* read it)."""
    return {"gltf": str(scenario.model), **environment, "size": list(scenario.size(scale)),
            "camera": camera_of(scenario, bounds), "samples": int(samples), "seed": int(seed),
            "denoise": bool(denoise)}
