"""What each quality tier costs in the whole lit pixel (issue 35): static RDNA3 / RDNA2 / GCN5
instructions and VGPRs of `pbrlab render`'s specialised GLSL program for the metallic-roughness
class with one light (Mesa RADV/ACO on a null device: no GPU, nothing runs; pbrlab.bench.gpu's
ACO_NOTE says what the figures are), per tier, with the parts that no tier changes measured by
removing them from the program's text: the light (PBRLAB_DIRECTIONAL_COUNT 0) and the
environment (PBRLAB_ENV undefined).

Scenes: the whole-program bench's metallic-roughness class (pbrlab.bench.peer_gltf: a textured
sphere mesh with base colour, metallic-roughness and normal maps, one directional light, under
the sunrise HDR; the class issue 35's LOW <= 0.7x HIGH is stated for), a metallic-workflow torus
(a mesh without maps: the sphere impostor's ray intersection would add its own cost) under a
uniform environment colour, and the fidelity benchmark's DamagedHelmet (base colour,
metallic-roughness, normal, occlusion and emission maps) under the sunrise HDR; the last two
with this file's directional light. The programs are the production ones (`pbrlab render`'s,
without the checking program's NaN/Inf test: gpu.scene_programs(..., checking=False)).

Image error of each tier (rendered on this machine's OpenGL, linear radiance, covered pixels;
relative error of the luminance, median / p99 / max, and the share of pixels more than 1 %
off): the torus against the float64 CPU renderer (pbrlab.render.cpu_render: a constant
environment, an untextured mesh) drawing the exact model (quality high, with its
multiple-scattering compensation); the class and DamagedHelmet against HIGH's own image,
since no float64 path covers texture maps and an HDR environment. A benchmark: it prints figures and asserts
nothing.

    python benchmarks/tier_program_cost.py
"""

from __future__ import annotations

import dataclasses
import functools
from pathlib import Path

import numpy as np

from pbrlab.bench import gpu
from pbrlab.checking.fidelity import staging
from pbrlab.importers.loader import parse_scene

ROOT = Path(__file__).resolve().parents[1]
HELMET = ROOT / "corpus/gltf/khronos/DamagedHelmet/DamagedHelmet.glb"
LIGHT = {"type": "directional", "direction": [0.4, -0.8, -0.5], "color": [1, 1, 1], "intensity": 1.4}
CAMERA = {"position": [0, 0, 3], "target": [0, 0, 0], "size": [64, 64]}
QUALITIES = ("high", "medium", "low")
PARTS = {"whole pixel": (), "without the light": (("#define PBRLAB_DIRECTIONAL_COUNT 1", "#define PBRLAB_DIRECTIONAL_COUNT 0"),),
         "without the environment": (("#define PBRLAB_ENV 1\n", "\n"),)}


CLASS = "metallic-roughness class"


@functools.lru_cache(maxsize=1)
def _class_scene():
    """The whole-program bench's metallic-roughness file (pbrlab.bench.peer_gltf), loaded as
    pbrlab.bench.peer_programs loads it (sunrise HDR), at 64 x 64; written and loaded once per
    process (each tier is a copy with its own quality)."""
    import tempfile

    from pbrlab.bench import peer_gltf
    from pbrlab.importers.gltf import load_gltf
    from pbrlab.scene.model import Environment

    folder = Path(tempfile.mkdtemp(prefix="pbrlab-tier-class-"))
    path, _ = peer_gltf.write(folder, "metallic-roughness", 1)
    environment = Environment(path=staging.ENVIRONMENTS_DIR / "sunrise.exr")
    return load_gltf(path, environment=environment, size=(64, 64), emit_warnings=False).scene


