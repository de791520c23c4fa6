"""The AMD GPU ISA part of the bench report (bench/gpu.py's figures): its checks in the
JSON document, the machine line, the table beside each family's table, and the
scene-program tables (specialised versus full; GLSL versus HLSL)."""

from __future__ import annotations

import math

from .gpu import GPU_FAMILIES, LANGUAGES, PROGRAM_KINDS, TITLES

KERNEL_FIELDS = ("instructions_per_eval", "latency_per_eval", "inverse_throughput_per_eval",
                 "valu_f16_per_eval", "valu_packed_per_eval", "transcendental_per_eval",
                 "vgprs", "vgprs_baseline", "sgprs", "subgroups_per_simd", "wave_size")
PROGRAM_FIELDS = ("instructions", "vgprs", "sgprs", "latency", "inverse_throughput",
                  "subgroups_per_simd", "wave_size")


def _finite(value) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value)


def _check_numbers(record, fields, where, problems):
    for key in fields:
        if not _finite(record.get(key)):
            problems.append(f"{where}.{key}: expected a finite number, got {record.get(key)!r}")


def validate(doc: dict) -> list[str]:
    """Problems with the gpu_isa fields: where RADV was available every variant has its
    figures for every family (or says why there is none) and every test scene its
    programs; where it was not, the document says why."""
    problems: list[str] = []
    isa = doc["gpu_isa"]
    if not isa.get("available"):
        if not isinstance(isa.get("reason"), str) or not isa["reason"]:
            problems.append("$.gpu_isa: not available, and no reason given")
        return problems
    families = list(isa.get("families") or {})
    if families != list(GPU_FAMILIES):
        problems.append(f"$.gpu_isa.families: expected {list(GPU_FAMILIES)}, got {families}")
    for fam in doc["families"]:
        for v in fam.get("variants", []):
            where = f"$.families[{fam.get('name')}].{v.get('name')}.gpu_isa"
            record = v.get("gpu_isa")
            if not isinstance(record, dict):
                problems.append(f"{where}: not compiled")
            elif "na" in record:
                if not isinstance(record["na"], str):
                    problems.append(f"{where}.na: expected the reason")
            else:
                for family in GPU_FAMILIES:
                    if family not in record.get("families", {}):
                        problems.append(f"{where}: missing {family}")
                    else:
                        _check_numbers(record["families"][family], KERNEL_FIELDS,
                                       f"{where}.{family}", problems)
    for name, scene in doc["specialisation"]["scenes"].items():
        where = f"$.specialisation.scenes[{name}].gpu_isa"
        record = scene.get("gpu_isa")
        if not isinstance(record, dict) or not record.get("programs"):
            problems.append(f"{where}: no programs compiled")
            continue
        for i, program in enumerate(record["programs"]):
            for language in LANGUAGES:
                figures = program["languages"].get(language)
                if figures is None:
                    problems.append(f"{where}.programs[{i}]: missing {language}")
                elif "na" not in figures:
                    for family in GPU_FAMILIES:
                        _check_numbers(figures.get(family, {}), PROGRAM_FIELDS,
                                       f"{where}.programs[{i}].{language}.{family}", problems)
    return problems


def _n(x, digits: int = 1) -> str:
    if x is None:
        return "—"
    if isinstance(x, int):
        return str(x)
    return f"{x:.{digits}f}"


def machine_line(doc: dict) -> str:
    isa = doc["gpu_isa"]
    if not isa["available"]:
        return (f"**AMD GPU ISA: NOT MEASURED.** {isa['reason']} The GPU columns are empty "
                "(install libvulkan1 and mesa-vulkan-drivers: sudo apt-get install libvulkan1 "
                "mesa-vulkan-drivers; in a pbrlab checkout, scripts/setup.sh does).")
    devices = ", ".join(f"{TITLES[f]}: `{isa['devices'][f]}` (RADV_FORCE_FAMILY={isa['families'][f]})"
                        for f in GPU_FAMILIES)
    return f"**AMD GPU ISA**: Mesa RADV/ACO null devices, {devices}."


def intro(doc: dict) -> list[str]:
    isa = doc["gpu_isa"]
    if not isa["available"]:
        return [f"> AMD GPU ISA columns not measured: {isa['reason']}", ""]
    return [f"> {isa['note']}", "", f"> {isa['kernel_note']}", ""]


