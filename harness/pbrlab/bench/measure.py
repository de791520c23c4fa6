"""The measurements: error (in this process), time and instruction counts (in worker
subprocesses, see worker.py), frame cost and tier image error of the default scene."""

from __future__ import annotations

import json
import os
import platform
import re
import shutil
import subprocess
import sys
import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ..foundation import console
from ..gpu import evaluator, gl, ibl, shaders, targets
from ..checking.golden_scenes import LIT_SCENE
from . import count_check, kernel
from .families import Family, Variant

DEFAULT_SCENE = LIT_SCENE  # the lit golden scene (pbrlab.checking.golden_scenes), one definition of its path
TIERS = ("high", "medium", "low")


# callgrind target, the timing target's size (Settings.time_size), so that counts and times
# describe the same draws. A count per evaluation depends on the size, deterministically:
# llvmpipe runs two compiled fragment functions, and the one that costs ~20 % more per loop
# iteration covers a share of the pixels that falls as 1/size (callgrind's per-function
# counts: ~46 % at 32x32, 23 % at 64x64, 11 % at 128x128), so smith_ggx_correlated counts
# 9.77 at 32x32, 9.44 at 64x64 and 9.27 at 128x128.
COUNT_SIZE = 128
# Each kernel is counted this many times (worker.count_plan); count_check compares them.
COUNT_PASSES = 2
# callgrind collects instructions only inside these functions, moderngl's C entry points of
# VertexArray.render and Context.finish (symbols of its mgl extension): one draw and
# llvmpipe's rasterisation of it (LP_NUM_THREADS=0: in the calling thread, inside finish).
# Outside them run Python's interpreter, whose adaptive specialisation retries a call site
# now and then (~0.3-1.7 k instructions, measured), and anything else the worker does.
COUNTED_FUNCTIONS = ("MGLVertexArray_render*", "MGLContext_finish*")


@dataclass(frozen=True)
class Settings:
    """How much to measure. ``quick``: what CI runs (fewer samples and rounds; its
    figures show that the bench works, not what things cost)."""

    quick: bool
    grid_1d: int
    grid_axes: dict          # inputs -> points per axis
    time_size: int           # timing target is size x size pixels
    time_trips: int          # loop iterations per pixel
    time_rounds: int         # interleaved randomised rounds (issue 7: >= 10)
    count_size: int          # callgrind target
    count_trips: tuple       # (T1, T2): per-iteration count = difference
    frame_size: int
    frame_rounds: int
    tier_image_scale: float  # of the scene's own size
    # None: every family; (): none. A callgrind worker spends ~15 s (kernels: collection only
    # in the draws) to ~55 s (frames: whole process) in start-up, so --quick skips counting.
    count_families: tuple | None

    @classmethod
    def make(cls, quick: bool) -> "Settings":
        if quick:
            return cls(True, 4096, {2: 96, 3: 20, 4: 10}, 48, 4, 3, 16, (1, 2), 192, 2, 0.5, ())
        return cls(False, 65536, {2: 512, 3: 64, 4: 32}, 128, 32, 15, COUNT_SIZE, (2, 4), 1024, 10, 1.0,
                   None)


_START = time.monotonic()


def progress(message: str) -> None:
    """The progress line on stderr, with the seconds elapsed since the bench started."""
    console.note(f"pbrlab bench: {time.monotonic() - _START:6.1f}s {message}", stream=sys.stderr)


# ---- error -----------------------------------------------------------------------------------

def grid(family: Family, settings: Settings) -> dict:
    """float32 inputs over the family's domain (a regular grid, endpoints included)."""
    if family.diagonal:
        line = np.linspace(family.inputs[0][1], family.inputs[0][2], settings.grid_1d)
        return {name: line.astype(np.float32) for name, _, _ in family.inputs}
    n = family.grid_points if family.grid_points and not settings.quick else settings.grid_axes[len(family.inputs)]
    if family.grid_points and settings.quick:
        n = min(n, 24)
    axes = [np.linspace(lo, hi, n) for _, lo, hi in family.inputs]
    mesh = np.meshgrid(*axes, indexing="ij")
    return {name: m.ravel().astype(np.float32) for (name, _, _), m in zip(family.inputs, mesh)}


