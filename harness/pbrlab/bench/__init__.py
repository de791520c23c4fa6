"""`pbrlab bench`: what accuracy costs in time, for every variant and tier (issue 7).

For each family (``families.FAMILIES``) every variant gets

* **error** against the family's float64 reference over a documented input domain (a
  regular grid; GPU results through ``pbrlab.evaluate``, bit-exact float32): max abs, max
  relative (where |reference| exceeds the family's floor), 99th-percentile relative, RMSE,
  and the inputs of the worst absolute and relative error; plus, for approximations that
  have one, the float32 error against the variant's *own* float64 twin (``self_error``);
* **instructions per evaluation** (the deterministic cost): callgrind's ``Ir`` (x86
  instructions executed inside the draw and glFinish calls, ``measure.COUNTED_FUNCTIONS``)
  of a draw of the timing kernel (``kernel.py``) at two loop trip counts T1 < T2, variant
  minus the family's baseline kernel, divided by pixels x evaluations per iteration x
  (T2 - T1). It counts the code llvmpipe actually compiled (the worker under valgrind loads
  it from Mesa's shader cache, filled by the native timing run with the same CPU-caps pin),
  amortised over its 4-wide SIMD. Every kernel is counted in ``measure.COUNT_PASSES`` passes
  (each counted draw right after a warm draw of the same kernel; the second pass in reverse
  order), and the bench fails (``count_check``) on a negative figure or two figures of one
  variant more than 1 % apart; the figure is their mean;
* **time per evaluation** (ns): CPU time (``time.process_time``) around draw + glFinish in
  a worker with ``LP_NUM_THREADS=1``, every kernel warmed, kernels interleaved in a fresh
  random order each round, the family baseline of the same round subtracted; median,
  quartiles, min, max over rounds. Differences below about 20 % are noise.

* **AMD GPU instructions per evaluation** (``gpu.py``): the same kernels compiled by Mesa's
  RADV/ACO for RDNA3, RDNA2 and GCN5 on a null device (no GPU): static instructions,
  latency and inverse-throughput estimates, variant minus baseline over the 8 evaluations
  of the loop body; the variant's VGPRs.

Plus the default scene per quality tier: frame CPU time at 1024x1024 (and the shading
part: minus the same render with no objects) and image error against the HIGH tier; and
for each test scene, its programs specialised and full, in GLSL and HLSL, compiled for the
three AMD families (instructions, VGPRs, waves per SIMD).

Outputs of ``run(out_dir)``: ``accuracy_cost.json``, ``accuracy_cost.md``, ``<family>.png``,
written all or nothing (``report.write_report``: a failed write keeps the previous report whole).

JSON schema ``pbrlab-bench/2`` (checked by ``report.validate``)::

    {"schema": "pbrlab-bench/2", "quick": bool, "generated": ISO time,
     "machine": {"GL_RENDERER", "GL_VERSION", "mesa", "llvm", "backend", "llvmpipe_cpu_caps",
                 "cpu", "cpu_features": [...], "cpu_count", "python", "valgrind",
                 "gpu_isa_devices": {gpu family: RADV device name} | null},
     "method": {"evals_per_iteration", "time_size", "time_trips", "time_rounds",
                "count_size", "count_trips": [T1, T2], "count_passes", "count_tolerance",
                "noise_note", ...},
     "families": [{"name", "title", "reference", "domain", "exact", "unit",
                   "variants": [{"name", "expression" (null: not an expression), "note",
                                 "defines": {...},
                                 "error": ERROR, "self_error": ERROR | null,
                                 "lsb_8bit": int (sRGB encode only),
                                 "time_ns": {"median", "p25", "p75", "min", "max", "rounds",
                                             "ratio_to_exact"},
                                 "instructions": {"per_eval", "ratio_to_exact",
                                                  "counts": [per_eval of each pass] | null},
                                 "gpu_isa": GPU_KERNEL | null (RADV unavailable)}]}],
     "frame": {"scene", "size": [w, h], "rounds", "setup_ms_median",
               "tiers": {tier: {"total_ms_median", "shading_ms_median", "shading_ms_p25",
                                "shading_ms_p75", "ratio_to_high"}}},
     "tier_images": {"reference", "size": [w, h],
                     "tiers": {tier: {"max_abs", "max_rel", "median_rel", "rmse",
                                      "worst_rel_pixel": [x, y], "max_srgb8_codes",
                                      "fraction_over_2_codes"}}},
     "specialisation": {"rounds", "size",
                        "instructions_size": [w, h],
                        "scenes": {scene: {"programs_specialised", "programs_full",
                                           "specialised_ms_median", "full_ms_median",
                                           "full_over_specialised",
                                           "specialised_instructions": int | null (quick),
                                           "full_instructions": int | null (quick),
                                           "gpu_isa": GPU_SCENE | null}}},
     "gpu_isa": {"available": bool, "reason": str | null (why not available),
                 "families": {gpu family: RADV_FORCE_FAMILY}, "devices": {...} | null,
                 "float16": {gpu family: bool} | null (the device's shaderFloat16),
                 "float16_study": {"note", "families": {gpu family: {"float32" | "float16":
                                   figures as in GPU_KERNEL}}} | null (the LOW tier with
                                   PBR_FLOAT16), "note", "kernel_note"}}

    ERROR = {"max_abs", "max_rel", "p99_rel", "rmse", "worst_abs_at": {input: value},
             "worst_rel_at": {input: value}, "nonfinite", "samples", "rel_floor"}
    GPU_KERNEL = {"na": why} (the hardware sRGB encode: no fragment instructions)
               | {"note", "families": {"rdna3" | "rdna2" | "gcn5": {
                     "instructions_per_eval", "latency_per_eval", "inverse_throughput_per_eval",
                     "valu_f16_per_eval", "valu_packed_per_eval", "transcendental_per_eval",
                     "vgprs", "vgprs_baseline", "sgprs", "subgroups_per_simd", "wave_size",
                     "instructions", "baseline_instructions"}}}
    GPU_SCENE = {"programs": [{"kind": "specialised" | "full", "stem", "materials": [...],
                               "defines": {...}, "languages": {"glsl" | "hlsl":
                                   {"na": why} | {gpu family: PROGRAM}}}],
                 "materials": {material: {"specialised": program index, "full": index}},
                 "summary": {language: {gpu family: {"specialised" | "full": {"programs",
                             "instructions_max", "vgprs_max", "subgroups_per_simd_min"},
                             "vgprs_saved_max", "subgroups_gained_max"}}}}
    PROGRAM = {"instructions", "vgprs", "sgprs", "latency", "inverse_throughput",
               "subgroups_per_simd", "code_size", "wave_size", "branches"}

``instructions.per_eval`` is null where valgrind is missing and under ``--quick`` (a
callgrind worker spends 15-55 s in start-up whatever it counts). Time units: ns per
evaluation, except the hardware sRGB encode (ns per pixel: one encode per pixel).
"""

