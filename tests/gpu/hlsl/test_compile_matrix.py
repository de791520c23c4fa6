"""Compilation matrix: every GLSL include alone as #version 330 core, #version 300 es,
#version 100 (GLSL ES 1.00 / WebGL 1; both ES columns with mediump default precision) and #version 450, plus all of them together as Vulkan GLSL 450
(-V --target-env vulkan1.0, SPIR-V generated); every HLSL port alone for pixel shader model
5.0 and 6.0 with glslang's HLSL front end. "Alone" means a shader that includes only that
file (it includes what it needs); glslang type-checks every function, called or not
(test_matrix_catches_a_broken_file).

What "SM 5.0" and "SM 6.0" mean here: glslang 12 has no shader-model switch (its HLSL
front end accepts one dialect, DX10-and-later HLSL, and emits SPIR-V). The two columns are
the two language modes a D3D compiler would see, reproduced with the macros FXC and DXC
predefine and the SPIR-V validator run on the result:
  5.0: __SHADER_TARGET_MAJOR 5, __SHADER_TARGET_MINOR 0 (FXC ps_5_0), glslang's legalising
       optimiser on (the default), --spirv-val;
  6.0: __SHADER_TARGET_MAJOR 6, __SHADER_TARGET_MINOR 0, __HLSL_VERSION 2018 (DXC ps_6_0),
       -Od (what the evaluator runs), --spirv-val.
The ports use nothing shader-model dependent (no 16-bit types, no wave ops, no vector ?:
which HLSL 2021 forbids: the generator refuses a boolean mix), so both compile
the same text; a real FXC/DXC run is not part of this toolchain.
"""

from __future__ import annotations

import os
import subprocess
import tempfile
from concurrent.futures import ThreadPoolExecutor

from pathlib import Path

import pytest

from pbrlab.gpu import hlsl, shaders
from pbrlab.foundation.errors import ShaderCompileError

GLSL_FILES = sorted(p.relative_to(shaders.GLSL_ROOT).as_posix() for p in (shaders.GLSL_ROOT / "pbr").rglob("*.glsl"))
HLSL_FILES = sorted(p.relative_to(hlsl.HLSL_ROOT).as_posix() for p in (hlsl.HLSL_ROOT / "pbr").rglob("*.hlsl"))

GLSL_TARGETS = {
    "330core": ("#version 330 core\n", []),
    "300es": ("#version 300 es\nprecision mediump float;\n", []),
    # GLSL ES 1.00 (WebGL 1, GLES 2): no uint, no bit operations, no boolean-vector mix;
    # the library has portable forms (pbr_hammersley_float, pbr_sanitize per component).
    "100es": ("#version 100\nprecision mediump float;\n", []),
    "450": ("#version 450\n", []),
}
HLSL_TARGETS = {
    "sm5.0": (["-D__SHADER_TARGET_MAJOR=5", "-D__SHADER_TARGET_MINOR=0"], True),
    "sm6.0": (["-D__SHADER_TARGET_MAJOR=6", "-D__SHADER_TARGET_MINOR=0", "-D__HLSL_VERSION=2018"], False),
}


def _glslang_glsl(text: str, args) -> str | None:
    """None if glslang accepts ``text`` (a fragment shader), else its messages."""
    proc = subprocess.run([hlsl.tool(hlsl.GLSLANG), "--stdin", "-S", "frag", *args], input=text,
                          capture_output=True, text=True, timeout=60)
    return None if proc.returncode == 0 else proc.stdout + proc.stderr


def _glsl_failures(target: str) -> list[str]:
    """Every include alone, in ONE glslang run (glslang's start-up, ~0.25 s per GLSL
    process, dominates otherwise): without -V glslang compiles each file as its own
    shader, links nothing, and prints each file's name before its messages."""
    head, args = GLSL_TARGETS[target]
    with tempfile.TemporaryDirectory(prefix="pbrlab-matrix-") as tmp:
        names = {}
        for i, include in enumerate(GLSL_FILES):
            name = f"f{i:03d}.frag"
            names[name] = include
            source = shaders.expand(f'{head}#include "{include}"\nvoid main() {{}}\n', "<matrix>")
            (Path(tmp) / name).write_text(source.text, encoding="utf-8")
        proc = subprocess.run([hlsl.tool(hlsl.GLSLANG), "-S", "frag", *args, *sorted(names)],
                              cwd=tmp, capture_output=True, text=True, timeout=120)
    failures, current = {}, None
    for line in (proc.stdout + proc.stderr).splitlines():
        if line.strip() in names:
            current = names[line.strip()]
        elif current and line.startswith("ERROR"):
            failures.setdefault(current, []).append(line)
    if proc.returncode != 0 and not failures:
        return [f"glslang failed without a per-file message:\n{proc.stdout}{proc.stderr}"]
    return [f"{inc} as {target}:\n" + "\n".join(msgs) for inc, msgs in failures.items()]


