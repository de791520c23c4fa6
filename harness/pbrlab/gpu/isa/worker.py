"""``python -m pbrlab.gpu.isa.worker SPEC.json OUT.json``: make each pipeline of the spec
(SPIR-V files and layouts that pbrlab.gpu.isa.compile prepared) on the RADV null device
that ``RADV_FORCE_FAMILY`` selects, and write ``{job id: {statistic: value, "isa": {...}}}``
for the fragment stage."""

from __future__ import annotations

import json
import sys
from pathlib import Path

from ...foundation.errors import PbrlabError
from . import isa, vulkan
from .compile import STATISTICS
from .device import Device


def compile_job(device: Device, job: dict) -> dict:
    sets = {int(k): [tuple(row) for row in rows] for k, rows in job["sets"].items()}
    executables = device.graphics(Path(job["vertex"]).read_bytes(),
                                  Path(job["fragment"]).read_bytes(), sets, job["colours"])
    stage = [e for e in executables if e.stages & vulkan.STAGE_FRAGMENT]
    if not stage:
        raise PbrlabError(f"{job['id']}: RADV reported no fragment executable")
    stats = {name: stage[0].statistics.get(name) for name in STATISTICS}
    stats["Wave size"] = stage[0].subgroup_size
    stats["isa"] = isa.summary(stage[0].disassembly)
    return stats


def main(argv=None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    spec_path, out_path = argv
    jobs = json.loads(open(spec_path).read())
    try:
        device = Device("RADV")
        result = {job["id"]: compile_job(device, job) for job in jobs}
        result["_device"] = {"name": device.name, "float16": device.float16}
    except PbrlabError as exc:
        print(f"pbrlab.gpu.isa: {exc}", file=sys.stderr)
        return 1
    with open(out_path, "w") as f:
        json.dump(result, f)
    return 0


if __name__ == "__main__":
    sys.exit(main())
