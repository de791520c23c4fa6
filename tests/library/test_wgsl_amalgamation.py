"""The WGSL amalgamation (wgsl/pbrlab.wgsl, pbrlab.gpu.port_wgsl) and naga's reading of the library.

* The committed file is what the generator writes (naga-cli NAGA_VERSION, installed by
  scripts/setup.sh), naga validates it, and wgpu builds it into compute pipelines.
* Its functions compute what the GLSL computes: each case below runs in WGSL through wgpu on
  lavapipe and in GLSL through pbrlab.evaluate on llvmpipe, on the same 3,564 inputs.
  Bound, derived as in tests/examples/test_wgpu_example.py: the same float32 arithmetic on the
  same LLVM back end, differing only where the compilers order or fuse operations; the most
  sensitive term is GGX's peak, slope at most 4 (1 - a^2) / a^2 in NdotH (93.5 at the grid's
  smallest alpha, 0.45^2), times 16 u of rounding in NdotH (u = 2^-24): 8.9e-5, relative above 1
  and absolute below (the inputs and intermediate terms are O(1), so a small result carries their
  absolute rounding). Measured: bit-identical in every case but pbr_shade_punctual, 6.9e-8 (one
  ulp) there. The control pairs the WGSL fast visibility with the GLSL exact one (their
  documented difference): 91 % of values over the bound, worst 0.15.
* naga accepts the library only because its #error messages carry no quote: the control shows
  naga rejecting a quote in a branch the preprocessor skips.
"""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np
import pytest

from pbrlab import evaluate
from pbrlab.foundation.errors import PbrlabError, ShaderCompileError
from pbrlab.gpu import naga, port_wgsl, shaders

ROOT = Path(__file__).resolve().parents[2]
LAVAPIPE_ICD = "/usr/share/vulkan/icd.d/lvp_icd.x86_64.json"
SHIPPED = port_wgsl.WGSL_ROOT / port_wgsl.WGSL_FILE
UNIT_ROUNDOFF = 2.0 ** -24
SMALLEST_ALPHA = 0.45 ** 2  # the grid's smallest roughness (y), as alpha in pbr_shade_punctual
MAX_DEVIATION = 4 * (1 - SMALLEST_ALPHA ** 2) / SMALLEST_ALPHA ** 2 * 16 * UNIT_ROUNDOFF
SETUP_HINT = " (bash scripts/setup.sh installs it)"

# name: (GLSL expression, WGSL expression) of x, y, z (p.x, p.y, p.z in WGSL), as a vec4
CASES = {
    "D_GGX": ("vec4(pbr_D_GGX(x, y))", "vec4<f32>(pbr_D_GGX(p.x, p.y))"),
    "V_SmithGGXCorrelated": ("vec4(pbr_V_SmithGGXCorrelated(x, z, y))",
                             "vec4<f32>(pbr_V_SmithGGXCorrelated(p.x, p.z, p.y))"),
    "F_Schlick_vec3": ("vec4(pbr_F_Schlick(vec3(y, 0.5, 0.04), x), 0.0)",
                       "vec4<f32>(pbr_F_Schlick_1(vec3<f32>(p.y, 0.5, 0.04), p.x), 0.0)"),
    "env_brdf": ("vec4(pbr_env_brdf(x, y), 0.0, 0.0)", "vec4<f32>(pbr_env_brdf(p.x, p.y), 0.0, 0.0)"),
    "shade_punctual": (
        "vec4(pbr_shade_punctual(vec3(0.0, 0.0, 1.0), vec3(sqrt(1.0 - x * x), 0.0, x), "
        "vec3(0.0, sqrt(1.0 - z * z), z), vec3(1.0), vec3(0.5), vec3(0.04), y), 0.0)",
        "vec4<f32>(pbr_shade_punctual(vec3<f32>(0.0, 0.0, 1.0), vec3<f32>(sqrt(1.0 - p.x * p.x), 0.0, p.x), "
        "vec3<f32>(0.0, sqrt(1.0 - p.z * p.z), p.z), vec3<f32>(1.0), vec3<f32>(0.5), vec3<f32>(0.04), p.y), 0.0)"),
    "tonemap": ("vec4(pbr_tonemap(vec3(4.0 * x, y, z)), 0.0)",
                "vec4<f32>(pbr_tonemap(vec3<f32>(4.0 * p.x, p.y, p.z)), 0.0)"),
    "srgb_and_pow5": ("vec4(pbr_linear_to_srgb(vec3(x, y, z)), pbr_pow5(x))",
                      "vec4<f32>(pbr_linear_to_srgb_1(vec3<f32>(p.x, p.y, p.z)), pbr_pow5_(p.x))"),
}
CONTROL = ("vec4(pbr_V_SmithGGXCorrelated(x, z, y))", "vec4<f32>(pbr_V_SmithGGXCorrelatedFast(p.x, p.z, p.y))")


