"""Compile programs for AMD GPU families and return what ACO made of them.

RADV reads ``RADV_FORCE_FAMILY`` when a Vulkan instance enumerates its devices, so each
family is compiled in a subprocess of its own (``python -m pbrlab.gpu_isa.worker``), with
Mesa's shader cache off (a cached pipeline must not stand in for a compile) and an
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
from dataclasses import dataclass
from pathlib import Path

from ..errors import PbrlabError

# name -> RADV_FORCE_FAMILY
FAMILIES = {"rdna3": "gfx1100", "rdna2": "navi21", "gcn5": "vega10"}

# Statistics carried into pbrlab's figures (RADV's names).
STATISTICS = ("Instructions", "VGPRs", "SGPRs", "Code size", "Latency", "Inverse Throughput",
              "Copies", "Branches", "Subgroups per SIMD")

# A full-screen triangle (the Vulkan twin of pbrlab.bench.kernel's vertex stage).
FULLSCREEN_VERTEX = """#version 450
void main() {
    vec2 p = vec2(float((gl_VertexIndex << 1) & 2), float(gl_VertexIndex & 2));
    gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
}
"""


@dataclass(frozen=True)
class Job:
    """One program to compile. ``fragment`` is GLSL (OpenGL dialect) or HLSL text with its
    includes expanded; ``vertex`` None uses the full-screen triangle."""
    id: str
    fragment: str
    language: str = "glsl"     # glsl | hlsl
    vertex: str | None = None
    entry: str = "main"        # the HLSL fragment entry point


def available() -> str | None:
    """None when a RADV null device can be made here; else why not (one line)."""
    try:
        result = run([Job("probe", "#version 450\nlayout(location=0) out vec4 c;\n"
                                   "void main() { c = vec4(1.0); }\n")], families=("rdna3",))
    except PbrlabError as exc:
        return str(exc)
    return None if result["rdna3"].get("probe") else "RADV compiled nothing"


def run(jobs: list, families=tuple(FAMILIES)) -> dict:
    """``{family: {job id: {statistic: value, ..., "isa": {...}}}}`` for every family."""
    out = {}
    with tempfile.TemporaryDirectory(prefix="pbrlab-gpu-isa-") as tmp:
        spec = Path(tmp) / "spec.json"
        spec.write_text(json.dumps([job.__dict__ for job in jobs]))
        runtime = Path(tmp) / "xdg"
        runtime.mkdir(mode=0o700)
        for family in families:
            result = Path(tmp) / f"{family}.json"
            env = dict(os.environ, RADV_FORCE_FAMILY=FAMILIES[family],
                       MESA_SHADER_CACHE_DISABLE="true",
                       XDG_RUNTIME_DIR=os.environ.get("XDG_RUNTIME_DIR") or str(runtime))
            proc = subprocess.run([sys.executable, "-m", "pbrlab.gpu_isa.worker", str(spec),
                                   str(result)], env=env, capture_output=True, text=True)
            if proc.returncode != 0 or not result.exists():
                message = (proc.stderr.strip().splitlines() or [f"exit {proc.returncode}"])[-1]
                if proc.returncode < 0:
                    message = f"the compiler process died (signal {-proc.returncode})"
                raise PbrlabError(f"GPU ISA ({family}, RADV_FORCE_FAMILY={FAMILIES[family]}): "
                                  f"{message}")
            out[family] = json.loads(result.read_text())
    return out
