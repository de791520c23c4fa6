"""Measurement subprocess: ``python -m pbrlab.bench.worker MODE SPEC.json OUT.json``.

Runs in a process of its own so that ``LP_NUM_THREADS`` (llvmpipe's rasteriser threads,
read when the driver loads) is set before any GL context exists; the parent sets it in
the environment it passes. Modes:

* ``time``: for every round, every kernel in a freshly shuffled order: CPU time
  (``time.process_time``, all threads of the process) of one draw + ``glFinish`` of a
  ``size``-square target at ``trips`` loop iterations. Every program is warmed first
  (compile + one draw). Writes ``{"seconds": {id: [per round]}, "order": [...]}``.
* ``count``: meant to run under ``valgrind --tool=callgrind --dump-before=getppid``
  collecting only inside the draw and finish calls (``measure.COUNTED_FUNCTIONS``): calls
  ``os.getppid()`` (the marker; a ctypes call is not seen as a function entry) before each
  draw of ``count_plan``, so each callgrind dump holds one draw's instructions. Writes
  ``{"sequence": [[id, trips, pass (null: a warm draw, not a count)], ...]}``.
* ``frame``: CPU time of rendering a scene per quality tier, interleaved rounds.

The garbage collector is off in every mode (``main``): a collection runs inside whichever
draw happens to allocate the object that crosses its threshold, which depends on everything
the process did before (measured under callgrind: 0.01-0.4 M instructions for a young
collection, 0.9 M for the middle and 8 M for the oldest generation, against 1-4 M for a whole
32x32 draw). The workers are short-lived and allocate little.
"""

from __future__ import annotations

import gc
import json
import os
import random
import sys
import time

import moderngl
import numpy as np