def with_derived(family: Family, inputs32: dict) -> dict:
    """float64 dict of the (float32-rounded) inputs and derived values, each rounded to
    float32 as the GPU receives it: the reference sees exactly the GPU's inputs."""
    d = {k: v.astype(np.float64) for k, v in inputs32.items()}
    for _, name, _, fn in family.derived:
        d[name] = np.asarray(fn(d), np.float32).astype(np.float64)
    return d


def error_stats(gpu, ref, d: dict, rel_floor: float) -> dict:
    gpu = np.asarray(gpu, np.float64).reshape(ref.shape)
    finite = np.isfinite(gpu)
    abs_err = np.where(finite, np.abs(gpu - ref), np.inf)
    per_sample = abs_err.reshape(len(abs_err), -1).max(axis=1)
    with np.errstate(divide="ignore", invalid="ignore"):
        rel = np.where(np.abs(ref) > rel_floor, abs_err / np.abs(ref), 0.0)
    rel_sample = rel.reshape(len(rel), -1).max(axis=1)
    i_abs, i_rel = int(np.argmax(per_sample)), int(np.argmax(rel_sample))

    def at(i):
        return {k: round(float(v[i]), 6) for k, v in d.items() if np.ndim(v) == 1}

    return {"max_abs": float(per_sample[i_abs]), "max_rel": float(rel_sample[i_rel]),
            "p99_rel": float(np.percentile(rel_sample, 99)),
            "rmse": float(np.sqrt(np.mean(np.where(finite, gpu - ref, 0.0) ** 2))),
            "mean_abs": float(np.mean(np.where(finite, np.abs(gpu - ref), 0.0))),
            "worst_abs_at": at(i_abs), "worst_rel_at": at(i_rel),
            "nonfinite": int((~finite).sum()), "samples": int(len(per_sample)),
            "rel_floor": rel_floor}


def _gpu_inputs(family: Family, d: dict) -> dict:
    out = {name: d[name].astype(np.float32) for name, _, _ in family.inputs}
    for glsl_type, name, _, _ in family.derived:
        value = d[name].astype(np.float32)
        out[name] = evaluator.vec3(value) if glsl_type == "vec3" else value
    return out


def _reference(family: Family, d: dict, settings: Settings) -> np.ndarray:
    if family.name == "env_brdf":
        from ..maths.reference import directional_albedo
        return directional_albedo.split_sum_terms_grid(d["NdotV"], d["r"] ** 2, theta_nodes=20, phi_nodes=24)
    return np.asarray(family.reference(d), np.float64)


def _dfg_bilinear(ndotv, rough):
    """The renderer's lookup in float64: texture(u_dfg_lut, pbr_dfg_lut_uv(NdotV, r)) with
    bilinear filtering and clamp to edge (reference/surface.py sample_dfg_lut)."""
    from ..maths.reference import surface
    return surface.sample_dfg_lut(ibl.dfg_lut()[::-1], ndotv, rough)


def _fullscreen_program(ctx, fragment: str):
    return ctx.program(vertex_shader=kernel.vertex_source(), fragment_shader=fragment)


def hardware_decode_values(ctx) -> tuple[np.ndarray, np.ndarray]:
    """(codes / 255, the sRGB texture's decoded red channel) for the 256 codes."""
    codes = np.arange(256, dtype=np.uint8)
    image = np.stack([codes, codes, codes, np.full(256, 255, np.uint8)], -1)[None]
    tex = targets.upload_texture(ctx, image, srgb=True)
    program = _fullscreen_program(ctx, """#version 330 core
uniform sampler2D tex; out vec4 o;
void main() { o = texelFetch(tex, ivec2(gl_FragCoord.xy), 0); }""")
    vao = ctx.vertex_array(program, [])
    with targets.Target(ctx, (256, 1), "f32", depth=False) as target:
        target.use()
        tex.use(0)
        program["tex"].value = 0
        vao.render(vertices=3)
        out = target.read()[0, :, 0].astype(np.float64)
    tex.release()
    return codes / 255.0, out


HARDWARE_ENCODE_POINTS = 4096


def hardware_encode_values(ctx) -> tuple[np.ndarray, np.ndarray]:
    """(linear inputs, the sRGB framebuffer's 8-bit codes / 255) for a ramp over [0, 1]."""
    n = HARDWARE_ENCODE_POINTS
    program = _fullscreen_program(ctx, f"""#version 330 core
out vec4 o;
void main() {{ o = vec4(vec3((gl_FragCoord.x - 0.5) / {float(n - 1)}), 1.0); }}""")
    vao = ctx.vertex_array(program, [])
    with targets.Target(ctx, (n, 1), "srgb8", depth=False) as target:
        target.use()
        vao.render(vertices=3)
        codes = target.read()[0, :, 0].astype(np.float64)
    x = (np.arange(n, dtype=np.float32) + np.float32(0.5) - np.float32(0.5)) / np.float32(n - 1)
    return x.astype(np.float64), codes / 255.0


