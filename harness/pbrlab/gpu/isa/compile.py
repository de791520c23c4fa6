"""Compile programs for AMD GPU families and return what ACO made of them.

The family-independent work is done once, here: glslang to SPIR-V, spirv-cross's
reflection (the descriptor layout, the colour outputs) and the vertex stage that feeds the
fragment's inputs (pbrlab.gpu.isa.vertex). RADV reads ``RADV_FORCE_FAMILY`` when a Vulkan
instance enumerates its devices, so each family's pipelines are made in a subprocess of
its own (``python -m pbrlab.gpu.isa.worker``, the families side by side), with Mesa's
shader cache off (a cached pipeline must not stand in for a compile) and an
``XDG_RUNTIME_DIR`` (the loader wants one).

What the figures are: ACO's static statistics of the compiled program. *Instructions*
counts every instruction in the binary once, so a loop body counts once and both sides
of a branch count; *Latency* and *Inverse Throughput* are ACO's cycle estimates for one
wave from its instruction model, with no clocks, no memory system, no other waves. They
rank programs on one family; they are not frame times."""

from __future__ import annotations

import json
import os
import subprocess
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass
from pathlib import Path

from ...foundation.errors import PbrlabError
from . import spirv
from .vertex import feeding_vertex

# name -> RADV_FORCE_FAMILY
FAMILIES = {"rdna3": "gfx1100", "rdna2": "navi21", "gcn5": "vega10"}

# Statistics carried into pbrlab's figures (RADV's names).
STATISTICS = ("Instructions", "VGPRs", "SGPRs", "Code size", "Latency", "Inverse Throughput",
              "Copies", "Branches", "Subgroups per SIMD")



@dataclass(frozen=True)
class Job:
    """One program to compile. ``fragment`` is GLSL (OpenGL dialect) with its includes
    expanded, or HLSL whose includes glslang resolves against ``include_dirs``; ``vertex``
    None: a vertex stage generated to feed every fragment input with a per-vertex value
    (pbrlab.gpu.isa.vertex), drawing the full-screen triangle."""
    id: str
    fragment: str
    language: str = "glsl"     # glsl | hlsl
    vertex: str | None = None
    entry: str = "main"        # the HLSL fragment entry point
    include_dirs: tuple = ()   # HLSL: where its #include files are


def available() -> str | None:
    """None when a RADV null device can be made here; else why not (one line)."""
    try:
        result = run([Job("probe", "#version 450\nlayout(location=0) out vec4 c;\n"
                                   "void main() { c = vec4(1.0); }\n")], families=("rdna3",))
    except PbrlabError as exc:
        return str(exc)
    return None if result["rdna3"].get("probe") else "RADV compiled nothing"


def _prepare(jobs: list, folder: Path) -> list:
    """Each job as the worker's spec entry: SPIR-V files of both stages, the descriptor
    sets and the colour-attachment count (glslang runs two at a time: it is a subprocess)."""
    def fragment(job):
        words = spirv.compile_glsl(job.fragment, "fragment", hlsl=job.language == "hlsl",
                                   entry=job.entry, include_dirs=job.include_dirs)
        return words, spirv.reflect(words)

    with ThreadPoolExecutor(max_workers=2) as pool:
        fragments = list(pool.map(fragment, jobs))
    vertices: dict = {}  # vertex text -> (path, reflection)
    entries = []
    for index, (job, (words, reflection)) in enumerate(zip(jobs, fragments)):
        vertex_text = job.vertex or feeding_vertex(reflection)
        if vertex_text not in vertices:
            vertex_words = spirv.compile_glsl(vertex_text, "vertex")
            path = folder / f"vertex{len(vertices)}.spv"
            path.write_bytes(vertex_words)
            vertices[vertex_text] = (path, spirv.reflect(vertex_words))
        vertex_path, vertex_reflection = vertices[vertex_text]
        fragment_path = folder / f"fragment{index}.spv"
        fragment_path.write_bytes(words)
        sets = spirv.descriptor_sets(vertex_reflection, reflection)
        entries.append({"id": job.id, "vertex": str(vertex_path), "fragment": str(fragment_path),
                        "sets": {str(k): rows for k, rows in sets.items()},
                        "colours": spirv.colour_outputs(reflection)})
    return entries


def run(jobs: list, families=tuple(FAMILIES)) -> dict:
    """``{family: {job id: {statistic: value, ..., "Wave size": 32 | 64, "isa": {...}},
    "_device": {...}}}`` (statistics: ``STATISTICS``, RADV's names)."""
    out = {}
    with tempfile.TemporaryDirectory(prefix="pbrlab-gpu-isa-") as tmp:
        spec = Path(tmp) / "spec.json"
        spec.write_text(json.dumps(_prepare(jobs, Path(tmp))))
        runtime = Path(tmp) / "xdg"
        runtime.mkdir(mode=0o700)
        procs = {}
        for family in families:
            result = Path(tmp) / f"{family}.json"
            env = dict(os.environ, RADV_FORCE_FAMILY=FAMILIES[family],
                       MESA_SHADER_CACHE_DISABLE="true",
                       XDG_RUNTIME_DIR=os.environ.get("XDG_RUNTIME_DIR") or str(runtime))
            procs[family] = (subprocess.Popen(
                [sys.executable, "-m", "pbrlab.gpu.isa.worker", str(spec), str(result)], env=env,
                stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True), result)
        for family, (proc, result) in procs.items():
            _, err = proc.communicate()
            if proc.returncode != 0 or not result.exists():
                message = (err.strip().splitlines() or [f"exit {proc.returncode}"])[-1]
                if proc.returncode < 0:
                    message = f"the compiler process died (signal {-proc.returncode})"
                raise PbrlabError(f"GPU ISA ({family}, RADV_FORCE_FAMILY={FAMILIES[family]}): "
                                  f"{message}")
            out[family] = json.loads(result.read_text())
    return out
