"""Issue 35, the per-pixel setup that the scene program inlines twice: pbrlab's scene template
calls the lighting once for the environment and once per light (Unity's structure), so the
anisotropic tangent (pbr_anisotropic_tangent: the environment's bent normal and the lights'
frame) and the film's Fresnel (pbr_F_Iridescence: the base's and the coat's F0 at the same
NdotV, in every call) appear more than once with the same inputs. The compiler merges the
copies only where they are straight-line code: a `?:` with a call as an operand is a branch in
glslang's SPIR-V, and two identical branches are kept twice (benchmarks/whole_program_cost.py,
1 light + environment, RDNA3: anisotropy 638 -> 597, iridescence 836 -> 806 instructions once
both functions select between values formed before the select; docs/bench.md).

The check, on RADV's null device (RDNA3): a kernel that calls the function twice with the same
inputs (from varyings: nothing folds) compiles to exactly as many instructions as the kernel
that calls it once and uses the value twice. Exact equality, not a bound: merged copies are the
same program. The control: the same kernels with the library's function respelled as it was
(the call inside the `?:`) cost more called twice than once, so the kernel does see an unmerged
copy (measured, RDNA3 instructions once / twice: tangent 93 / 93, former spelling 94 / 120;
film 260 / 260, former spelling 262 / 274, since the film is pbr_thin_film and one base's terms
with the phase shift as a sign: 272 / 272 and 274 / 289 before).
"""

import pytest

from pbrlab.bench import kernel
from pbrlab.gpu.isa import compile as gpu

_HEAD = """#version 330 core
#include "pbr/pbr.glsl"
in vec3 pbrlab_n;
in vec3 pbrlab_direction;
in vec3 pbrlab_f0;
in vec3 pbrlab_film;  // film IOR, thickness (nm), NdotV
out vec4 pbrlab_result;
void main() {
    vec3 n = normalize(pbrlab_n);
"""
_TAIL = "    pbrlab_result = vec4(a + 2.0 * b, 1.0);\n}\n"

# function -> (its call, the library's current select, the former spelling: the call in the ?:)
CASES = {
    "pbr_anisotropic_tangent": (
        "pbr_anisotropic_tangent(n, pbrlab_direction)",
        "return t2 > PBR_ANISOTROPY_MIN_SIN * PBR_ANISOTROPY_MIN_SIN ? projected : fallback;",
        "return t2 > PBR_ANISOTROPY_MIN_SIN * PBR_ANISOTROPY_MIN_SIN ? projected "
        ": pbr_tangent_to_world(vec3(1.0, 0.0, 0.0), n);"),
    "pbr_F_Iridescence": (
        "pbr_F_Iridescence(1.0, pbrlab_film.x, pbrlab_film.z, pbrlab_film.y, pbrlab_f0)",
        "return f.thicknessNm > 0.0 ? F : noFilm;",
        "return f.thicknessNm > 0.0 ? F : pbr_F_Schlick(baseF0, f.c1);"),
}


def _program(call: str, twice: bool, respell=None) -> str:
    body = f"    vec3 a = {call};\n    vec3 b = {call if twice else 'a'};\n"
    text = kernel.expanded(_HEAD + body + _TAIL)
    if respell is not None:
        current, former = respell
        assert text.count(current) == 1, f"the library no longer spells its select as {current!r}: update CASES"
        text = text.replace(current, former)
    return text


@pytest.fixture(scope="module")
def instructions():
    if (why := gpu.available()) is not None:
        pytest.fail(f"RADV null device unavailable (scripts/setup.sh installs it): {why}")
    jobs = []
    for name, (call, current, former) in CASES.items():
        for spelling, respell in (("library", None), ("former", (current, former))):
            for twice in (False, True):
                jobs.append(gpu.Job(f"{name}|{spelling}|{twice}", _program(call, twice, respell)))
    compiled = gpu.run(jobs, families=("rdna3",))["rdna3"]
    return {job.id: compiled[job.id]["Instructions"] for job in jobs}


@pytest.mark.parametrize("name", tuple(CASES))
def test_two_inlined_calls_with_the_same_inputs_cost_one(instructions, name):
    once, twice = instructions[f"{name}|library|False"], instructions[f"{name}|library|True"]
    former_once, former_twice = instructions[f"{name}|former|False"], instructions[f"{name}|former|True"]
    print(f"{name}: once {once}, twice {twice}; former spelling once {former_once}, twice {former_twice} "
          "(RDNA3 instructions)")
    assert twice == once
    # control: with the call inside the ?:, the second copy is kept
    assert former_twice > former_once