def _naga_or_fail() -> str:
    try:
        return naga.naga_binary()
    except PbrlabError as exc:
        pytest.fail(str(exc))


def test_the_committed_wgsl_is_the_generated_one():
    _naga_or_fail()
    assert SHIPPED.is_file(), f"{SHIPPED} is missing: python -m pbrlab.gpu.port_wgsl writes it"
    assert SHIPPED.read_text(encoding="utf-8") == port_wgsl.generate(), \
        "wgsl/pbrlab.wgsl is stale: regenerate it with python -m pbrlab.gpu.port_wgsl"


def test_one_naga_version_is_pinned_and_installed():
    """scripts/setup.sh installs the version pbrlab.gpu.naga names, and that is the binary found."""
    import re
    setup = (ROOT / "scripts" / "setup.sh").read_text(encoding="utf-8")
    assert re.search(r"^NAGA_VERSION=(\S+)$", setup, re.M).group(1) == naga.NAGA_VERSION
    assert naga.naga_version(_naga_or_fail()) == naga.NAGA_VERSION


def test_naga_validates_the_shipped_wgsl():
    import subprocess
    run = subprocess.run([_naga_or_fail(), "--input-kind", "wgsl", str(SHIPPED)], capture_output=True, text=True,
                         timeout=60)
    assert run.returncode == 0, run.stderr


def test_naga_translates_the_library_with_its_unity_layer_unchanged():
    """What examples/threejs amalgamates (the library and the Unity layer), as it is, plus a main."""
    _naga_or_fail()
    glsl = "#version 450\n" + shaders.amalgamate(ROOT / "examples" / "threejs" / "library_entry.glsl") + \
        "\nvoid main() {}\n"
    wgsl = naga.glsl_to_wgsl(glsl, "frag", "library_entry.glsl")
    assert "fn LightingStandard(" in wgsl and "fn pbr_D_GGX(" in wgsl


def test_naga_rejects_a_quote_even_in_a_skipped_branch():
    """Why the library's #error messages are bare: the same file with the message quoted fails."""
    _naga_or_fail()
    bare = "#version 450\n#if 0\n#error PBR_X: unknown value\n#endif\nvoid main() {}\n"
    naga.glsl_to_wgsl(bare)
    with pytest.raises(ShaderCompileError, match="UnexpectedCharacter"):
        naga.glsl_to_wgsl(bare.replace("PBR_X: unknown value", '"PBR_X: unknown value"'))


def _inputs() -> np.ndarray:
    x, y, z = np.meshgrid(np.linspace(0, 1, 33), np.linspace(0.45, 1, 12), np.linspace(0.05, 1, 9), indexing="ij")
    return np.stack([x.ravel(), y.ravel(), z.ravel(), np.zeros(x.size)], axis=-1).astype(np.float32)


