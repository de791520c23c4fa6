"""Path-traced reference render of one fidelity "view spec" with Blender Cycles (CPU).

    /work/bpyvenv/bin/python tools/cycles/render.py SPEC.json OUT [--threads N] [--set KEY=VALUE ...]

writes OUT.f32 (float32 RGBA, rows top to bottom, linear scene radiance, PREMULTIPLIED
alpha: the colour of a pixel is the radiance it receives, already weighted by its
coverage; alpha = coverage) and OUT.json (size, renderer, samples, seed, denoise, seconds,
threads, and the Cycles settings used). The view spec is described in /work/fidelity_spec.md
(issue 38): gltf, environment, size, camera {eye, target, up, yfov_deg, znear, zfar},
samples, seed, denoise.

Runs with the `bpy` module (Blender as a Python module, `pip install bpy` in a Python 3.11
virtualenv); see tools/cycles/README.md. Bad input (a missing file, a bad spec, a glTF the
importer refuses) ends with one line on stderr naming the file, exit status 2.

Conventions (why each setting is what it is):
- glTF is +Y up, Blender +Z up; Blender's glTF importer converts (x, y, z)_gltf to
  (x, -z, y)_blender (the importer's Yup2Zup conversion), and so does this script for the
  camera.
- Environment: Cycles' equirectangular lookup (direction_to_equirectangular in Blender's
  intern/cycles/kernel/camera/projection.h: range (-2pi, pi, -pi, pi)) is
  u = 0.5 - atan2(d.y, d.x) / (2 pi), v_from_top = acos(d.z) / pi, in Blender axes.
  pbrlab's (harness/pbrlab/scene/environment.py) is u = atan2(x, -z) / (2 pi),
  v_from_top = acos(y) / pi in glTF axes = atan2(bx, by) / (2 pi), acos(bz) / pi in Blender
  axes, and atan2(bx, by) = pi/2 - atan2(by, bx), so u_pbrlab(d) = u_cycles(d) - 1/4 and
  the v's agree. u_cycles decreases by a / (2 pi) when d turns by a about +Z, so looking up
  Rz(+90 deg) d gives pbrlab's image: a Mapping node of type POINT (which applies its
  rotation to the vector) with rotation (0, 0, 90 deg). Proven by orientation_proof.py on a
  mirror sphere (README).
"""

from __future__ import annotations

import json
import math
import resource
import sys
import tempfile
import time
from pathlib import Path
from typing import NoReturn

import numpy as np


class SpecError(Exception):
    """Bad input: reported as one line, no traceback."""


def _fail(message: str) -> NoReturn:
    print(f"tools/cycles/render.py: {message}", file=sys.stderr)
    sys.exit(2)


def _vec3(value, what: str, spec_path: Path) -> tuple[float, float, float]:
    if (not isinstance(value, (list, tuple)) or len(value) != 3
            or not all(isinstance(c, (int, float)) and not isinstance(c, bool) and math.isfinite(c) for c in value)):
        raise SpecError(f"{spec_path}: {what} must be 3 finite numbers, got {value!r}")
    return tuple(float(c) for c in value)


def _number(value, what: str, spec_path: Path, positive: bool = True) -> float:
    if not isinstance(value, (int, float)) or isinstance(value, bool) or not math.isfinite(value) or (positive and value <= 0):
        raise SpecError(f"{spec_path}: {what} must be a {'positive ' if positive else ''}finite number, got {value!r}")
    return float(value)


def _integer(value, what: str, spec_path: Path, minimum: int) -> int:
    if not isinstance(value, int) or isinstance(value, bool) or value < minimum:
        raise SpecError(f"{spec_path}: {what} must be an integer >= {minimum}, got {value!r}")
    return value


def _existing_file(value, what: str, spec_path: Path) -> Path:
    if not isinstance(value, str) or not value:
        raise SpecError(f"{spec_path}: {what} must be a file path, got {value!r}")
    path = Path(value)
    if not path.is_absolute():
        path = spec_path.parent / path  # a relative path is relative to the spec's folder
    if not path.is_file():
        raise SpecError(f"{spec_path}: {what} file not found: {path}")
    return path