def lsb_error(values, ref) -> int:
    """Largest difference in 8-bit codes after rounding both to 8 bits."""
    q = lambda x: np.round(np.clip(np.asarray(x, np.float64), 0, 1) * 255.0)  # noqa: E731
    return int(np.max(np.abs(q(values) - q(ref))))


def measure_errors(family: Family, settings: Settings) -> dict:
    """{variant: {"error": stats vs the family reference, "self_error": stats vs its own
    float64 twin or None, "lsb_8bit": codes (colour families)}}."""
    from ..maths.reference import color
    with np.errstate(all="ignore"):
        return _measure_errors(family, settings)


def _measure_errors(family: Family, settings: Settings) -> dict:
    from ..maths.reference import color
    inputs32 = grid(family, settings)
    d = with_derived(family, inputs32)
    ref = None if family.own_reference else _reference(family, d, settings)
    out = {}
    for variant in family.variants:
        record = {"self_error": None}
        if variant.kind == "texture" and variant.texture == "dfg":
            gpu = _dfg_bilinear(d["NdotV"], d["r"])
            record["error"] = error_stats(gpu, ref, d, family.rel_floor)
        elif variant.kind == "texture":  # hardware sRGB decode, the 256 codes
            x, y = hardware_decode_values(gl.shared_context())
            ref_hw = color.srgb_to_linear(x)[:, None]
            record["error"] = error_stats(y[:, None], ref_hw, {"c0": x}, family.rel_floor)
        elif variant.kind == "hardware_encode":
            x, y = hardware_encode_values(gl.shared_context())
            ref_hw = color.linear_to_srgb(x)[:, None]
            record["error"] = error_stats(y[:, None], ref_hw, {"c0": x}, family.rel_floor)
            record["lsb_8bit"] = lsb_error(y, ref_hw[:, 0])
        elif family.own_reference:
            gpu = evaluator.evaluate(variant.expression, defines=variant.defines or None,
                                     **_gpu_inputs(family, d))
            own = np.asarray(variant.self_reference(d), np.float64)
            record["error"] = error_stats(gpu.reshape(own.shape), own, d, family.rel_floor)
        else:
            peer = {"includes": (shaders.UMBRELLA_INCLUDE, variant.peer),
                    "include_dirs": (kernel.PEERS_DIR,)} if variant.peer else {}
            gpu = evaluator.evaluate(variant.expression, defines=variant.defines or None,
                                     **peer, **_gpu_inputs(family, d))
            gpu = np.asarray(gpu, np.float64).reshape(len(ref), -1)
            if family.name == "env_brdf":
                gpu = gpu[:, :2]
            record["error"] = error_stats(gpu, ref, d, family.rel_floor)
            if variant.self_reference is not None:
                own = np.asarray(variant.self_reference(d), np.float64).reshape(ref.shape[0], -1)
                record["self_error"] = error_stats(gpu.reshape(own.shape), own, d, family.rel_floor)
            if family.name == "srgb_encode":
                record["lsb_8bit"] = lsb_error(gpu, ref)
        out[variant.name] = record
    return out


# ---- kernels for time and instruction counts ---------------------------------------------------

