"""AMD GPU instruction-set costs of what `pbrlab bench` measures (issue 16), from Mesa's
RADV/ACO on a null device (pbrlab.gpu.isa): no AMD GPU needed, nothing is run.

* **Kernels**: the same fragment programs the bench times on llvmpipe (``measure.kernel_specs``:
  every variant and each family's baseline), compiled for RDNA3 (gfx1100), RDNA2 (navi21)
  and GCN5 (vega10). Per evaluation: (variant − baseline) / ``kernel.EVALS_PER_ITERATION``
  of ACO's static *Instructions*, *Latency* and *Inverse Throughput*, and of the 16-bit,
  packed and transcendental vector-ALU counts of the disassembly; the variant program's
  VGPRs (absolute). Static counts: every instruction of the binary counts once, so a loop
  body counts once and both sides of a branch count. The kernel's loop (a uniform trip
  count: never unrolled) holds ``EVALS_PER_ITERATION`` evaluations and is the only part
  that differs from the baseline, so the difference over 8 is the static cost of one
  evaluation.
* **Scene programs**: every program a test scene of the specialisation section compiles
  (``features.plan_programs``, specialised and full; the templates of ``pbrlab.gpu.programs``),
  in GLSL and in HLSL (the ``hlsl_ports`` library through glslang's HLSL front end), with
  the program's instructions, VGPRs and RADV's *Subgroups per SIMD* (the waves that fit
  one SIMD given the registers: what the VGPRs cost in occupancy).

What ACO's figures are: a static count and a cycle estimate of one wave from ACO's
instruction model, with no clocks, no memory system (a texture fetch costs its issue, not
its latency), no other waves and so no occupancy effect beyond the register figure. They
rank programs on one family; they are not frame times.
"""

from __future__ import annotations

import hashlib
from dataclasses import dataclass

from ..render import features, tangent_frames
from ..gpu import programs
from ..foundation.errors import PbrlabError
from ..gpu.isa import compile as gpu_isa
from ..gpu.hlsl import HLSL_ROOT
from . import kernel

FORCE_FAMILY = dict(gpu_isa.FAMILIES)  # rdna3, rdna2, gcn5 -> RADV_FORCE_FAMILY
GPU_FAMILIES = tuple(FORCE_FAMILY)
TITLES = {"rdna3": "RDNA3", "rdna2": "RDNA2", "gcn5": "GCN5"}
LANGUAGES = ("glsl", "hlsl")
PROGRAM_KINDS = ("specialised", "full")

ACO_NOTE = ("AMD figures: ACO's statistics from Mesa's RADV compiling for a forced GPU family on "
            "a null device (no GPU; nothing runs). *Instructions* is static: every instruction of "
            "the binary counts once, so a loop body counts once and both sides of a branch count. "
            "*Latency* and *Inverse Throughput* are ACO's cycle estimates for one wave from its "
            "instruction model: no clocks, no memory system (a texture fetch costs its issue, not "
            "its latency), no other waves, so no occupancy effect beyond what the VGPR figure "
            "implies (*waves/SIMD*: RADV's Subgroups per SIMD). They rank programs on one family; "
            "they are not frame times.")
KERNEL_NOTE = ("Per evaluation: (variant − family baseline) / 8 of the timing kernel's statistics: "
               "its loop (uniform trip count, never unrolled) holds 8 evaluations and is all that "
               "differs from the baseline, so a static count of it over 8 is the static cost of one "
               "evaluation. The baseline is the same program without the term: each evaluation's "
               "inputs made from a per-pixel, per-iteration hash (what a shader's loads would give: "
               "values the compiler cannot know), its derived values (the shading frame n, tx, ty "
               "that turns per evaluation, l and v in it) and their sum into the output (what a "
               "shader's store would keep alive); subtracting it leaves the term alone. Nothing is "
               "constant across evaluations, so no part of the term folds. VGPRs: of the variant's "
               "whole program (absolute).")
SRGB_TEXTURE_NOTE = ("on AMD the sRGB decode happens in the texture unit (the format is in the "
                     "descriptor): the program is the same as the UNORM8 fetch, so its cost is 0")
HARDWARE_ENCODE_NA = ("n/a: the sRGB encode happens in the colour-buffer hardware on the way to "
                      "memory; the fragment program is the same as for a UNORM8 target")
UNITY_NA = "n/a: a ShaderLab material (pbrlab.importers.unity builds its program; not compiled here)"