def read_spec(spec_path: Path) -> dict:
    """The view spec, checked; every problem is a SpecError naming the file and the key."""
    if not spec_path.is_file():
        raise SpecError(f"view spec not found: {spec_path}")
    try:
        spec = json.loads(spec_path.read_text())
    except (OSError, UnicodeDecodeError, json.JSONDecodeError) as exc:
        raise SpecError(f"{spec_path}: not a readable JSON view spec ({exc})") from None
    if not isinstance(spec, dict):
        raise SpecError(f"{spec_path}: the view spec must be a JSON object")
    for key in ("gltf", "environment", "size", "camera"):
        if key not in spec:
            raise SpecError(f"{spec_path}: missing key {key!r}")
    size = spec["size"]
    if not isinstance(size, list) or len(size) != 2:
        raise SpecError(f"{spec_path}: size must be [width, height], got {size!r}")
    width, height = (_integer(s, "size", spec_path, 1) for s in size)
    camera = spec["camera"]
    if not isinstance(camera, dict):
        raise SpecError(f"{spec_path}: camera must be an object")
    for key in ("eye", "target", "yfov_deg", "znear", "zfar"):
        if key not in camera:
            raise SpecError(f"{spec_path}: camera is missing {key!r}")
    eye = _vec3(camera["eye"], "camera.eye", spec_path)
    target = _vec3(camera["target"], "camera.target", spec_path)
    up = _vec3(camera.get("up", [0, 1, 0]), "camera.up", spec_path)
    yfov = _number(camera["yfov_deg"], "camera.yfov_deg", spec_path)
    if yfov >= 180:
        raise SpecError(f"{spec_path}: camera.yfov_deg must be below 180, got {yfov}")
    znear = _number(camera["znear"], "camera.znear", spec_path)
    zfar = _number(camera["zfar"], "camera.zfar", spec_path)
    if zfar <= znear:
        raise SpecError(f"{spec_path}: camera.zfar ({zfar}) must exceed camera.znear ({znear})")
    forward = np.subtract(target, eye)
    if np.linalg.norm(forward) == 0:
        raise SpecError(f"{spec_path}: camera.eye and camera.target are the same point")
    if np.linalg.norm(np.cross(forward, up)) <= 1e-9 * np.linalg.norm(forward) * np.linalg.norm(up):
        raise SpecError(f"{spec_path}: camera.up is zero or parallel to the view direction")
    denoise = spec.get("denoise", True)
    if not isinstance(denoise, bool):
        raise SpecError(f"{spec_path}: denoise must be true or false, got {denoise!r}")
    return {
        "gltf": _existing_file(spec["gltf"], "gltf", spec_path),
        "environment": _existing_file(spec["environment"], "environment", spec_path),
        "size": (width, height),
        "eye": eye, "target": target, "up": up, "yfov_deg": yfov, "znear": znear, "zfar": zfar,
        "samples": _integer(spec.get("samples", 128), "samples", spec_path, 1),
        "seed": _integer(spec.get("seed", 0), "seed", spec_path, 0),
        "denoise": denoise,
    }


def gltf_to_blender(v) -> tuple[float, float, float]:
    """(x, y, z) in glTF axes (+Y up) -> Blender axes (+Z up): (x, -z, y), as the importer."""
    x, y, z = v
    return (x, -z, y)


