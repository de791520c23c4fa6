"""accuracy_cost.json (validated against SCHEMA), accuracy_cost.md and the Pareto plots
(the AMD GPU ISA parts: report_gpu.py)."""

from __future__ import annotations

import json
import math
from pathlib import Path

from ..foundation import outputs
from . import report_gpu

NOISE_NOTE = ("Times are CPU time on llvmpipe with LP_NUM_THREADS=1 (median of interleaved rounds, "
              "empty-loop baseline subtracted); differences below about 20 % are noise here. "
              "Instruction counts (callgrind) are repeatable and are the main cost column.")

# The record of one variant. Types: "num" (float, or null where the figure does not exist),
# "str", "dict", "dict?" (dict or null).
VARIANT_FIELDS = {
    "name": "str", "expression": "str?", "note": "str", "defines": "dict",
    "error": "dict", "self_error": "dict?",
    "time_ns": "dict", "instructions": "dict", "gpu_isa": "dict?",
}
ERROR_FIELDS = {"max_abs": "num", "max_rel": "num", "p99_rel": "num", "rmse": "num",
                "worst_abs_at": "dict", "worst_rel_at": "dict", "samples": "num", "nonfinite": "num"}
TIME_FIELDS = {"median": "num", "p25": "num", "p75": "num", "min": "num", "max": "num",
               "rounds": "num", "ratio_to_exact": "num"}
INSTRUCTION_FIELDS = {"per_eval": "num", "ratio_to_exact": "num"}
FAMILY_FIELDS = {"name": "str", "title": "str", "reference": "str", "domain": "str",
                 "exact": "str", "unit": "str", "variants": "list"}
TOP_FIELDS = {"schema": "str", "quick": "bool", "machine": "dict", "method": "dict",
              "families": "list", "frame": "dict", "tier_images": "dict", "specialisation": "dict",
              "gpu_isa": "dict"}
SCHEMA_ID = "pbrlab-bench/2"


def _check(obj, fields, where, problems):
    if not isinstance(obj, dict):
        problems.append(f"{where}: not an object")
        return
    for key, kind in fields.items():
        if key not in obj:
            problems.append(f"{where}: missing {key!r}")
            continue
        value, optional = obj[key], kind.endswith("?")
        kind = kind.rstrip("?")
        if value is None and (optional or kind == "num"):
            continue
        ok = {"str": isinstance(value, str), "dict": isinstance(value, dict),
              "list": isinstance(value, list), "bool": isinstance(value, bool),
              "num": isinstance(value, (int, float)) and not isinstance(value, bool)}[kind]
        if not ok:
            problems.append(f"{where}.{key}: expected {kind}, got {type(value).__name__}")


def validate(doc: dict) -> list[str]:
    """Problems with an accuracy_cost.json document ([] when it follows the schema of
    pbrlab.bench's docstring). Every variant must carry an error and both costs."""
    problems: list[str] = []
    _check(doc, TOP_FIELDS, "$", problems)
    if problems:
        return problems
    if doc["schema"] != SCHEMA_ID:
        problems.append(f"$.schema: expected {SCHEMA_ID!r}")
    for i, fam in enumerate(doc["families"]):
        where = f"$.families[{fam.get('name', i)}]"
        _check(fam, FAMILY_FIELDS, where, problems)
        names = [v.get("name") for v in fam.get("variants", [])]
        if fam.get("exact") not in names:
            problems.append(f"{where}: exact variant {fam.get('exact')!r} is not among {names}")
        for v in fam.get("variants", []):
            vw = f"{where}.{v.get('name')}"
            _check(v, VARIANT_FIELDS, vw, problems)
            _check(v.get("error"), ERROR_FIELDS, vw + ".error", problems)
            if v.get("self_error") is not None:
                _check(v["self_error"], ERROR_FIELDS, vw + ".self_error", problems)
            _check(v.get("time_ns"), TIME_FIELDS, vw + ".time_ns", problems)
            _check(v.get("instructions"), INSTRUCTION_FIELDS, vw + ".instructions", problems)
            if isinstance(v.get("error"), dict) and v["error"].get("max_rel") is None:
                problems.append(f"{vw}.error.max_rel: no error measured")
            if isinstance(v.get("time_ns"), dict) and v["time_ns"].get("median") is None:
                problems.append(f"{vw}.time_ns.median: no time measured")
            counted = isinstance(v.get("instructions"), dict) and v["instructions"].get("per_eval") is not None
            if not counted and not doc["quick"] and doc["machine"].get("valgrind"):
                problems.append(f"{vw}.instructions.per_eval: not counted")
    for tier in ("high", "medium", "low"):
        if tier not in doc["frame"].get("tiers", {}):
            problems.append(f"$.frame.tiers: missing {tier}")
        if tier not in doc["tier_images"].get("tiers", {}):
            problems.append(f"$.tier_images.tiers: missing {tier}")
    return problems + report_gpu.validate(doc)