def kernel_specs(families) -> list[dict]:
    """Every program the workers run, with the arithmetic that turns draws into figures:
    ``("loop", variant_id, baseline_id)``: per evaluation, variant minus baseline;
    ``("pixel", variant_id, baseline_id)``: per pixel (hardware sRGB encode)."""
    kernels, plans = [], []
    for family in families:
        base = f"{family.name}/_baseline"
        text = kernel.fragment_source(family.inputs, family.derived, None)
        kernels.append({"id": base, "fragment": kernel.expanded(text)})
        for variant in family.variants:
            vid = f"{family.name}/{variant.name}"
            if variant.kind == "hardware_encode":
                for target in ("srgb8", "unorm8"):
                    kernels.append({"id": f"{vid}@{target}", "fragment": kernel.expanded(text),
                                    "target": target, "trips": 1})
                plans.append({"family": family.name, "variant": variant.name, "kind": "pixel",
                              "id": f"{vid}@srgb8", "baseline": f"{vid}@unorm8"})
                continue
            vtext = kernel.fragment_source(family.inputs, family.derived, variant.expression,
                                           variant.defines, peer=variant.peer)
            entry = {"id": vid, "fragment": kernel.expanded(vtext)}
            baseline = base
            if variant.kind == "texture":
                entry["texture"] = variant.texture
                if variant.texture == "srgb8":  # the same fetch from a UNORM8 texture
                    baseline = f"{vid}@unorm8"
                    kernels.append({"id": baseline, "fragment": entry["fragment"], "texture": "unorm8"})
            kernels.append(entry)
            plans.append({"family": family.name, "variant": variant.name, "kind": "loop",
                          "id": vid, "baseline": baseline})
    return kernels, plans


def _worker_env(threads: int) -> dict:
    """The worker's environment: llvmpipe's rasteriser thread count (read when the driver
    loads), the parent's CPU-caps pin (so the worker compiles the same code and shares
    Mesa's shader cache with every other pbrlab process) and a fixed hash seed."""
    gl.pin_llvmpipe_cpu_caps()
    env = dict(os.environ, LP_NUM_THREADS=str(threads), PYTHONHASHSEED="0")
    return env


def _worker_command(mode: str, spec: dict, workdir: Path, prefix=(), tag=""):
    spec_path, out_path = workdir / f"{mode}{tag}.spec.json", workdir / f"{mode}{tag}.out.json"
    spec_path.write_text(json.dumps(spec), encoding="utf-8")
    cmd = [*prefix, sys.executable, "-m", "pbrlab.bench.worker", mode, str(spec_path), str(out_path)]
    return cmd, out_path


def _dfg_file(workdir: Path) -> str:
    path = workdir / "dfg_lut.npy"
    if not path.exists():
        np.save(path, ibl.dfg_lut())
    return str(path)


def _wait(procs):
    results = []
    for proc, cmd, out_path in procs:
        _, err = proc.communicate()
        if proc.returncode != 0:
            raise RuntimeError(f"bench worker failed ({' '.join(cmd[-4:])}):\n{err[-3000:]}")
        results.append(json.loads(out_path.read_text(encoding="utf-8")))
    return results


ROUND_LINE = "round"  # what a worker prints on stderr after each interleaved round (worker.py)