# Light paths. Cycles' defaults (max 12, diffuse 4, glossy 4, transmission 12,
# transparent 8) cut glass short: a ray through a thick glass object leaves after 2
# transmissions, one through a glass shell (front and back faces, each two interfaces) after
# 4, and a reflection seen through glass needs glossy bounces on top; a mirror-like
# surface seen in another mirror-like surface (helmet visor, metal in metal) needs more
# glossy bounces than 4. Russian roulette ends paths that carry little, so generous caps
# cost little where they are not needed.
LIGHT_PATHS = {
    "max_bounces": 32,
    "diffuse_bounces": 8,
    "glossy_bounces": 16,
    "transmission_bounces": 32,
    "transparent_max_bounces": 32,  # alpha-blended / cut-out layers (Transparent BSDF)
    "volume_bounces": 4,            # KHR_materials_volume absorption inside glass
    "caustics_reflective": True,    # Cycles' defaults, stated: the reference keeps caustics
    "caustics_refractive": True,
    "blur_glossy": 0.0,             # no "filter glossy" bias (Cycles' default is 1.0)
    "sample_clamp_direct": 0.0,     # no clamping: the reference is unbiased
    "sample_clamp_indirect": 0.0,   # (Cycles' default clamps indirect at 10)
}


def parse_overrides(pairs: list[str]) -> dict:
    """--set KEY=VALUE for the LIGHT_PATHS settings (for noise studies); recorded in OUT.json."""
    overrides = {}
    for pair in pairs:
        key, sep, text = pair.partition("=")
        if not sep or key not in LIGHT_PATHS:
            raise SpecError(f"--set {pair!r}: expected KEY=VALUE with KEY one of {', '.join(LIGHT_PATHS)}")
        kind = type(LIGHT_PATHS[key])
        try:
            if kind is bool:
                if text.lower() not in ("true", "false", "1", "0"):
                    raise ValueError
                value = text.lower() in ("true", "1")
            else:
                value = kind(text)
                if value < 0:
                    raise ValueError
        except ValueError:
            raise SpecError(f"--set {pair!r}: {key} takes a non-negative {kind.__name__}") from None
        overrides[key] = value
    return overrides