def report_paths(doc: dict, out_dir: Path) -> list[Path]:
    """accuracy_cost.json, accuracy_cost.md and one Pareto plot per family, in ``out_dir``."""
    out_dir = Path(out_dir)
    return ([out_dir / "accuracy_cost.json", out_dir / "accuracy_cost.md"]
            + [out_dir / f"{fam['name']}.png" for fam in doc["families"]])


def write_report(doc: dict, out_dir: Path) -> list[Path]:
    """Write the report (``report_paths``) all or nothing (outputs.transaction): a full disk
    or a failing plot keeps the previous report whole, JSON, tables and plots alike, and
    the PbrlabError names the file that could not be written. Returns the paths written."""
    paths = report_paths(doc, out_dir)
    json_path, md_path, plots = paths[0], paths[1], paths[2:]
    with outputs.transaction(paths) as tx:
        write_json(doc, json_path, tx)
        tx.write_text(md_path, markdown(doc))
        for fam, plot in zip(doc["families"], plots):
            pareto_plot(fam, plot, doc["quick"], doc["gpu_isa"], tx=tx)
    return paths


def write_json(doc: dict, path: Path, tx: outputs.Transaction | None = None) -> None:
    """accuracy_cost.json (``tx``: a transaction holding ``path``; else a file of its own)."""
    text = json.dumps(doc, indent=1, sort_keys=False) + "\n"
    if tx is None:
        outputs.write_file(path, text)
    else:
        tx.write_text(path, text)


def _g(x, digits=2):
    if x is None:
        return "—"
    if isinstance(x, float) and not math.isfinite(x):
        return str(x)
    if x == 0:
        return "0"
    if abs(x) >= 1000 or abs(x) < 0.01:
        return f"{x:.{digits}e}".replace("e+0", "e").replace("e-0", "e-")
    return f"{x:.{digits + 1}g}"


def _where(at: dict) -> str:
    return ", ".join(f"{k} {v:g}" for k, v in at.items())


