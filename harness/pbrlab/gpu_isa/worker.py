"""``python -m pbrlab.gpu_isa.worker SPEC.json OUT.json``: compile each job of the spec on
the RADV null device that ``RADV_FORCE_FAMILY`` selects (see pbrlab.gpu_isa.compile) and
write ``{job id: {statistic: value, "isa": {...}}}`` for the fragment stage."""

from __future__ import annotations

import json
import sys

from ..errors import PbrlabError
from . import isa, spirv, vulkan
from .compile import FULLSCREEN_VERTEX, STATISTICS
from .device import Device


def compile_job(device: Device, job: dict, vertex_cache: dict) -> dict:
    vertex_text = job.get("vertex") or FULLSCREEN_VERTEX
    if vertex_text not in vertex_cache:
        vertex_cache[vertex_text] = spirv.compile_glsl(vertex_text, "vertex")
    vertex = vertex_cache[vertex_text]
    hlsl = job.get("language") == "hlsl"
    fragment = spirv.compile_glsl(job["fragment"], "fragment", hlsl=hlsl,
                                  entry=job.get("entry", "main"))
    reflection = spirv.reflect(fragment)
    sets = spirv.descriptor_sets(spirv.reflect(vertex), reflection)
    executables = device.graphics(vertex, fragment, sets, spirv.colour_outputs(reflection))
    stage = [e for e in executables if e.stages & vulkan.STAGE_FRAGMENT]
    if not stage:
        raise PbrlabError(f"{job['id']}: RADV reported no fragment executable")
    stats = {name: stage[0].statistics.get(name) for name in STATISTICS}
    stats["isa"] = isa.summary(stage[0].disassembly)
    return stats


def main(argv=None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    spec_path, out_path = argv
    jobs = json.loads(open(spec_path).read())
    try:
        device = Device("RADV")
        cache: dict = {}
        result = {job["id"]: compile_job(device, job, cache) for job in jobs}
        result["_device"] = {"name": device.name, "float16": device.float16}
    except PbrlabError as exc:
        print(f"pbrlab.gpu_isa: {exc}", file=sys.stderr)
        return 1
    with open(out_path, "w") as f:
        json.dump(result, f)
    return 0


if __name__ == "__main__":
    sys.exit(main())