# statistic name in RADV -> key in the bench's JSON
_PROGRAM_STATS = {"Instructions": "instructions", "VGPRs": "vgprs", "SGPRs": "sgprs",
                  "Latency": "latency", "Inverse Throughput": "inverse_throughput",
                  "Subgroups per SIMD": "subgroups_per_simd", "Code size": "code_size",
                  "Wave size": "wave_size", "Branches": "branches"}
_PER_EVAL_STATS = {"Instructions": "instructions_per_eval", "Latency": "latency_per_eval",
                   "Inverse Throughput": "inverse_throughput_per_eval"}
_PER_EVAL_ISA = {"valu_f16": "valu_f16_per_eval", "valu_packed": "valu_packed_per_eval",
                 "transcendental": "transcendental_per_eval"}


def unavailable_reason() -> str | None:
    """None when RADV's null device compiles here; else why not (one line)."""
    return gpu_isa.available()


def require_null_device() -> None:
    """For a benchmark script: exit with the reason when RADV's null device cannot compile here."""
    reason = unavailable_reason()
    if reason:
        raise SystemExit(f"RADV's null device is not available here: {reason}")


# ---- compiling, each distinct program once --------------------------------------------------

def _compile(jobs: dict, families) -> dict:
    """``{family: {key: statistics}}`` for ``{key: Job}``; identical programs compile once
    (the sRGB and UNORM8 texture kernels are one program)."""
    by_text, unique = {}, {}
    for key, job in jobs.items():
        dirs = tuple(str(d) for d in job.include_dirs)
        digest = hashlib.sha256(repr((job.fragment, job.language, job.vertex, job.entry,
                                      dirs)).encode()).hexdigest()[:16]
        unique.setdefault(digest, gpu_isa.Job(digest, job.fragment, job.language, job.vertex,
                                              job.entry, dirs))
        by_text[key] = digest
    compiled = gpu_isa.run(list(unique.values()), families) if unique else {f: {} for f in families}
    return {family: {key: compiled[family][digest] for key, digest in by_text.items()}
            | {"_device": compiled[family].get("_device", {})} for family in families}


# ---- kernels -----------------------------------------------------------------------------------

def kernel_jobs(kernels) -> dict:
    """The bench's kernels (``measure.kernel_specs``) as jobs; the hardware-encode kernels
    (a render-target format, the same program) are left out."""
    return {k["id"]: gpu_isa.Job(k["id"], k["fragment"]) for k in kernels if "target" not in k}


def per_eval(variant: dict, baseline: dict) -> dict:
    """One family's figures for a variant against its baseline (RADV statistics dicts)."""
    out = {key: (variant[stat] - baseline[stat]) / kernel.EVALS_PER_ITERATION
           for stat, key in _PER_EVAL_STATS.items()}
    out.update({key: (variant["isa"][name] - baseline["isa"][name]) / kernel.EVALS_PER_ITERATION
                for name, key in _PER_EVAL_ISA.items()})
    out.update({"vgprs": variant["VGPRs"], "vgprs_baseline": baseline["VGPRs"],
                "sgprs": variant["SGPRs"], "subgroups_per_simd": variant["Subgroups per SIMD"],
                "wave_size": variant["Wave size"],
                "instructions": variant["Instructions"],
                "baseline_instructions": baseline["Instructions"]})
    return out


def kernel_figures(plans, compiled: dict, families_by_name: dict) -> dict:
    """``{(family, variant): {"families": {gpu family: figures}, "note": str} or {"na": why}}``."""
    out = {}
    for plan in plans:
        key = (plan["family"], plan["variant"])
        if plan["kind"] == "pixel":
            out[key] = {"na": HARDWARE_ENCODE_NA}
            continue
        variant = next(v for v in families_by_name[plan["family"]].variants if v.name == plan["variant"])
        note = SRGB_TEXTURE_NOTE if variant.texture == "srgb8" else ""
        out[key] = {"note": note, "families": {
            family: per_eval(compiled[family][plan["id"]], compiled[family][plan["baseline"]])
            for family in compiled}}
    return out


# ---- scene programs -----------------------------------------------------------------------------

@dataclass(frozen=True)
class SceneProgram:
    """One program a scene compiles: the draw's template stem, its defines and surface."""
    stem: str                 # sphere | mesh
    defines: tuple            # sorted (name, value) pairs
    surface: object           # the material's surface file (GLSL path) or None
    unity: bool               # a ShaderLab material (not compiled here)

    def job(self, language: str) -> gpu_isa.Job:
        surface = programs.surface_file(self.surface, language)
        name = programs.fragment_template(self.stem, language)
        if language == "glsl":
            return gpu_isa.Job(name, programs.template_source(name, dict(self.defines), surface).text)
        text, dirs = programs.hlsl_template_text(name, dict(self.defines), surface)
        return gpu_isa.Job(name, text, language="hlsl", include_dirs=tuple(map(str, [*dirs, HLSL_ROOT])))


