"""What the environment read's two corrections and the harness's checks cost in the whole
lit pixel: the horizon occlusion (render.horizon_occlusion, compiled where a normal can tilt),
the dominant direction (the pbrlab model's read along mix(r, n, alpha)), the checking
program's NaN/Inf test of the surface output (PBRLAB_CHECKING: `pbrlab render` compiles the
checking program, the production program leaves the test out) and the degenerate-tangent
fallback (PBRLAB_TANGENT_FALLBACK: compiled only for a mesh whose tangent frames can reach
it, pbrlab.render.tangent_frames), as static RDNA3 / RDNA2 / GCN5 instructions and VGPRs of
`pbrlab render`'s specialised programs (Mesa RADV/ACO on a null device: no GPU, nothing
runs; pbrlab.bench.gpu's ACO_NOTE says what the figures are).

Programs: the fidelity benchmark's DamagedHelmet (base colour, metallic-roughness, normal,
occlusion and emission maps under an environment), ClearCoatTest (a coat and its normal
map), SheenChair (sheen, normal maps; some of its meshes have tangents parallel to their
normals, so they keep the fallback) and TransmissionRoughnessTest (transmission, no normal
map: no tangent code to save); for each, the largest program of: the checking program
(`pbrlab render`'s, "as shipped"), the production program, the checking program with the
fallback compiled for every mesh (what every program had before the per-mesh decision), and
the checking program with horizon_occlusion off, and with the dominant read replaced by the
mirror direction in the program's text (that line alone). With ``--time``, the paired
llvmpipe cost too: process time of ``render_scene`` of DamagedHelmet and ClearCoatTest framed
at 512 x 512 with horizon occlusion on and off, interleaved after a warm-up of each, medians
(run with LP_NUM_THREADS=1 so llvmpipe shades on this process's thread). A benchmark: it
prints figures and asserts nothing.

    python benchmarks/environment_read_cost.py
    LP_NUM_THREADS=1 python benchmarks/environment_read_cost.py --time [--repeats 7]
"""

from __future__ import annotations

import argparse
import dataclasses
import os
import statistics
import time
from pathlib import Path

from pbrlab.bench import gpu
from pbrlab.checking.fidelity import staging
from pbrlab.gpu import gl
from pbrlab.importers.gltf import load_gltf
from pbrlab.importers.loader import parse_scene
from pbrlab.render import tangent_frames
from pbrlab.render.renderer import render_scene
from pbrlab.scene.model import Environment

ROOT = Path(__file__).resolve().parents[1]
MODELS = {"DamagedHelmet": ROOT / "corpus/gltf/khronos/DamagedHelmet/DamagedHelmet.glb",
          "ClearCoatTest": ROOT / "corpus/gltf/khronos/ClearCoatTest/ClearCoatTest.glb",
          "SheenChair": ROOT / "corpus/gltf/khronos/SheenChair/SheenChair.gltf",
          "TransmissionRoughnessTest": ROOT / "corpus/gltf/khronos/TransmissionRoughnessTest/"
                                              "TransmissionRoughnessTest.glb"}
TIMED_MODELS = ("DamagedHelmet", "ClearCoatTest")
DOMINANT = "vec3 lookup = pbr_specular_dominant_direction(n, r, alpha);"
MIRROR = "vec3 lookup = r;"
# (label, horizon occlusion, mirror read, checking program, fallback for every mesh)
VARIANTS = (("as shipped", True, False, True, False),
            ("production", True, False, False, False),
            ("fallback on every mesh", True, False, True, True),
            ("horizon occlusion off", False, False, True, False),
            ("mirror read", True, True, True, False))


def _every_mesh_falls_back(program):
    """``program`` with the templates' default tangent fallback (the per-mesh define dropped)."""
    defines = tuple((k, v) for k, v in program.defines if k != tangent_frames.TANGENT_FALLBACK_DEFINE)
    return dataclasses.replace(program, defines=defines)