from __future__ import annotations

import datetime
import sys
import tempfile
from pathlib import Path

import numpy as np

from . import families as families_mod
from . import count_check, gpu, kernel, measure, report


def _ratio(value, exact):
    if value is None or exact is None or exact == 0:
        return None
    return float(value / exact)


def _mean(values):
    return None if values is None else float(np.mean(values))


def _time_stats(ns):
    if ns is None:
        return {"median": None, "p25": None, "p75": None, "min": None, "max": None, "rounds": 0}
    return {"median": float(np.median(ns)), "p25": float(np.percentile(ns, 25)),
            "p75": float(np.percentile(ns, 75)), "min": float(np.min(ns)), "max": float(np.max(ns)),
            "rounds": int(len(ns))}


def _specialisation_scenes() -> dict:
    from .worker import _bench_scene
    return {name: _bench_scene(name) for name in measure.SPECIALISATION_SCENES}


def run(out_dir, family: str | None = None, quick: bool = False, progress=measure.progress) -> dict:
    """Measure, write the outputs into ``out_dir`` and return the JSON document. Each step
    prints a line when it starts and, on a terminal, a live line with its seconds once it has
    run two seconds (pbrlab.foundation.progress)."""
    from ..foundation import progress as live

    stages = live.Stages()
    try:
        return _measure_and_write(out_dir, family, quick, progress, stages)
    finally:
        stages.close()