def markdown(doc: dict) -> str:
    m = doc["machine"]
    lines = [
        "# Accuracy versus cost (`pbrlab bench`)",
        "",
        f"Generated by `pbrlab bench{' --quick' if doc['quick'] else ''}`"
        + (" (QUICK: few samples and rounds, figures not for conclusions)" if doc["quick"] else "") + ".",
        "",
        f"**Machine**: {m['cpu']} ({m['cpu_count']} cores; features {', '.join(m['cpu_features'])}); "
        f"renderer `{m['GL_RENDERER']}`, Mesa {m['mesa']}, LLVM {m['llvm']}, backend {m['backend']}; "
        f"llvmpipe code generation pinned to `{m['llvmpipe_cpu_caps']}` (GALLIUM_OVERRIDE_CPU_CAPS, "
        f"4-wide SSE: one instruction serves 4 pixels). " + report_gpu.machine_line(doc),
        "",
        "**Columns.** *err*: against the family's float64 reference over the stated domain: max abs, "
        "max rel (where |ref| is above the floor), 99th-percentile rel, RMSE, and the inputs of the "
        "worst relative error. *instr/eval*: x86 instructions executed per evaluation (callgrind `Ir` of "
        "the draws, per pixel; deterministic: every kernel is counted in two passes, which must agree "
        "within 1 %). *ns/eval*: median CPU time [25th-75th percentile]. "
        "*×exact*: ratio to the family's exact variant. Under each family's table, the same "
        "kernels compiled for AMD GPUs (RDNA3, RDNA2, GCN5) by Mesa's ACO: static instructions, "
        "latency and inverse-throughput estimates per evaluation, and registers (notes below). "
        "Plots: error against x86 instructions (left) and RDNA3 instructions (right) per evaluation.",
        "",
        f"> {NOISE_NOTE}",
        "",
        *report_gpu.intro(doc),
    ]
    for fam in doc["families"]:
        lines += [f"## {fam['title']} (`{fam['name']}`)", "",
                  f"Reference: {fam['reference']}. Domain: {fam['domain']}. Exact variant: `{fam['exact']}`. "
                  f"Plot: [{fam['name']}.png]({fam['name']}.png).", "",
                  "| variant | max abs | mean abs | max rel | p99 rel | RMSE | worst rel at | instr/eval | ×exact | ns/eval | ×exact | note |",
                  "|---|---|---|---|---|---|---|---|---|---|---|---|"]
        for v in fam["variants"]:
            e, t, c = v["error"], v["time_ns"], v["instructions"]
            extra = f"; 8-bit: {v['lsb_8bit']} codes off" if v.get("lsb_8bit") is not None else ""
            own = (f"; float32 vs own twin: {_g(v['self_error']['max_rel'])} rel"
                   if v.get("self_error") else "")
            lines.append(
                f"| `{v['name']}` | {_g(e['max_abs'])} | {_g(e.get('mean_abs'))} | {_g(e['max_rel'])} | {_g(e['p99_rel'])} | "
                f"{_g(e['rmse'])} | {_where(e['worst_rel_at'])} | {_g(c['per_eval'], 1)} | "
                f"{_g(c['ratio_to_exact'])} | {_g(t['median'], 1)} [{_g(t['p25'], 1)}–{_g(t['p75'], 1)}] | "
                f"{_g(t['ratio_to_exact'])} | {v['note']}{extra}{own} |")
        lines.append("")
        lines += report_gpu.family_table(fam, doc)
    ti, fr = doc["tier_images"], doc["frame"]
    lines += ["## Quality tiers on the default scene", "",
              f"Scene `{fr['scene']}`. Image error at {ti['size'][0]}x{ti['size'][1]} against {ti['reference']}; "
              f"frame cost at {fr['size'][0]}x{fr['size'][1]}, CPU time, LP_NUM_THREADS=1, median of "
              f"{fr['rounds']} interleaved rounds; *shading* = frame minus the same render with no objects "
              f"(clear, readback, resolve: {_g(fr['setup_ms_median'], 1)} ms; the environment's prefilter, textures "
              f"and meshes are made once, at warm-up, and cached: pbrlab.render.resource_cache).", "",
              "| tier | max abs (linear) | max rel | median rel | max sRGB codes | pixels > 2 codes | "
              "frame ms | shading ms [25th–75th] | ×high |", "|---|---|---|---|---|---|---|---|---|"]
    for tier in ("high", "medium", "low"):
        e, f = ti["tiers"][tier], fr["tiers"][tier]
        lines.append(f"| {tier} | {_g(e['max_abs'])} | {_g(e['max_rel'])} | {_g(e['median_rel'])} | "
                     f"{e['max_srgb8_codes']} | {100 * e['fraction_over_2_codes']:.2f} % | "
                     f"{_g(f['total_ms_median'], 1)} | {_g(f['shading_ms_median'], 1)} "
                     f"[{_g(f['shading_ms_p25'], 1)}–{_g(f['shading_ms_p75'], 1)}] | {_g(f['ratio_to_high'])} |")
    sp = doc["specialisation"]
    lines += ["", "## Specialised versus full programs", "",
              f"Each test scene rendered with the programs specialised to it (pbrlab.render.features) and "
              f"with the full program (every effect compiled in, fed neutral values; bit-identical "
              f"images). CPU time per frame, LP_NUM_THREADS=1, median of {sp['rounds']} interleaved "
              f"rounds, size: {sp['size']}.", "",
              f"Instructions: callgrind Ir of the whole process for one frame at "
              f"{sp.get('instructions_size', ['?', '?'])[0]}x{sp.get('instructions_size', ['?', '?'])[1]} "
              f"(uniform uploads, draws, readback, resolve; mean of 2 passes in opposite orders, "
              f"which must agree within 1 %; not counted under --quick; scenes with an "
              f"environment or textures are not countable here: valgrind 3.19 cannot decode a GFNI "
              f"instruction a library executes on those paths on this host).", "",
              "| scene | programs (specialised / full) | specialised ms | full ms | full / specialised | "
              "specialised Ir | full Ir | full / specialised Ir |",
              "|---|---|---|---|---|---|---|---|"]
    for name, r in sp["scenes"].items():
        si, fi = r.get("specialised_instructions"), r.get("full_instructions")
        ratio = _g(fi / si) if si and fi else "–"
        lines.append(f"| `{name}` | {r['programs_specialised']} / {r['programs_full']} | "
                     f"{_g(r['specialised_ms_median'], 1)} | {_g(r['full_ms_median'], 1)} | "
                     f"{_g(r['full_over_specialised'])} | {_g(si, 1) if si else '–'} | "
                     f"{_g(fi, 1) if fi else '–'} | {ratio} |")
    lines += [""] + report_gpu.specialisation_tables(doc) + report_gpu.language_table(doc)
    lines += report_gpu.float16_table(doc)
    lines += [f"> {NOISE_NOTE}", ""]
    return "\n".join(lines)