@pytest.fixture(scope="module")
def wgsl_values():
    """Every case's WGSL values: {name: N x 4}, one compute pipeline per case on one module."""
    try:
        import wgpu
    except ImportError:
        pytest.fail("the Python package wgpu is not installed" + SETUP_HINT)
    cases = dict(CASES, control=CONTROL)
    entries = "".join(f"\n@compute @workgroup_size(64)\nfn pbrlab_eval_{name}(@builtin(global_invocation_id) id: vec3<u32>) {{\n"
                      "    if (id.x >= arrayLength(&pbrlab_inputs)) { return; }\n"
                      f"    let p = pbrlab_inputs[id.x];\n    pbrlab_outputs[id.x] = {wgsl};\n}}\n"
                      for name, (_, wgsl) in cases.items())
    source = SHIPPED.read_text(encoding="utf-8") + (
        "\n@group(0) @binding(0) var<storage, read> pbrlab_inputs: array<vec4<f32>>;\n"
        "@group(0) @binding(1) var<storage, read_write> pbrlab_outputs: array<vec4<f32>>;\n") + entries
    with pytest.MonkeyPatch.context() as mp:
        if "VK_ICD_FILENAMES" not in os.environ:
            mp.setenv("VK_ICD_FILENAMES", LAVAPIPE_ICD)  # read when wgpu first opens Vulkan
        adapters = [a for a in wgpu.gpu.enumerate_adapters_sync() if a.info["backend_type"] == "Vulkan"]
    assert adapters, f"wgpu found no Vulkan adapter: Mesa's lavapipe ({LAVAPIPE_ICD})" + SETUP_HINT
    device = adapters[0].request_device_sync()
    module = device.create_shader_module(code=source)
    points = _inputs()
    inputs = device.create_buffer_with_data(data=points.tobytes(), usage=wgpu.BufferUsage.STORAGE)
    values = {}
    for name in cases:
        outputs = device.create_buffer(size=points.nbytes, usage=wgpu.BufferUsage.STORAGE | wgpu.BufferUsage.COPY_SRC)
        pipeline = device.create_compute_pipeline(layout="auto",
                                                  compute={"module": module, "entry_point": f"pbrlab_eval_{name}"})
        group = device.create_bind_group(layout=pipeline.get_bind_group_layout(0), entries=[
            {"binding": 0, "resource": {"buffer": inputs}}, {"binding": 1, "resource": {"buffer": outputs}}])
        encoder = device.create_command_encoder()
        compute = encoder.begin_compute_pass()
        compute.set_pipeline(pipeline)
        compute.set_bind_group(0, group)
        compute.dispatch_workgroups((len(points) + 63) // 64)
        compute.end()
        device.queue.submit([encoder.finish()])
        values[name] = np.frombuffer(device.queue.read_buffer(outputs), np.float32).reshape(-1, 4)
    return values


def _deviation(glsl: str, wgsl_values: np.ndarray) -> np.ndarray:
    p = _inputs()
    ours = evaluate(glsl, x=p[:, 0], y=p[:, 1], z=p[:, 2])
    return np.abs(wgsl_values - ours) / np.maximum(np.abs(ours), 1.0)


@pytest.mark.parametrize("name", sorted(CASES))
def test_the_shipped_wgsl_computes_what_the_glsl_computes(wgsl_values, name):
    deviation = _deviation(CASES[name][0], wgsl_values[name])
    assert deviation.max() <= MAX_DEVIATION, (name, f"worst {deviation.max():.3g}, bound {MAX_DEVIATION:.3g}",
                                              f"{(deviation > MAX_DEVIATION).mean():.2%} over")


def test_the_bound_tells_two_functions_apart(wgsl_values):
    """The control: the fast visibility in WGSL against the exact one in GLSL fails the bound."""
    assert _deviation(CONTROL[0], wgsl_values["control"]).max() > MAX_DEVIATION


def test_the_shipped_wgsl_carries_the_licence_notice():
    """As every shader file an engine copies (tests/library/test_license_notice.py), in its header."""
    header = SHIPPED.read_text(encoding="utf-8").split("\nstruct ", 1)[0]
    assert "// SPDX-License-Identifier: MIT. Part of pbrlab" in header