def family_table(fam: dict, doc: dict) -> list[str]:
    """The AMD columns of a family's variants: a second table under the family's own."""
    if not doc["gpu_isa"]["available"]:
        return ["AMD GPU ISA: not measured (see the machine line).", ""]
    head = ("| variant | RDNA3 instr/eval | RDNA3 latency/eval | RDNA3 inv. thr./eval | RDNA3 VGPRs | "
            "RDNA2 instr/eval | RDNA2 VGPRs | GCN5 instr/eval | GCN5 VGPRs | GCN5 waves/SIMD | "
            "RDNA3 transc./eval | RDNA3 16-bit / packed VALU/eval | note |")
    lines = [f"AMD GPU ISA of the same kernels (ACO, static; per evaluation except VGPRs; baseline "
             f"program's VGPRs in brackets):", "", head, "|" + "---|" * 13]
    for v in fam["variants"]:
        record = v["gpu_isa"]
        if "na" in record:
            lines.append(f"| `{v['name']}` | n/a |" + " |" * 10 + f" {record['na']} |")
            continue
        r3, r2, g5 = (record["families"][f] for f in ("rdna3", "rdna2", "gcn5"))
        lines.append(
            f"| `{v['name']}` | {_n(r3['instructions_per_eval'], 2)} | {_n(r3['latency_per_eval'], 0)} | "
            f"{_n(r3['inverse_throughput_per_eval'], 0)} | {r3['vgprs']} [{r3['vgprs_baseline']}] | "
            f"{_n(r2['instructions_per_eval'], 2)} | {r2['vgprs']} [{r2['vgprs_baseline']}] | "
            f"{_n(g5['instructions_per_eval'], 2)} | {g5['vgprs']} [{g5['vgprs_baseline']}] | "
            f"{g5['subgroups_per_simd']} | {_n(r3['transcendental_per_eval'], 2)} | "
            f"{_n(r3['valu_f16_per_eval'], 2)} / {_n(r3['valu_packed_per_eval'], 2)} | {record['note']} |")
    return lines + [""]


def _pair(spec, full, key) -> str:
    return f"{_n(spec[key]) if spec else '—'} / {_n(full[key]) if full else '—'}"