class _Kernels:
    """The spec's programs with their texture and target, on one context."""

    def __init__(self, spec):
        from ..gpu import gl, targets
        self.ctx = ctx = gl.create_context(None)
        self.size = size = spec["size"]
        codes = np.arange(256, dtype=np.uint8)
        ramp = np.stack([codes, 255 - codes, codes // 2, np.full(256, 255, np.uint8)], -1)[None]
        self.textures = {
            "srgb8": targets.upload_texture(ctx, ramp, srgb=True),
            "unorm8": targets.upload_texture(ctx, ramp, srgb=False),
            # the parent's ibl.dfg_lut() (integrating it here would dominate a callgrind run),
            # uploaded and filtered as ibl.dfg_texture does
            "dfg": targets.upload_texture(ctx, np.load(spec["dfg_lut"]), srgb=False),
        }
        self.textures["dfg"].filter = (moderngl.LINEAR, moderngl.LINEAR)
        self.textures["dfg"].repeat_x = self.textures["dfg"].repeat_y = False
        for name in ("srgb8", "unorm8"):
            self.textures[name].filter = (moderngl.NEAREST, moderngl.NEAREST)
        self.targets = {kind: targets.Target(ctx, (size, size), kind, depth=False)
                        for kind in ("f32", "srgb8", "unorm8")}
        self.kernels = {}
        for kernel in spec["kernels"]:
            program = ctx.program(vertex_shader=spec["vertex"], fragment_shader=kernel["fragment"])
            self.kernels[kernel["id"]] = (program, ctx.vertex_array(program, []), kernel)

    def draw(self, kid, trips):
        program, vao, kernel = self.kernels[kid]
        program["pbrlab_trips"].value = int(kernel.get("trips", trips))
        if "pbrlab_seed" in program:
            program["pbrlab_seed"].value = 0.25
        if kernel.get("texture"):
            self.textures[kernel["texture"]].use(0)
            if "pbrlab_tex" in program:
                program["pbrlab_tex"].value = 0
        self.targets[kernel.get("target", "f32")].use()
        vao.render(moderngl.TRIANGLES, vertices=3)
        self.ctx.finish()


def run_time(spec):
    k = _Kernels(spec)
    for kid in k.kernels:  # warm-up: compile, first draw
        k.draw(kid, spec["trips"])
    rng = random.Random(spec.get("seed", 1))
    seconds = {kid: [] for kid in k.kernels}
    for _ in range(spec["rounds"]):
        order = list(k.kernels)
        rng.shuffle(order)
        for kid in order:
            start = time.process_time()
            k.draw(kid, spec["trips"])
            seconds[kid].append(time.process_time() - start)
        if spec.get("progress"):
            print("round", file=sys.stderr, flush=True)
    return {"seconds": seconds}


WARM_TRIPS = 0  # loop trips of a warm draw: its work is the state change, not the loop


def count_plan(kernel_ids, trips_pair, passes):
    """The draws of a count run in order, as ``(kernel id, trips, pass)``; pass None marks
    a warm draw, which is not counted.

    Each pass draws every kernel once at each trip count, right after a warm draw of the
    same kernel: the work llvmpipe does when a draw follows another program, texture or
    target (state validation, shader variant lookup, a different fragment function) falls in
    the warm draw, and each counted draw follows a draw of the same kernel. Odd passes visit the kernels
    in reverse order with the trip counts swapped, so each kernel's counts in two passes
    follow different kernels and the check (count_check) sees any dependence on order."""
    plan = []
    for p in range(passes):
        ids = list(kernel_ids) if p % 2 == 0 else list(kernel_ids)[::-1]
        trips_order = list(trips_pair) if p % 2 == 0 else list(trips_pair)[::-1]
        for kid in ids:
            plan.append((kid, WARM_TRIPS, None))
            plan.extend((kid, trips, p) for trips in trips_order)
    return plan


def run_count(spec):
    k = _Kernels(spec)
    for kid in k.kernels:  # llvmpipe compiles a program's variant at its first draw
        k.draw(kid, WARM_TRIPS)
    sequence = []
    for kid, trips, counted_pass in count_plan(list(k.kernels), spec["trips_pair"], spec["passes"]):
        os.getppid()  # marker: callgrind dumps the counts since the previous marker
        k.draw(kid, trips)
        sequence.append([kid, trips, counted_pass])
    os.getppid()
    return {"sequence": sequence}


def run_frame(spec):
    from ..gpu import gl
    from ..render import renderer as render
    from ..importers import loader as scene_mod
    ctx = gl.create_context(None)
    scenes = {}
    for tier in spec["tiers"]:
        s = scene_mod.load_scene(spec["scene"])
        s.render.quality = tier
        scenes[tier] = s
    setup = scene_mod.load_scene(spec["scene"])
    setup.objects = []  # clear, readback and resolve: no shading (the environment,
                        # textures and meshes are cached from the warm-up on: resource_cache)
    scenes["_setup"] = setup
    for tier, s in scenes.items():  # warm-up: compile every program of the tier
        render.render_scene(s, ctx, size=(spec["size"], spec["size"]))
    rng = random.Random(spec.get("seed", 1))
    seconds = {tier: [] for tier in scenes}
    for _ in range(spec["rounds"]):
        order = list(scenes)
        rng.shuffle(order)
        for tier in order:
            gl.make_current(ctx)
            start = time.process_time()
            render.render_scene(scenes[tier], ctx, size=(spec["size"], spec["size"]))
            seconds[tier].append(time.process_time() - start)
        if spec.get("progress"):
            print("round", file=sys.stderr, flush=True)
    return {"seconds": seconds}


def _bench_scene(name):
    """A test scene by name: a chart, or a scene file under scenes/."""
    from ..checking import charts
    from ..importers import loader as scene_mod
    from ..foundation.locations import locate
    if name in charts.CHARTS:
        return scene_mod.parse_scene(charts.CHARTS[name](), origin=name)
    return scene_mod.load_scene(locate("scenes") / name)


def _specialisation_jobs(spec):
    jobs = {}
    for name in spec["scenes"]:
        for specialise in (True, False):
            jobs[f"{name}|{'specialised' if specialise else 'full'}"] = (_bench_scene(name), specialise)
    return jobs


def run_count_frames(spec):
    """Under callgrind: one frame per job between two markers (after a warm-up frame that
    compiles its programs), so each dump holds the instructions of exactly one frame; every
    job in ``spec["passes"]`` passes (default 2), each pass in the reverse order of the one
    before, so the parent can check that a frame's count does not depend on what ran before."""
    from ..gpu import gl
    from ..render import renderer as render
    ctx = gl.create_context(None)
    jobs = _specialisation_jobs(spec)
    size = tuple(spec["size"])
    for scene, specialise in jobs.values():
        render.render_scene(scene, ctx, size=size, specialise=specialise)
    sequence = []
    order = list(jobs)
    for number in range(int(spec.get("passes", 2))):
        for key in order:
            scene, specialise = jobs[key]
            os.getppid()  # marker: callgrind dumps the counts since the previous marker
            render.render_scene(scene, ctx, size=size, specialise=specialise)
            sequence.append([key, number])
        order.reverse()
    os.getppid()
    return {"sequence": sequence}


def run_specialise(spec):
    """Each scene rendered with its specialised programs and with the full program,
    interleaved in a shuffled order each round (features.py; the images are identical)."""
    from ..gpu import gl
    from ..render import renderer as render
    ctx = gl.create_context(None)
    jobs = _specialisation_jobs(spec)
    size = tuple(spec["size"]) if spec.get("size") else None
    programs = {}
    for key, (s, specialise) in jobs.items():  # warm-up: compile every program
        programs[key] = render.render_scene(s, ctx, size=size, specialise=specialise).programs.distinct
    rng = random.Random(spec.get("seed", 1))
    seconds = {key: [] for key in jobs}
    for _ in range(spec["rounds"]):
        order = list(jobs)
        rng.shuffle(order)
        for key in order:
            gl.make_current(ctx)
            start = time.process_time()
            render.render_scene(jobs[key][0], ctx, size=size, specialise=jobs[key][1])
            seconds[key].append(time.process_time() - start)
        if spec.get("progress"):
            print("round", file=sys.stderr, flush=True)
    return {"seconds": seconds, "programs": programs}


MODES = {"time": run_time, "count": run_count, "frame": run_frame, "specialise": run_specialise,
         "count_frames": run_count_frames}


def main(argv=None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    mode, spec_path, out_path = argv
    with open(spec_path, encoding="utf-8") as f:
        spec = json.load(f)
    gc.disable()  # no collection inside a measured draw (module docstring)
    result = MODES[mode](spec)
    with open(out_path, "w", encoding="utf-8") as f:
        json.dump(result, f)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