def scene_programs(scene, kind: str, checking: bool = True) -> dict:
    """``{SceneProgram: [material, ...]}``: the distinct programs of one render of
    ``scene`` (``kind`` specialised or full; ``checking`` False: the production programs,
    features.plan_programs) and the materials drawn with each. A mesh of pbrlab's own
    material has the renderer's per-draw tangent define (tangent_frames.draw_defines)."""
    plan = features.plan_programs(scene, specialise=kind == "specialised", checking=checking)
    out: dict = {}
    for obj in scene.objects:
        material = scene.materials[obj.material]
        unity = material.source is not None  # a shader of its own (a Unity shader's material)
        stem = "mesh" if obj.sphere is None or (unity and material.source.moves_vertices) else "sphere"
        defines = dict(plan.defines[obj.material])
        if not unity and obj.sphere is None:  # the renderer's _draw_mesh, one object per draw
            defines.update(tangent_frames.draw_defines([obj], defines, scene.render.antialias,
                                                       material.surface is not None))
        program = SceneProgram(stem, tuple(sorted(defines.items())), material.surface, unity)
        names = out.setdefault(program, [])
        if obj.material not in names:
            names.append(obj.material)
    return out


def _program_stats(statistics: dict) -> dict:
    return {key: statistics[stat] for stat, key in _PROGRAM_STATS.items()}


def scene_jobs(scenes: dict) -> tuple[dict, dict]:
    """(jobs by key, layout): ``layout[scene][kind]`` lists ``(SceneProgram, materials)``;
    a job's key is ``scene|kind|index|language``."""
    jobs, layout, skipped = {}, {}, {}
    for name, scene in scenes.items():
        layout[name] = {}
        for kind in PROGRAM_KINDS:
            entries = list(scene_programs(scene, kind).items())
            layout[name][kind] = entries
            for index, (program, _) in enumerate(entries):
                for language in LANGUAGES:
                    key = f"{name}|{kind}|{index}|{language}"
                    if program.unity:
                        skipped[key] = UNITY_NA
                        continue
                    try:
                        jobs[key] = program.job(language)
                    except PbrlabError as exc:  # e.g. a surface file without its HLSL twin
                        skipped[key] = f"n/a: {exc}"
    return jobs, {"layout": layout, "skipped": skipped}


def scene_figures(layout: dict, compiled: dict) -> dict:
    """Per scene: its programs with their figures per language and family, each material's
    (specialised, full) program pair, and a summary per language and family."""
    out = {}
    for name, kinds in layout["layout"].items():
        record = {"programs": [], "materials": {}}
        index_of = {}
        for kind, entries in kinds.items():
            for index, (program, materials) in enumerate(entries):
                languages = {}
                for language in LANGUAGES:
                    key = f"{name}|{kind}|{index}|{language}"
                    if key in layout["skipped"]:
                        languages[language] = {"na": layout["skipped"][key]}
                    else:
                        languages[language] = {family: _program_stats(compiled[family][key])
                                               for family in compiled}
                index_of[(kind, index)] = len(record["programs"])
                for material in materials:
                    record["materials"].setdefault(material, {})[kind] = len(record["programs"])
                record["programs"].append({"kind": kind, "stem": program.stem, "materials": materials,
                                           "defines": dict(program.defines), "languages": languages})
        record["summary"] = _scene_summary(record, list(compiled))
        out[name] = record
    return out


def _scene_summary(record: dict, families) -> dict:
    """Per language and family, per kind: the largest program's instructions and VGPRs and
    the fewest waves per SIMD (the heaviest program sets them); and over the materials, the
    most VGPRs specialisation saves (full minus specialised, same material)."""
    out = {}
    for language in LANGUAGES:
        out[language] = {}
        for family in families:
            row = {}
            for kind in PROGRAM_KINDS:
                stats = [p["languages"][language][family] for p in record["programs"]
                         if p["kind"] == kind and family in p["languages"][language]]
                row[kind] = ({"programs": len(stats),
                              "instructions_max": max(s["instructions"] for s in stats),
                              "vgprs_max": max(s["vgprs"] for s in stats),
                              "subgroups_per_simd_min": min(s["subgroups_per_simd"] for s in stats)}
                             if stats else None)
            saved = []
            for pair in record["materials"].values():
                spec = record["programs"][pair["specialised"]]["languages"][language].get(family)
                full = record["programs"][pair["full"]]["languages"][language].get(family)
                if spec and full:
                    saved.append((full["vgprs"] - spec["vgprs"],
                                  full["subgroups_per_simd"] - spec["subgroups_per_simd"]))
            row["vgprs_saved_max"] = max((s[0] for s in saved), default=None)
            row["subgroups_gained_max"] = max((-s[1] for s in saved), default=None)
            out[language][family] = row
    return out