def _measure_and_write(out_dir, family, quick, progress, stages) -> dict:
    from ..foundation import outputs
    from ..foundation.errors import PbrlabError

    out_dir = Path(out_dir)
    if family is not None and family not in families_mod.BY_NAME:
        raise PbrlabError(f"unknown family {family!r}; choose from {', '.join(families_mod.BY_NAME)}")
    fams = [families_mod.BY_NAME[family]] if family else list(families_mod.FAMILIES)
    try:
        out_dir.mkdir(parents=True, exist_ok=True)
    except FileExistsError:
        raise PbrlabError(f"--out {out_dir}: exists and is not a directory") from None
    except OSError as exc:
        raise PbrlabError(f"--out {out_dir}: cannot create the folder: {exc.strerror or exc}") from None
    for target in report.report_paths({"families": [{"name": f.name} for f in fams]}, out_dir):
        outputs.check_writable_target(target)  # before minutes of measuring, not after
    settings = measure.Settings.make(quick)
    steps = len(fams) + 6  # + time, instructions, frame, specialisation, tier images, GPU ISA
    step = iter(range(1, steps + 1))

    def tick(what):
        progress(f"[{next(step)}/{steps}] {what}")
        stages.start(what)

    machine = measure.machine_info()
    errors = {}
    for fam in fams:
        tick(f"error: {fam.name} ({len(fam.variants)} variants)")
        errors[fam.name] = measure.measure_errors(fam, settings)
    kernels, plans = measure.kernel_specs(fams)
    with tempfile.TemporaryDirectory(prefix="pbrlab-bench-") as tmp:
        tmp = Path(tmp)
        tick(f"time: {len(kernels)} kernels x {settings.time_rounds} interleaved rounds (LP_NUM_THREADS=1)")
        times = measure.measure_time(kernels, plans, settings, tmp)
        tick("instructions: skipped under --quick" if settings.count_families == () else
             f"instructions: callgrind of {len(kernels)} kernels x 2 trip counts x "
             f"{measure.COUNT_PASSES} passes (~1 min)")
        counts = measure.measure_instructions(kernels, plans, settings, tmp)
        tick(f"frame cost: default scene at {settings.frame_size}^2 per tier")
        frame = measure.measure_frame(settings, tmp)
        tick("specialised vs full programs: frame cost per test scene")
        specialisation = measure.measure_specialisation(settings, tmp)
    frame["scene"] = str(measure.DEFAULT_SCENE.relative_to(measure.DEFAULT_SCENE.parents[2]))
    tick("tier image error against the HIGH tier")
    tier_images = measure.tier_image_error(scale=settings.tier_image_scale)
    tick("GPU ISA: the kernels and the scenes' programs for RDNA3, RDNA2, GCN5 (RADV null device)")
    isa = gpu.measure(kernels, plans, families_mod.BY_NAME, _specialisation_scenes())
    stages.close()
    if not isa["available"]:
        progress(f"GPU ISA columns NOT measured: {isa['reason']}")
    machine["gpu_isa_devices"] = isa["devices"]
    for name, record in specialisation["scenes"].items():
        record["gpu_isa"] = isa["scenes"].get(name)

    doc_families = []
    for fam in fams:
        exact_t = times.get((fam.name, fam.exact))
        exact_t = float(np.median(exact_t)) if exact_t is not None else None
        exact_c = _mean(counts.get((fam.name, fam.exact)))
        variants = []
        for v in fam.variants:
            ns = times.get((fam.name, v.name))
            t = _time_stats(ns)
            t["ratio_to_exact"] = _ratio(t["median"], exact_t)
            passes = counts.get((fam.name, v.name))
            c = _mean(passes)
            record = {"name": v.name, "expression": v.expression, "note": v.note,
                      "defines": dict(v.defines), **errors[fam.name][v.name],
                      "time_ns": t,
                      "instructions": {"per_eval": c, "ratio_to_exact": _ratio(c, exact_c),
                                       "counts": passes},
                      "gpu_isa": isa["kernels"].get((fam.name, v.name))}
            variants.append(record)
        doc_families.append({"name": fam.name, "title": fam.title, "reference": fam.reference_name,
                             "domain": fam.domain_note, "exact": fam.exact,
                             "unit": "per evaluation (hardware sRGB encode: per pixel)", "variants": variants})
    doc = {"schema": report.SCHEMA_ID, "quick": quick,
           "generated": datetime.datetime.now(datetime.timezone.utc).isoformat(timespec="seconds"),
           "machine": machine,
           "method": {"evals_per_iteration": kernel.EVALS_PER_ITERATION,
                      "time_size": settings.time_size, "time_trips": settings.time_trips,
                      "time_rounds": settings.time_rounds, "count_size": settings.count_size,
                      "count_trips": list(settings.count_trips),
                      "count_passes": measure.COUNT_PASSES, "count_tolerance": count_check.TOLERANCE,
                      "lp_num_threads_timing": 1,
                      "noise_note": report.NOISE_NOTE},
           "families": doc_families, "frame": frame, "tier_images": tier_images,
           "specialisation": specialisation,
           "gpu_isa": {"available": isa["available"], "reason": isa["reason"],
                       "families": dict(gpu.FORCE_FAMILY), "devices": isa["devices"],
                       "float16": isa.get("float16_feature"), "float16_study": isa.get("float16"),
                       "note": gpu.ACO_NOTE,
                       "kernel_note": gpu.KERNEL_NOTE}}
    problems = report.validate(doc)
    if problems:
        raise RuntimeError("bench produced an invalid document:\n" + "\n".join(problems))
    report.write_report(doc, out_dir)
    progress(f"wrote {out_dir / 'accuracy_cost.md'}, accuracy_cost.json and {len(doc_families)} plots")
    return doc