def _build_scene(bpy, spec: dict, light_paths: dict) -> None:
    from mathutils import Matrix, Vector

    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene

    gltf = spec["gltf"]
    try:
        result = bpy.ops.import_scene.gltf(filepath=str(gltf))
    except RuntimeError as exc:  # the importer reports its errors as RuntimeError
        message = " ".join(str(exc).split())
        raise SpecError(f"Blender's glTF importer failed on {gltf}: {message}") from None
    if "FINISHED" not in result:
        raise SpecError(f"Blender's glTF importer failed on {gltf} (result {sorted(result)})")
    if not any(o.type == "MESH" for o in scene.objects):
        raise SpecError(f"{gltf}: the glTF's scene has no mesh to render")

    # Camera: Blender cameras look down their local -Z with local +Y up.
    eye = Vector(gltf_to_blender(spec["eye"]))
    target = Vector(gltf_to_blender(spec["target"]))
    up = Vector(gltf_to_blender(spec["up"]))
    forward = (target - eye).normalized()
    right = forward.cross(up).normalized()
    true_up = right.cross(forward)
    rotation = Matrix((right, true_up, -forward)).transposed()  # columns: local X, Y, Z
    camera_data = bpy.data.cameras.new("fidelity_camera")
    camera_data.type = "PERSP"
    camera_data.sensor_fit = "VERTICAL"  # the FoV below is the vertical one, whatever the aspect
    camera_data.angle_y = math.radians(spec["yfov_deg"])
    camera_data.shift_x = camera_data.shift_y = 0.0
    camera_data.clip_start = spec["znear"]
    camera_data.clip_end = spec["zfar"]
    camera = bpy.data.objects.new("fidelity_camera", camera_data)
    camera.matrix_world = Matrix.Translation(eye) @ rotation.to_4x4()
    scene.collection.objects.link(camera)
    scene.camera = camera

    # World: the environment, in pbrlab's orientation (module docstring), strength 1.
    world = bpy.data.worlds.new("fidelity_world")
    scene.world = world
    if world.node_tree is None:  # Blender 5 gives new worlds a node tree; older ones need use_nodes
        world.use_nodes = True
    nodes, links = world.node_tree.nodes, world.node_tree.links
    nodes.clear()
    coords = nodes.new("ShaderNodeTexCoord")
    mapping = nodes.new("ShaderNodeMapping")
    mapping.vector_type = "POINT"
    mapping.inputs["Rotation"].default_value = (0.0, 0.0, math.pi / 2)
    env = nodes.new("ShaderNodeTexEnvironment")
    try:
        env.image = bpy.data.images.load(str(spec["environment"]), check_existing=False)
        env.image.colorspace_settings.name = "Linear Rec.709"  # the EXR holds linear Rec.709 radiance
        env.image.reload()
        if env.image.size[0] == 0:
            raise RuntimeError("not an image Blender can read")
    except RuntimeError as exc:
        raise SpecError(f"Blender cannot read the environment {spec['environment']}: {exc}") from None
    env.projection = "EQUIRECTANGULAR"
    env.interpolation = "Linear"
    background = nodes.new("ShaderNodeBackground")
    background.inputs["Strength"].default_value = 1.0
    output = nodes.new("ShaderNodeOutputWorld")
    links.new(coords.outputs["Generated"], mapping.inputs["Vector"])
    links.new(mapping.outputs["Vector"], env.inputs["Vector"])
    links.new(env.outputs["Color"], background.inputs["Color"])
    links.new(background.outputs["Background"], output.inputs["Surface"])

    # Render settings.
    render = scene.render
    render.engine = "CYCLES"
    render.resolution_x, render.resolution_y = spec["size"]
    render.resolution_percentage = 100
    render.pixel_aspect_x = render.pixel_aspect_y = 1.0
    render.film_transparent = True      # a camera ray that sees only the environment: alpha 0
    render.use_persistent_data = False
    cycles = scene.cycles
    cycles.device = "CPU"
    cycles.samples = spec["samples"]
    cycles.use_adaptive_sampling = False  # exactly spec.samples per pixel, everywhere
    cycles.seed = spec["seed"]
    cycles.use_animated_seed = False
    cycles.film_transparent_glass = False  # glass stays opaque: the environment is seen through it
    cycles.film_exposure = 1.0
    cycles.pixel_filter_type = "BLACKMAN_HARRIS"  # Cycles' default pixel filter, the protocol's
    cycles.filter_width = 1.5
    for key, value in light_paths.items():
        setattr(cycles, key, value)
    cycles.use_denoising = spec["denoise"]
    if spec["denoise"]:
        cycles.denoiser = "OPENIMAGEDENOISE"
        cycles.denoising_input_passes = "RGB_ALBEDO_NORMAL"
        cycles.denoising_prefilter = "ACCURATE"
        cycles.denoising_use_gpu = False
    # No display transform in the data: "Standard", exposure 0, gamma 1 (the EXR written
    # below is scene-linear whatever these say; they are set so nothing can scale it).
    scene.view_settings.view_transform = "Standard"
    scene.view_settings.look = "None"
    scene.view_settings.exposure = 0.0
    scene.view_settings.gamma = 1.0


def _render_to_array(bpy, threads: int | None) -> tuple[np.ndarray, int]:
    """Render; the result (HxWx4 float32, top row first, premultiplied) and the thread count."""
    scene = bpy.context.scene
    if threads:
        scene.render.threads_mode = "FIXED"
        scene.render.threads = threads
    else:
        scene.render.threads_mode = "AUTO"
    used_threads = scene.render.threads
    with tempfile.TemporaryDirectory(prefix="pbrlab_cycles_") as tmp:
        exr = Path(tmp) / "render.exr"
        settings = scene.render.image_settings
        settings.file_format = "OPEN_EXR"
        settings.color_mode = "RGBA"
        settings.color_depth = "32"
        settings.exr_codec = "ZIP"
        scene.render.filepath = str(exr)
        bpy.ops.render.render(write_still=True)
        if not exr.is_file():
            raise RuntimeError(f"Cycles wrote no image to {exr}")
        image = bpy.data.images.load(str(exr), check_existing=False)
        image.colorspace_settings.name = "Linear Rec.709"
        image.alpha_mode = "PREMUL"  # the EXR holds premultiplied RGBA: read it unchanged
        width, height = image.size
        pixels = np.empty(width * height * 4, np.float32)
        image.pixels.foreach_get(pixels)
        bpy.data.images.remove(image)
    # Blender's image rows run bottom to top.
    return pixels.reshape(height, width, 4)[::-1].copy(), used_threads