def _run_with_rounds(cmd, out_path, env, rounds: int, what: str) -> dict:
    """Run one worker whose spec asks for ``progress``: a tqdm bar over its ``rounds``
    (elapsed and estimated time left, on stderr; off under -q), then its result."""
    from tqdm import tqdm

    proc = subprocess.Popen(cmd, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    other = []
    with tqdm(total=rounds, desc=f"pbrlab bench: {what}", unit="round", leave=False,
              disable=console.level() < console.NORMAL, file=sys.stderr) as bar:
        for line in proc.stderr:  # the worker writes its result to a file, so this cannot block
            if line.strip() == ROUND_LINE:
                bar.update(1)
            else:
                other.append(line)
    proc.wait()
    if proc.returncode != 0:
        raise RuntimeError(f"bench worker failed ({' '.join(cmd[-4:])}):\n{''.join(other)[-3000:]}")
    return json.loads(out_path.read_text(encoding="utf-8"))


def measure_time(kernels, plans, settings: Settings, workdir: Path) -> dict:
    spec = {"vertex": kernel.vertex_source(), "kernels": kernels, "size": settings.time_size,
            "trips": settings.time_trips, "rounds": settings.time_rounds, "seed": 7,
            "dfg_lut": _dfg_file(workdir), "progress": True}
    cmd, out_path = _worker_command("time", spec, workdir)
    seconds = _run_with_rounds(cmd, out_path, _worker_env(1), settings.time_rounds, "kernel time")["seconds"]
    pixels = settings.time_size ** 2
    out = {}
    for plan in plans:
        a, b = np.array(seconds[plan["id"]]), np.array(seconds[plan["baseline"]])
        per = (pixels if plan["kind"] == "pixel"
               else pixels * settings.time_trips * kernel.EVALS_PER_ITERATION)
        ns = (a - b) / per * 1e9  # per round: baseline of the same round subtracted
        out[(plan["family"], plan["variant"])] = ns
    return out


def measure_instructions(kernels, plans, settings: Settings, workdir: Path, jobs: int = 2) -> dict:
    """Instructions per evaluation from callgrind: ``{(family, variant): [figure per pass]}``,
    checked by count_check (raises InconsistentCountError). A draw's count is callgrind's
    ``Ir`` inside COUNTED_FUNCTIONS between two markers: one draw + glFinish.

    What a count excludes, and why (issue 16; measured at 32x32, where 1 instruction per
    evaluation is 16,384 in a T2 - T1 difference: 32 x 32 pixels x 8 evaluations x 2 trips):
    Python's garbage collector (off in the worker: a young collection inside one baseline
    draw moved a whole family by +25 per evaluation; the oldest generation's costs 500), the
    interpreter's adaptive specialisation (outside COUNTED_FUNCTIONS: 0.02-0.1), and
    llvmpipe's work when a draw follows another program, texture or target (worker.count_plan:
    a warm draw first: 0.1-0.3, depending on the kernels drawn before). Left inside: work in
    llvmpipe's draw whose amount depends on the process's heap (malloc), which moved a figure
    by at most 0.003 per evaluation at 128x128 between passes and worker processes."""
    valgrind = shutil.which("valgrind")
    if valgrind is None or settings.count_families == ():
        return {}
    families = sorted({k["id"].split("/")[0] for k in kernels})
    if settings.count_families is not None:
        families = [f for f in families if f in settings.count_families]
        kernels = [k for k in kernels if k["id"].split("/")[0] in families]
        plans = [p for p in plans if p["family"] in families]
        jobs = min(jobs, len(families))
    groups = [families[i::jobs] for i in range(jobs)]
    procs = []
    for g, names in enumerate(groups):
        chunk = [k for k in kernels if k["id"].split("/")[0] in names]
        spec = {"vertex": kernel.vertex_source(), "kernels": chunk, "size": settings.count_size,
                "trips_pair": list(settings.count_trips), "passes": COUNT_PASSES,
                "dfg_lut": _dfg_file(workdir)}
        outdir = workdir / f"callgrind{g}"
        outdir.mkdir()
        prefix = (valgrind, "--tool=callgrind", "--dump-before=getppid", "--dump-instr=no",
                  *(f"--toggle-collect={name}" for name in COUNTED_FUNCTIONS),
                  f"--callgrind-out-file={outdir}/cg.out")
        cmd, out_path = _worker_command("count", spec, workdir, prefix=prefix, tag=str(g))
        procs.append((subprocess.Popen(cmd, env=_worker_env(0), stdout=subprocess.PIPE,
                                       stderr=subprocess.PIPE, text=True), cmd, out_path, outdir))
    draws = {}
    for (proc, cmd, out_path, outdir), result in zip(procs, _wait([p[:3] for p in procs])):
        dumps = sorted(outdir.glob("cg.out.*"), key=lambda p: int(p.suffix[1:]))
        totals = [int(re.search(r"^summary:\s*(\d+)", p.read_text(), re.M).group(1)) for p in dumps]
        # dump 1: start-up up to the first marker; then one per draw of the plan
        for (kid, trips, counted_pass), ir in zip(result["sequence"], totals[1:]):
            if counted_pass is not None:
                draws[(kid, trips, counted_pass)] = ir
    count_check.check_collected(draws, COUNTED_FUNCTIONS)
    figures = per_eval_counts(draws, plans, settings, COUNT_PASSES)
    count_check.check_counts({"/".join(key): values for key, values in figures.items()},
                             unit=" per evaluation")
    return figures


def per_eval_counts(draws: dict, plans, settings: Settings, passes: int) -> dict:
    """``{(family, variant): [instructions per evaluation, one per pass]}`` from the counted
    draws ``{(kernel id, trips, pass): Ir}``: per pass, the variant's T2 - T1 difference minus
    its baseline's, over pixels x evaluations per iteration x (T2 - T1); "pixel" plans (the
    hardware sRGB encode): the variant's draw minus its baseline's at T2, per pixel."""
    t1, t2 = settings.count_trips
    pixels = settings.count_size ** 2
    out = {}
    for plan in plans:
        values = []
        for p in range(passes):
            c = lambda kid, trips: draws[(kid, trips, p)]  # noqa: E731
            if plan["kind"] == "pixel":
                v = (c(plan["id"], t2) - c(plan["baseline"], t2)) / pixels
            else:
                dv = c(plan["id"], t2) - c(plan["id"], t1)
                db = c(plan["baseline"], t2) - c(plan["baseline"], t1)
                v = (dv - db) / (pixels * kernel.EVALS_PER_ITERATION * (t2 - t1))
            values.append(float(v))
        out[(plan["family"], plan["variant"])] = values
    return out


# ---- frame cost and tier image error ------------------------------------------------------------

def measure_frame(settings: Settings, workdir: Path, scene_path=DEFAULT_SCENE) -> dict:
    spec = {"scene": str(scene_path), "tiers": list(TIERS), "size": settings.frame_size,
            "rounds": settings.frame_rounds, "seed": 3, "progress": True}
    cmd, out_path = _worker_command("frame", spec, workdir)
    seconds = _run_with_rounds(cmd, out_path, _worker_env(1), settings.frame_rounds, "frame cost")["seconds"]
    setup = np.array(seconds.pop("_setup"))
    out = {"size": [settings.frame_size, settings.frame_size], "rounds": settings.frame_rounds,
           "setup_ms_median": float(np.median(setup) * 1e3), "tiers": {}}
    high = np.median(np.array(seconds["high"]) - setup)
    for tier, values in seconds.items():
        total = np.array(values)
        net = total - setup
        out["tiers"][tier] = {"total_ms_median": float(np.median(total) * 1e3),
                              "shading_ms_median": float(np.median(net) * 1e3),
                              "shading_ms_p25": float(np.percentile(net, 25) * 1e3),
                              "shading_ms_p75": float(np.percentile(net, 75) * 1e3),
                              "ratio_to_high": float(np.median(net) / high)}
    return out


SPECIALISATION_SCENES = ("chart_metallic", "chart_terms", "example.json",
                         "unity_example/scene.json", "torture/scene.json")


def measure_specialisation(settings: Settings, workdir: Path) -> dict:
    """Frame CPU time of each test scene with specialised programs against the full
    program (LP_NUM_THREADS=1, interleaved rounds; the images are bit-identical)."""
    spec = {"scenes": list(SPECIALISATION_SCENES), "rounds": settings.frame_rounds, "seed": 5,
            "size": [96, 64] if settings.quick else None, "progress": True}
    cmd, out_path = _worker_command("specialise", spec, workdir)
    result = _run_with_rounds(cmd, out_path, _worker_env(1), settings.frame_rounds, "specialised vs full")
    instructions = _count_frames(settings, workdir)
    out = {"rounds": settings.frame_rounds, "size": spec["size"] or "each scene's own",
           "instructions_size": list(SPECIALISATION_COUNT_SIZE), "scenes": {}}
    for name in SPECIALISATION_SCENES:
        spec_s = np.array(result["seconds"][f"{name}|specialised"])
        full_s = np.array(result["seconds"][f"{name}|full"])
        out["scenes"][name] = {
            "programs_specialised": result["programs"][f"{name}|specialised"],
            "programs_full": result["programs"][f"{name}|full"],
            "specialised_ms_median": float(np.median(spec_s) * 1e3),
            "full_ms_median": float(np.median(full_s) * 1e3),
            "full_over_specialised": float(np.median(full_s) / np.median(spec_s)),
            "specialised_instructions": instructions.get(f"{name}|specialised"),
            "full_instructions": instructions.get(f"{name}|full"),
        }
    return out


SPECIALISATION_COUNT_SIZE = (64, 48)  # frames counted under callgrind are small: ~50x slower
# Scenes whose frames callgrind can count: valgrind 3.19 stops on a GFNI instruction
# (GF2P8AFFINEQB) that a library on this host executes on the environment and image paths
# (DFG table, prefilter, image decoding), so scenes with an environment or textures keep
# only their times.
SPECIALISATION_COUNT_SCENES = ("chart_metallic", "chart_terms")


def _count_frames(settings: Settings, workdir: Path) -> dict:
    """callgrind instructions (Ir, whole process) of one frame per (scene, program kind) at
    SPECIALISATION_COUNT_SIZE, for SPECIALISATION_COUNT_SCENES; empty under --quick
    (callgrind start-up alone is ~55 s)."""
    valgrind = shutil.which("valgrind")
    if valgrind is None or settings.count_families == ():
        return {}
    spec = {"scenes": list(SPECIALISATION_COUNT_SCENES), "size": list(SPECIALISATION_COUNT_SIZE),
            "passes": COUNT_PASSES}
    outdir = workdir / "callgrind_frames"
    outdir.mkdir()
    prefix = (valgrind, "--tool=callgrind", "--dump-before=getppid", "--dump-instr=no",
              f"--callgrind-out-file={outdir}/cg.out")
    cmd, out_path = _worker_command("count_frames", spec, workdir, prefix=prefix, tag="frames")
    proc = subprocess.Popen(cmd, env=_worker_env(0), stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    result = _wait([(proc, cmd, out_path)])[0]
    dumps = sorted(outdir.glob("cg.out.*"), key=lambda p: int(p.suffix[1:]))
    totals = [int(re.search(r"^summary:\s*(\d+)", p.read_text(), re.M).group(1)) for p in dumps]
    per_frame: dict = {}
    for (key, _), ir in zip(result["sequence"], totals[1:]):  # dump 1: start-up to the first marker
        per_frame.setdefault(key, []).append(ir)
    count_check.check_counts(per_frame, unit=" (whole-process Ir of one frame)")
    return {key: float(np.mean(values)) for key, values in per_frame.items()}


def tier_image_error(scene_path=DEFAULT_SCENE, scale: float = 1.0) -> dict:
    """Each tier's render of the default scene against the HIGH-tier render (GPU, float32,
    the scene's own size): linear radiance and the displayed 8-bit image."""
    from ..render import renderer as render
    from ..importers import loader as scene_mod
    renders = {}
    for tier in TIERS:
        s = scene_mod.load_scene(scene_path)
        s.render.quality = tier
        size = tuple(max(1, int(round(n * scale))) for n in s.camera.size)
        renders[tier] = render.render_scene(s, size=size)
    ref = renders["high"].linear[..., :3].astype(np.float64)
    lum = ref @ np.array([0.2126, 0.7152, 0.0722])
    out = {"reference": "the HIGH-tier GPU render of the same scene (no float64 renderer covers "
                        "meshes, textures and IBL; the brdf_tier family gives the float64 comparison)",
           "size": list(ref.shape[1::-1]), "tiers": {}}
    for tier in TIERS:
        img = renders[tier].linear[..., :3].astype(np.float64)
        diff = np.abs(img - ref).max(axis=-1)
        with np.errstate(divide="ignore", invalid="ignore"):
            rel = np.where(lum > 0.01, diff / np.maximum(lum, 1e-12), 0.0)
        codes = np.abs(renders[tier].srgb8[..., :3].astype(int) - renders["high"].srgb8[..., :3].astype(int)).max(-1)
        y, x = np.unravel_index(int(np.argmax(rel)), rel.shape)
        out["tiers"][tier] = {"max_abs": float(diff.max()), "max_rel": float(rel.max()),
                              "median_rel": float(np.median(rel[lum > 0.01])),
                              "rmse": float(np.sqrt(np.mean((img - ref) ** 2))),
                              "worst_rel_pixel": [int(x), int(y)],
                              "max_srgb8_codes": int(codes.max()),
                              "fraction_over_2_codes": float(np.mean(codes > 2))}
    return out


# ---- machine -------------------------------------------------------------------------------------

def machine_info() -> dict:
    info = gl.context_info(gl.shared_context())
    llvm = re.search(r"LLVM ([0-9.]+)", info["GL_RENDERER"])
    flags, model = [], platform.processor()
    try:
        cpuinfo = Path("/proc/cpuinfo").read_text()
        model = re.search(r"model name\s*:\s*(.*)", cpuinfo).group(1)
        flags = re.search(r"flags\s*:\s*(.*)", cpuinfo).group(1).split()
    except (OSError, AttributeError):
        pass
    wanted = ("sse4_1", "sse4_2", "avx", "avx2", "fma", "f16c", "avx512f")
    valgrind = shutil.which("valgrind")
    vg_version = (subprocess.run([valgrind, "--version"], capture_output=True, text=True).stdout.strip()
                  if valgrind else None)
    return {"GL_RENDERER": info["GL_RENDERER"], "GL_VERSION": info["GL_VERSION"], "mesa": info["mesa"],
            "llvm": llvm.group(1) if llvm else None, "backend": info["backend"],
            "llvmpipe_cpu_caps": info["llvmpipe_cpu_caps"], "cpu": model,
            "cpu_features": [f for f in wanted if f in flags], "cpu_count": os.cpu_count(),
            "python": platform.python_version(), "valgrind": vg_version}