def _largest(scene, mirror_read: bool, families, checking: bool = True, fallback_always: bool = False) -> dict:
    """Per family, (instructions, VGPRs) of the scene's largest specialised GLSL program."""
    jobs = {}
    for index, program in enumerate(gpu.scene_programs(scene, "specialised", checking=checking)):
        if fallback_always:
            program = _every_mesh_falls_back(program)
        job = program.job("glsl")
        if mirror_read:
            if DOMINANT not in job.fragment:
                raise SystemExit("the dominant read's line is not in the program: update this benchmark")
            job = dataclasses.replace(job, fragment=job.fragment.replace(DOMINANT, MIRROR))
        jobs[str(index)] = job
    compiled = gpu._compile(jobs, families)
    out = {}
    for family in families:
        stats = [compiled[family][key] for key in jobs]
        best = max(stats, key=lambda s: s["Instructions"])
        out[family] = (best["Instructions"], best["VGPRs"])
    return out


def figures(name: str, families=gpu.GPU_FAMILIES) -> dict:
    """{variant: {family: (instructions, VGPRs)}} for MODELS[name] under the sunrise."""
    model = MODELS[name]
    environment = staging.ENVIRONMENTS_DIR / "sunrise.exr"
    variants = {}
    for label, horizon, mirror, checking, fallback_always in VARIANTS:
        scene = parse_scene({"camera": {"position": [0, 0, 3], "target": [0, 0, 0], "size": [64, 64]},
                             "environment": {"path": str(environment)}, "objects": [{"gltf": str(model)}],
                             "render": {"horizon_occlusion": horizon}},
                            origin=f"{name} under sunrise", base=model.parent)
        variants[label] = _largest(scene, mirror, families, checking, fallback_always)
    return variants


def cpu_times(name: str, repeats: int, size: int = 512) -> dict:
    """{horizon occlusion on/off: median process time (s) of render_scene} for MODELS[name]
    framed at size x size under the sunrise, interleaved after one warm-up each."""
    ctx = gl.shared_context()
    environment = Environment(path=staging.ENVIRONMENTS_DIR / "sunrise.exr")
    scenes = {}
    for label, horizon in (("on", True), ("off", False)):
        scene = load_gltf(MODELS[name], size=(size, size), environment=environment, emit_warnings=False).scene
        scene.render.horizon_occlusion = horizon
        scenes[label] = scene
        render_scene(scene, ctx)  # compile, upload, prefilter, cache
    times = {label: [] for label in scenes}
    for _ in range(repeats):
        for label, scene in scenes.items():
            start = time.process_time()
            render_scene(scene, ctx)
            times[label].append(time.process_time() - start)
    return {label: statistics.median(t) for label, t in times.items()}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--time", action="store_true", help="also the llvmpipe process time (LP_NUM_THREADS=1)")
    parser.add_argument("--repeats", type=int, default=7)
    args = parser.parse_args()
    gpu.require_null_device()
    families = gpu.GPU_FAMILIES
    print("largest specialised GLSL program, instructions / VGPRs per family "
          + " / ".join(gpu.TITLES[f] for f in families))
    for name in MODELS:
        for label, per_family in figures(name, families).items():
            print(f"  {name:26s} {label:22s} "
                  + "  ".join(f"{gpu.TITLES[f]} {i:5d} / {v:3d}" for f, (i, v) in per_family.items()))
    if args.time:
        print(f"llvmpipe, LP_NUM_THREADS={os.environ.get('LP_NUM_THREADS', 'unset')}: median process time of "
              f"{args.repeats} renders at 512 x 512, horizon occlusion on / off, interleaved")
        for name in TIMED_MODELS:
            t = cpu_times(name, args.repeats)
            print(f"  {name:16s} on {1e3 * t['on']:7.1f} ms   off {1e3 * t['off']:7.1f} ms   ({t['on'] / t['off']:.3f}x)")


if __name__ == "__main__":
    main()