def main(argv: list[str]) -> int:
    args = list(argv)
    threads = None
    set_pairs = []
    while "--set" in args:
        i = args.index("--set")
        if i + 1 >= len(args):
            _fail("--set needs KEY=VALUE")
        set_pairs.append(args[i + 1])
        del args[i:i + 2]
    if "--threads" in args:
        i = args.index("--threads")
        try:
            threads = int(args[i + 1])
            if threads < 1:
                raise ValueError
        except (IndexError, ValueError):
            _fail("--threads needs a positive integer")
        del args[i:i + 2]
    if len(args) != 2:
        _fail("usage: render.py SPEC.json OUT [--threads N] [--set KEY=VALUE ...]  (writes OUT.f32 and OUT.json)")
    spec_path, out = Path(args[0]), args[1]
    if out.endswith(".f32"):
        out = out[:-4]
    out_f32, out_json = Path(out + ".f32"), Path(out + ".json")
    if not out_f32.parent.is_dir():
        _fail(f"output folder not found: {out_f32.parent}")
    if out_json.resolve() == spec_path.resolve():
        _fail(f"OUT.json would overwrite the view spec {spec_path}: choose another OUT")
    try:
        spec = read_spec(spec_path)
        light_paths = {**LIGHT_PATHS, **parse_overrides(set_pairs)}
    except SpecError as exc:
        _fail(str(exc))

    try:
        import bpy
    except ImportError:
        _fail("the bpy module is missing: run with a Python that has `pip install bpy` (tools/cycles/README.md)")

    wall0, cpu0 = time.perf_counter(), resource.getrusage(resource.RUSAGE_SELF)
    try:
        _build_scene(bpy, spec, light_paths)
    except SpecError as exc:
        _fail(str(exc))
    wall1 = time.perf_counter()
    linear, used_threads = _render_to_array(bpy, threads)
    wall2, cpu2 = time.perf_counter(), resource.getrusage(resource.RUSAGE_SELF)
    width, height = spec["size"]
    if linear.shape != (height, width, 4):
        raise RuntimeError(f"Cycles returned {linear.shape[1]}x{linear.shape[0]}, asked {width}x{height}")
    if not np.isfinite(linear).all():
        raise RuntimeError("Cycles' render holds non-finite values")

    out_f32.write_bytes(np.ascontiguousarray(linear, np.float32).tobytes())
    cycles = bpy.context.scene.cycles
    info = {
        "size": [width, height],
        "renderer": f"Blender {bpy.app.version_string} Cycles",
        "version": bpy.app.version_string,
        "device": "CPU",
        "samples": spec["samples"],
        "seed": spec["seed"],
        "denoise": "OpenImageDenoise (albedo + normal, accurate prefilter)" if spec["denoise"] else False,
        "seconds": round(wall2 - wall0, 3),
        "seconds_render": round(wall2 - wall1, 3),
        "cpu_seconds": round((cpu2.ru_utime + cpu2.ru_stime) - (cpu0.ru_utime + cpu0.ru_stime), 3),
        "threads": used_threads,
        "format": "float32 RGBA, rows top to bottom, linear scene radiance, premultiplied alpha "
                  "(colour already weighted by coverage), alpha = coverage",
        "pixel_filter": f"{cycles.pixel_filter_type} {cycles.filter_width} px",
        "adaptive_sampling": False,
        "light_paths": light_paths,
        "environment_mapping": "Mapping POINT rotation (0, 0, 90 deg) before Environment Texture: "
                               "pbrlab's equirect convention",
        "gltf": str(spec["gltf"]),
        "environment": str(spec["environment"]),
        "view_spec": str(spec_path.resolve()),
    }
    out_json.write_text(json.dumps(info, indent=1) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
