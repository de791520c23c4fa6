"""benchmarks/tier_program_cost.py runs, and what it reports has the order the tiers claim
(issue 35, the whole lit pixel; no measured ratio is pinned: the figures are the bench's):
the production program of the metallic torus costs LOW < MEDIUM < HIGH RDNA3 instructions, LOW's
environment read costs less than HIGH's (the tier's choices in pbr/shading/dispatch.glsl), and
the same LOW program with those choices forced back to HIGH's costs more (the control: the
saving comes from them). Its image errors: HIGH against the float64 CPU renderer within the
GPU-against-CPU bound of tests/render/test_gpu_matches_cpu_reference.py, LOW further off (it is
another model)."""

import dataclasses
import importlib.util
from pathlib import Path

import pytest

from pbrlab.bench import gpu

SCRIPT = Path(__file__).resolve().parents[2] / "benchmarks" / "tier_program_cost.py"
# test_gpu_matches_cpu_reference.py's per-channel bound for every pixel: |gpu - cpu| <= 1e-5 +
# 5e-3 |cpu| (float32 against float64 through the whole renderer); on the torus's luminance
# (at least 0.012 on every covered pixel, float64) that is at most 5e-3 + 1e-5 / 0.012 = 5.9e-3
# relative. Measured: 5.4e-5.
HIGH_RELATIVE_BOUND = 5.9e-3
# LOW's environment choices forced back to HIGH's (explicit macros win over the tier)
HIGH_READ = "#define PBR_ENERGY_COMPENSATION 1\n#define PBR_IBL_DOMINANT_DIRECTION 1\n" \
            "#define PBR_IBL_HORIZON_OCCLUSION 1\n#define PBR_SPECULAR_OCCLUSION 1\n"


def _bench():
    spec = importlib.util.spec_from_file_location("tier_program_cost", SCRIPT)
    bench = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(bench)
    return bench


def test_whole_pixel_costs_follow_the_tiers():
    if (why := gpu.unavailable_reason()) is not None:
        pytest.fail(f"RADV null device unavailable (scripts/setup.sh installs it): {why}")
    bench = _bench()
    per = bench.figures("metallic torus", families=("rdna3",))
    whole = {q: per[(q, "whole pixel")]["rdna3"][0] for q in bench.QUALITIES}
    assert whole["low"] < whole["medium"] < whole["high"], whole
    environment = {q: whole[q] - per[(q, "without the environment")]["rdna3"][0] for q in bench.QUALITIES}
    assert environment["low"] < environment["high"], environment
    # the control: LOW's program with HIGH's environment read
    (program,) = gpu.scene_programs(bench._scene("metallic torus", "low"), "specialised", checking=False)
    job = program.job("glsl")
    marker = "#define PBR_QUALITY PBR_QUALITY_LOW\n"
    assert marker in job.fragment
    forced = dataclasses.replace(job, fragment=job.fragment.replace(marker, marker + HIGH_READ))
    compiled = gpu._compile({"forced": forced}, ("rdna3",))
    assert compiled["rdna3"]["forced"]["Instructions"] > whole["low"]


def test_image_errors_of_the_tiers():
    bench = _bench()
    errors = bench.image_errors("metallic torus")
    assert errors["high"][2] <= HIGH_RELATIVE_BOUND, errors["high"]
    assert errors["low"][0] > errors["high"][2], errors  # LOW's median beyond HIGH's worst


# LOW's normal-map frame and DFG table axes forced back to HIGH's
HIGH_FRAME_AND_TABLE = "#define PBR_NORMAL_MAP_FRAME 1\n#define PBR_DFG_LUT_LAYOUT 1\n"


def test_the_class_costs_follow_the_tiers_and_lows_frame_and_table_save():
    """On the whole-program bench's metallic-roughness class (normal-mapped): LOW < MEDIUM <
    HIGH, and LOW's program with HIGH's frame and table costs more, and more again than with
    only one of them set back (each choice saves on its own: no measured figure pinned)."""
    if (why := gpu.unavailable_reason()) is not None:
        pytest.fail(f"RADV null device unavailable (scripts/setup.sh installs it): {why}")
    bench = _bench()
    per = bench.figures(bench.CLASS, families=("rdna3",))
    whole = {q: per[(q, "whole pixel")]["rdna3"][0] for q in bench.QUALITIES}
    assert whole["low"] < whole["medium"] < whole["high"], whole
    (program,) = gpu.scene_programs(bench._scene(bench.CLASS, "low"), "specialised", checking=False)
    job = program.job("glsl")
    marker = "#define PBR_QUALITY PBR_QUALITY_LOW\n"
    assert marker in job.fragment
    variants = {name: dataclasses.replace(job, fragment=job.fragment.replace(marker, marker + extra))
                for name, extra in (("frame", "#define PBR_NORMAL_MAP_FRAME 1\n"),
                                    ("table", "#define PBR_DFG_LUT_LAYOUT 1\n"),
                                    ("both", HIGH_FRAME_AND_TABLE))}
    compiled = gpu._compile(variants, ("rdna3",))["rdna3"]
    count = {name: compiled[name]["Instructions"] for name in variants}
    assert whole["low"] < count["frame"] < count["both"], (whole["low"], count)
    assert whole["low"] < count["table"] < count["both"], (whole["low"], count)