# ---- half precision that reaches the ISA ------------------------------------------------------

FLOAT16_FAMILY, FLOAT16_VARIANT = "brdf_tier", "low"
FLOAT16_NOTE = ("The LOW tier's kernel with Hammon's V and Schlick's F (the lobe the half study runs in "
                "half's range) compiled twice for Vulkan (#version 450): as it is (float32: "
                "RADV 22.3 ignores mediump / RelaxedPrecision) and with PBR_FLOAT16 under "
                "GL_EXT_shader_explicit_arithmetic_types_float16, where the specular lobe "
                "(pbr_DV_GGX_SmithCorrelatedFast_half) runs in float16_t. Per evaluation against the "
                "family baseline; 16-bit and packed (v_pk_*) counts from the disassembly. The "
                "kernel's inputs are float32, so the float16 lobe pays its conversions; its error in "
                "half is the half study's (tests/checking/hardcases/test_half.py).")
_FLOAT16_HEADER = ("#version 450\n#extension GL_EXT_shader_explicit_arithmetic_types_float16 : require\n"
                   "#define PBR_SPECULAR_V PBR_SPECULAR_V_SMITH_GGX_CORRELATED_FAST\n"
                   "#define PBR_SPECULAR_F PBR_SPECULAR_F_SCHLICK")


def float16_jobs(kernels) -> dict:
    """The LOW-tier kernel and its baseline in Vulkan GLSL, float32 and PBR_FLOAT16."""
    ids = {k["id"]: k for k in kernels}
    low = ids.get(f"{FLOAT16_FAMILY}/{FLOAT16_VARIANT}")
    base = ids.get(f"{FLOAT16_FAMILY}/_baseline")
    if low is None or base is None:
        return {}
    def vulkan(text, float16=False):
        text = text.replace("#version 330 core", _FLOAT16_HEADER, 1)
        return text.replace(_FLOAT16_HEADER, _FLOAT16_HEADER + "\n#define PBR_FLOAT16 1", 1) if float16 else text
    return {"f16|baseline": gpu_isa.Job("f16|baseline", vulkan(base["fragment"])),
            "f16|float32": gpu_isa.Job("f16|float32", vulkan(low["fragment"])),
            "f16|float16": gpu_isa.Job("f16|float16", vulkan(low["fragment"], float16=True))}


def float16_figures(compiled: dict) -> dict | None:
    """Per GPU family: the float32 and float16 LOW kernels per evaluation (per_eval)."""
    if "f16|float16" not in compiled[next(iter(compiled))]:
        return None
    return {"note": FLOAT16_NOTE, "families": {
        family: {precision: per_eval(compiled[family][f"f16|{precision}"], compiled[family]["f16|baseline"])
                 for precision in ("float32", "float16")} for family in compiled}}


# ---- everything --------------------------------------------------------------------------------

def measure(kernels, plans, families_by_name: dict, scenes: dict, gpu_families=GPU_FAMILIES) -> dict:
    """Compile the bench's kernels and the scenes' programs; ``{"available": False,
    "reason": ...}`` when RADV's null device cannot be made here."""
    reason = unavailable_reason()
    if reason is not None:
        return {"available": False, "reason": reason, "devices": None, "kernels": {}, "scenes": {}}
    jobs = kernel_jobs(kernels)
    program_jobs, layout = scene_jobs(scenes)
    compiled = _compile({**jobs, **program_jobs, **float16_jobs(kernels)}, gpu_families)
    devices = {family: compiled[family]["_device"].get("name") for family in gpu_families}
    float16 = {family: compiled[family]["_device"].get("float16") for family in gpu_families}
    return {"available": True, "reason": None, "devices": devices, "float16_feature": float16,
            "kernels": kernel_figures(plans, compiled, families_by_name),
            "float16": float16_figures(compiled),
            "scenes": scene_figures(layout, compiled)}