def _hlsl_failure(include: str, target: str) -> str | None:
    defines, optimize = HLSL_TARGETS[target]
    text = f'#include "{include}"\nfloat4 main(float4 p : SV_Position) : SV_Target0 {{ return p; }}\n'
    try:
        spirv = hlsl.compile_spirv(text, f"<{target}>", optimize=optimize, extra_args=[*defines, "--spirv-val"])
    except ShaderCompileError as exc:
        return f"{include} as {target}: {exc}"
    return None if spirv[:4] == b"\x03\x02\x23\x07" else f"{include} as {target}: not SPIR-V"


def _run_all(check, files, target):
    # glslang runs are independent processes: two at a time keeps a 2-core run busy.
    with ThreadPoolExecutor(max_workers=2) as pool:
        failures = [f for f in pool.map(lambda inc: check(inc, target), files) if f]
    assert not failures, "\n\n".join(failures)


@pytest.mark.parametrize("target", GLSL_TARGETS)
def test_every_glsl_include_compiles_alone(target):
    assert len(GLSL_FILES) >= 40
    failures = _glsl_failures(target)
    assert not failures, "\n\n".join(failures)


def test_all_glsl_includes_generate_vulkan_spirv():
    """The 450 column as Vulkan GLSL proper: every file in one shader, -V --target-env
    vulkan1.0 (SPIR-V is generated and validated by glslang's own checks)."""
    includes = "".join(f'#include "{inc}"\n' for inc in GLSL_FILES)
    source = shaders.expand(f"#version 450\n{includes}void main() {{}}\n", "<vulkan>")
    log = _glslang_glsl(source.text, ["-V", "--target-env", "vulkan1.0", "-o", os.devnull])
    assert log is None, source.map_messages(log)


@pytest.mark.parametrize("target", HLSL_TARGETS)
def test_every_hlsl_port_compiles_alone(target):
    assert len(HLSL_FILES) == len(GLSL_FILES) + 1  # + the shim
    _run_all(_hlsl_failure, HLSL_FILES, target)


def test_matrix_catches_a_broken_file(tmp_path, monkeypatch):
    """The harness itself: an undeclared identifier in an uncalled function fails both columns."""
    (tmp_path / "pbr").mkdir()
    (tmp_path / "pbr" / "bad.glsl").write_text("#ifndef B\n#define B\nfloat f(float x) { return x + nope; }\n#endif\n")
    (tmp_path / "pbr" / "bad.hlsl").write_text("#ifndef B\n#define B\nfloat f(float x) { return x + nope; }\n#endif\n")
    source = shaders.expand('#version 330 core\n#include "pbr/bad.glsl"\nvoid main() {}\n', "<m>", include_dirs=[tmp_path])
    assert "nope" in (_glslang_glsl(source.text, []) or "")
    with pytest.raises(ShaderCompileError, match=r"pbr/bad.hlsl:3: error: 'nope'"):
        hlsl.compile_spirv('#include "pbr/bad.hlsl"\nfloat4 main(float4 p : SV_Position) : SV_Target0 { return p; }\n',
                           "<m>", include_dirs=[tmp_path])


HAVE_FIXED = """
fixed3 tint(fixed3 c, half k) { half3 h = c * k; fixed a = (fixed)0.5; return h * a; }
float4 main(float4 p : SV_Position) : SV_Target0 { return float4(tint((fixed3)p.xyz, (half)2.0), 1.0); }
"""


@pytest.mark.parametrize("prelude", ["", "#define fixed half\n#define fixed2 half2\n#define fixed3 half3\n#define fixed4 half4\n"],
                         ids=["shim-defines-fixed", "engine-defines-fixed"])
@pytest.mark.parametrize("sixteen_bit", [False, True], ids=["32bit-half", "16bit-half"])
def test_unity_types_work_and_step_aside(prelude, sixteen_bit):
    """fixed*/half* work after the library include, whether the engine (Unity's
    HLSLSupport.cginc) already defined fixed or not, with and without 16-bit types."""
    text = prelude + '#include "pbr/unity/surface_standard.hlsl"\n' + HAVE_FIXED
    args = ["--hlsl-enable-16bit-types"] if sixteen_bit else []
    hlsl.compile_spirv(text, "<unity-types>", extra_args=args)