def specialisation_tables(doc: dict) -> list[str]:
    """Per scene the heaviest program of each kind per family, then every material's
    (specialised, full) pair on RDNA3 and GCN5 (GLSL)."""
    if not doc["gpu_isa"]["available"]:
        return ["AMD GPU ISA of the scene programs: not measured (see the machine line).", ""]
    scenes = doc["specialisation"]["scenes"]
    lines = ["AMD GPU ISA of the same programs (GLSL; ACO's static statistics of each distinct "
             "fragment program the render compiles; *max* / *min* over the scene's programs: the "
             "heaviest program sets them). Cells: specialised / full. *waves/SIMD*: RADV's "
             "Subgroups per SIMD, the waves that fit one SIMD given the program's registers. "
             "A static count holds every copy of an unrolled loop: NIR unrolls the full program's "
             "light loops (8 slots per light type, a runtime exit) where their body is small, so a "
             "cheap BRDF variant can make a full program *longer* (more *branches* in the JSON).", "",
             "| scene | programs | RDNA3 instr max | RDNA3 VGPRs max | RDNA3 waves/SIMD min | "
             "RDNA2 instr max | RDNA2 VGPRs max | GCN5 instr max | GCN5 VGPRs max | "
             "GCN5 waves/SIMD min | VGPRs saved, most for one material (RDNA3 / GCN5) |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    for name, record in scenes.items():
        s = record["gpu_isa"]["summary"]["glsl"]
        cells = []
        for family, keys in (("rdna3", ("instructions_max", "vgprs_max", "subgroups_per_simd_min")),
                             ("rdna2", ("instructions_max", "vgprs_max")),
                             ("gcn5", ("instructions_max", "vgprs_max", "subgroups_per_simd_min"))):
            cells += [_pair(s[family]["specialised"], s[family]["full"], k) for k in keys]
        counts = _pair(s["rdna3"]["specialised"], s["rdna3"]["full"], "programs")
        saved = f"{_n(s['rdna3']['vgprs_saved_max'])} / {_n(s['gcn5']['vgprs_saved_max'])}"
        lines.append(f"| `{name}` | {counts} | " + " | ".join(cells) + f" | {saved} |")
    lines += ["", _occupancy_sentence(scenes), "",
              "Per material (GLSL; materials drawn with the same pair of programs share a row):", "",
              "| scene | materials | draw | RDNA3 instr | RDNA3 VGPRs | RDNA3 waves | GCN5 instr | "
              "GCN5 VGPRs | GCN5 waves |", "|---|---|---|---|---|---|---|---|---|"]
    for name, record in scenes.items():
        isa = record["gpu_isa"]
        pairs: dict = {}
        for material, pair in isa["materials"].items():
            pairs.setdefault((pair["specialised"], pair["full"]), []).append(material)
        for (si, fi), materials in pairs.items():
            spec, full = isa["programs"][si], isa["programs"][fi]
            shown = ", ".join(f"`{m}`" for m in materials[:4]) + (
                f" and {len(materials) - 4} more" if len(materials) > 4 else "")
            cells = []
            for family in ("rdna3", "gcn5"):
                a, b = spec["languages"]["glsl"].get(family), full["languages"]["glsl"].get(family)
                cells += [_pair(a, b, k) for k in ("instructions", "vgprs", "subgroups_per_simd")]
            lines.append(f"| `{name}` | {shown} | {spec['stem']} | " + " | ".join(cells) + " |")
    return lines + [""]


def _occupancy_sentence(scenes: dict) -> str:
    """What the VGPR figures mean for occupancy, from the figures themselves."""
    parts = []
    for family in GPU_FAMILIES:
        waves = {p["languages"]["glsl"][family]["subgroups_per_simd"]
                 for r in scenes.values() for p in r["gpu_isa"]["programs"]
                 if family in p["languages"]["glsl"]}
        sizes = {p["languages"]["glsl"][family]["wave_size"]
                 for r in scenes.values() for p in r["gpu_isa"]["programs"]
                 if family in p["languages"]["glsl"]}
        size = "/".join(f"wave{w}" for w in sorted(sizes))
        if len(waves) == 1:
            parts.append(f"{TITLES[family]} ({size}): {waves.pop()} waves/SIMD for every program, so "
                         "these VGPR counts do not limit its occupancy")
        else:
            parts.append(f"{TITLES[family]} ({size}): {min(waves)} to {max(waves)} waves/SIMD, so "
                         "the VGPRs specialisation saves buy occupancy there")
    return "Occupancy: " + "; ".join(parts) + "."


def language_table(doc: dict) -> list[str]:
    """GLSL against HLSL: the same programs from the two libraries, per scene and kind."""
    if not doc["gpu_isa"]["available"]:
        return []
    lines = ["### GLSL versus HLSL (AMD GPU ISA)", "",
             "The same scene programs from the GLSL library and from its HLSL port (`hlsl_ports/`, "
             "glslang's HLSL front end with its legalising optimiser; `Texture2D` + `SamplerState` "
             "as combined samplers, as the harness compiles them), through the same RADV/ACO. "
             "*instr*: total over the scene's distinct programs, GLSL / HLSL; *VGPRs*: the most of "
             "one program; *largest difference*: of one program's instructions, HLSL minus GLSL.", "",
             "| scene | programs | RDNA3 instr | RDNA2 instr | GCN5 instr | RDNA3 VGPRs | "
             "GCN5 VGPRs | largest difference (RDNA3) |", "|---|---|---|---|---|---|---|---|"]
    for name, record in doc["specialisation"]["scenes"].items():
        for kind in PROGRAM_KINDS:
            programs = [p for p in record["gpu_isa"]["programs"] if p["kind"] == kind
                        and "na" not in p["languages"]["glsl"] and "na" not in p["languages"]["hlsl"]]
            skipped = sum(1 for p in record["gpu_isa"]["programs"] if p["kind"] == kind) - len(programs)
            if not programs:
                lines.append(f"| `{name}` ({kind}) | 0 (+{skipped} n/a) |" + " — |" * 6)
                continue
            cells = []
            for family in GPU_FAMILIES:
                g = sum(p["languages"]["glsl"][family]["instructions"] for p in programs)
                h = sum(p["languages"]["hlsl"][family]["instructions"] for p in programs)
                cells.append(f"{g} / {h}")
            for family in ("rdna3", "gcn5"):
                g = max(p["languages"]["glsl"][family]["vgprs"] for p in programs)
                h = max(p["languages"]["hlsl"][family]["vgprs"] for p in programs)
                cells.append(f"{g} / {h}")
            diffs = [p["languages"]["hlsl"]["rdna3"]["instructions"]
                     - p["languages"]["glsl"]["rdna3"]["instructions"] for p in programs]
            largest = max(diffs, key=abs)
            count = f"{len(programs)}" + (f" (+{skipped} n/a)" if skipped else "")
            lines.append(f"| `{name}` ({kind}) | {count} | " + " | ".join(cells) + f" | {largest:+d} |")
    return lines + [""]


def float16_table(doc: dict) -> list[str]:
    """The LOW tier in float32 and with PBR_FLOAT16 (float16_t), per AMD family."""
    study = doc["gpu_isa"].get("float16_study")
    if not doc["gpu_isa"]["available"] or not study:
        return []
    lines = ["## Half precision on AMD GPUs (LOW tier, `PBR_FLOAT16`)", "", study["note"], "",
             "| family | precision | instr/eval | 16-bit VALU/eval | packed (v_pk) /eval | "
             "transcendental/eval | VGPRs |", "|---|---|---|---|---|---|---|"]
    for family in GPU_FAMILIES:
        for precision in ("float32", "float16"):
            r = study["families"][family][precision]
            lines.append(f"| {TITLES[family]} | {precision} | {_n(r['instructions_per_eval'], 2)} | "
                         f"{_n(r['valu_f16_per_eval'], 2)} | {_n(r['valu_packed_per_eval'], 2)} | "
                         f"{_n(r['transcendental_per_eval'], 2)} | {r['vgprs']} |")
    return lines + [""]