def _scene(name: str, quality: str):
    if name == CLASS:
        scene = _class_scene()
        return dataclasses.replace(scene, render=dataclasses.replace(scene.render, quality=quality))
    if name == "metallic torus":
        return parse_scene({"camera": CAMERA, "lights": [LIGHT], "environment": {"color": [0.05, 0.06, 0.08]},
                            "materials": {"m": {"workflow": "metallic", "albedo": [0.7, 0.08, 0.05], "metallic": 0.5,
                                                "smoothness": 0.6}},
                            "objects": [{"mesh": {"primitive": "torus", "major_radius": 0.6, "minor_radius": 0.2},
                                         "material": "m"}],
                            "render": {"quality": quality}}, origin=f"{name} ({quality})", base=ROOT)
    return parse_scene({"camera": CAMERA, "lights": [LIGHT],
                        "environment": {"path": str(staging.ENVIRONMENTS_DIR / "sunrise.exr")},
                        "objects": [{"gltf": str(HELMET)}], "render": {"quality": quality}},
                       origin=f"{name} ({quality})", base=HELMET.parent)


def figures(name: str, families=gpu.GPU_FAMILIES) -> dict:
    """{(quality, part): {family: (instructions, VGPRs)}} of the scene's largest program."""
    jobs = {}
    for quality in QUALITIES:
        for index, program in enumerate(gpu.scene_programs(_scene(name, quality), "specialised", checking=False)):
            job = program.job("glsl")
            for part, edits in PARTS.items():
                text = job.fragment
                for old, new in edits:
                    if old not in text:
                        raise SystemExit(f"'{old.strip()}' is not in the program: update this benchmark")
                    text = text.replace(old, new)
                jobs[(quality, part, index)] = dataclasses.replace(job, fragment=text)
    keyed = {"|".join(map(str, key)): job for key, job in jobs.items()}
    compiled = gpu._compile(keyed, families)
    out = {}
    for (quality, part, index) in jobs:
        for family in families:
            stats = compiled[family][f"{quality}|{part}|{index}"]
            best = out.setdefault((quality, part), {}).get(family, (0, 0))
            if stats["Instructions"] > best[0]:
                out[(quality, part)][family] = (stats["Instructions"], stats["VGPRs"])
    return out


def _luminance(rgb):
    return rgb[..., :3] @ np.array([0.2126, 0.7152, 0.0722])


def image_errors(name: str) -> dict:
    """{quality: (median, p99, max, share over 1 %)} of the relative luminance error of each
    tier's render against the reference named in the module's docstring."""
    from pbrlab.gpu import gl
    from pbrlab.render.renderer import render_scene

    ctx = gl.shared_context()
    images = {q: render_scene(_scene(name, q), ctx).linear.astype(np.float64) for q in QUALITIES}
    if name == "metallic torus":
        from pbrlab.render.cpu_render import render_scene_cpu
        reference = render_scene_cpu(_scene(name, "high"))
    else:
        reference = images["high"]
    covered = (reference[..., 3] > 0) & np.all([im[..., 3] > 0 for im in images.values()], axis=0)
    ref = _luminance(reference[covered])
    out = {}
    for quality, image in images.items():
        rel = np.abs(_luminance(image[covered]) - ref) / np.maximum(ref, 1e-6)
        out[quality] = (float(np.median(rel)), float(np.percentile(rel, 99)), float(rel.max()),
                        float((rel > 0.01).mean()))
    return out


def main() -> None:
    gpu.require_null_device()
    families = gpu.GPU_FAMILIES
    print("largest specialised GLSL program, instructions / VGPRs (x HIGH's whole pixel) per family "
          + " / ".join(gpu.TITLES[f] for f in families))
    for name in (CLASS, "metallic torus", "DamagedHelmet"):
        per = figures(name, families)
        for (quality, part), by_family in per.items():
            high = per[("high", "whole pixel")]
            print(f"  {name:24s} {quality:6s} {part:24s} " + "  ".join(
                f"{gpu.TITLES[f]} {i:4d} / {v:2d} ({i / high[f][0]:.3f}x)" for f, (i, v) in by_family.items()))
    print("image error, relative luminance error per covered pixel: median / p99 / max (share > 1 %)")
    for name, against in ((CLASS, "HIGH's image"), ("metallic torus", "the float64 CPU renderer's exact model"),
                          ("DamagedHelmet", "HIGH's image")):
        for quality, (median, p99, worst, share) in image_errors(name).items():
            print(f"  {name:24s} {quality:6s} against {against}: {median:.2e} / {p99:.2e} / {worst:.2e} "
                  f"({share:.1%})")


if __name__ == "__main__":
    main()