def _rdna3_per_eval(v: dict):
    """RDNA3 instructions per evaluation, or None (not compiled, or n/a)."""
    record = v.get("gpu_isa")
    if not record or "na" in record:
        return None
    return record["families"]["rdna3"]["instructions_per_eval"]


def pareto_plot(fam: dict, path: Path, quick: bool, gpu_isa: dict | None = None,
                tx: outputs.Transaction | None = None) -> None:
    """Error (max relative, log) against cost (log), one point per variant, in two panels:
    x86 instructions per evaluation (callgrind) and RDNA3 instructions per evaluation
    (ACO, static). The exact variant is ringed. Zero cost or error is drawn at the axis
    floor; a variant without a figure (not counted, n/a) is left out of that panel.
    Variants are told apart by colour and marker in a legend beside the axes, never by labels
    next to the points (neighbouring variants overlapped into an unreadable smear)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    def _readable_log_ticks(axis):
        """Plain numbers on a log axis; within one decade matplotlib labels every minor tick
        in scientific notation, and the labels run into each other: keep a few."""
        from matplotlib.ticker import LogLocator, NullFormatter, ScalarFormatter
        axis.set_major_locator(LogLocator(base=10, subs=(1.0, 2.0, 5.0)))
        formatter = ScalarFormatter()
        formatter.set_scientific(False)
        axis.set_major_formatter(formatter)
        axis.set_minor_formatter(NullFormatter())

    fig, axes = plt.subplots(1, 2, figsize=(12.6, 4.4), dpi=110, sharey=True)
    floor_y = 1e-8
    markers = "osD^vP*Xh<>p"
    colours = plt.get_cmap("tab10").colors
    panels = ((axes[0], lambda v: v["instructions"]["per_eval"], 0.3,
               "x86 instructions per evaluation (callgrind"),
              (axes[1], _rdna3_per_eval, 0.1, "RDNA3 instructions per evaluation (ACO, static"))
    for ax, cost, floor_x, label_x in panels:
        for i, v in enumerate(fam["variants"]):
            x = cost(v)
            if x is None and ax is axes[1]:
                continue
            x = max(x or 0.0, floor_x)
            y = max(v["error"]["max_rel"] or 0.0, floor_y)
            exact = v["name"] == fam["exact"]
            colour = colours[i % len(colours)]
            label = v["name"] + (" (exact)" if exact else "")
            ax.scatter([x], [y], s=90 if exact else 45, marker="o" if exact else markers[i % len(markers)],
                       facecolors="none" if exact else colour, edgecolors=colour,
                       linewidths=2 if exact else 0.8, zorder=3, label=label, alpha=0.9)
        ax.set_xscale("log")
        ax.set_yscale("log")
        _readable_log_ticks(ax.xaxis)
        ax.set_xlabel(f"{label_x}; floor {floor_x})")
        ax.grid(True, which="both", alpha=0.3)
    if gpu_isa is not None and not gpu_isa.get("available"):
        axes[1].text(0.5, 0.5, "AMD GPU ISA not measured:\n" + str(gpu_isa.get("reason"))[:80],
                     ha="center", va="center", transform=axes[1].transAxes, fontsize=8, wrap=True)
    handles, labels = axes[0].get_legend_handles_labels()
    axes[1].legend(handles, labels, loc="upper left", bbox_to_anchor=(1.02, 1.0), fontsize=8,
                   frameon=False, title="variant", title_fontsize=8, borderaxespad=0.0)
    axes[0].set_ylabel(f"max relative error vs float64 reference (floor {floor_y:g})")
    fig.suptitle(f"{fam['title']}" + (" [quick]" if quick else ""), fontsize=10)
    fig.tight_layout()
    try:  # into the transaction ``tx`` when given (the report's), else a file of its own
        if tx is None:
            outputs.write_figure(path, fig)
        else:
            outputs.write_figure_in(tx, path, fig)
    finally:
        plt.close(fig)
