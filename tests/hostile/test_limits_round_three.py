"""Issue 39 (round three), limits on shader text and cancellation that works.

Each hostile text runs in a child process under an address-space limit and a time limit,
so a compiler that hangs, crashes or takes the machine's memory (what main at d2cf9f0 did
with several of them) fails its case instead of the run. Allowed outcome: a
ShaderLimitError naming the file and the limit ("refused cleanly"). The cancellation cases
send SIGTERM or SIGINT to `pbrlab render` while llvmpipe compiles a slow surface at the
first draw and require the process gone within 1 s, with no traceback and no output.
"""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import textwrap
import time
from pathlib import Path

import numpy as np
import pytest

try:
    from pbrlab.gpu import source_limits
except ImportError:  # main before issue 39 (the before run): the limits as this change sets them
    import types
    source_limits = types.SimpleNamespace(MAX_INCLUDE_DEPTH=64, MAX_SOURCE_BYTES=16 << 20)

HARNESS = Path(__file__).resolve().parents[2] / "harness"
# The child's address space: pbrlab with an llvmpipe context maps about 1 GiB (measured
# peak RSS 0.2 GiB; LLVM reserves more address space than it touches); a bomb that gets
# past the checks crosses 4 GiB within seconds (issue 39: 5.5 GB, 5.8 GB).
CHILD_ADDRESS_SPACE = 4 << 30
# A refused text is refused before any compile: the child's time is pbrlab's import and an
# llvmpipe context (3 to 8 s measured on the loaded 2-core machine). 90 s is not a measure of
# the check; it only separates "refused" from "hung" (main's include cycle ran until killed).
CHILD_LIMIT_S = 90

VERTEX = "#version 330\nin vec2 p;\nvoid main() { gl_Position = vec4(p, 0.0, 1.0); }\n"


def _child(script: str, cwd: Path) -> tuple[int, str]:
    env = dict(os.environ, PYTHONPATH=str(HARNESS))

    def limit():
        import resource
        resource.setrlimit(resource.RLIMIT_AS, (CHILD_ADDRESS_SPACE, CHILD_ADDRESS_SPACE))

    try:
        proc = subprocess.run([sys.executable, "-c", textwrap.dedent(script)], cwd=cwd, env=env,
                              capture_output=True, text=True, timeout=CHILD_LIMIT_S, preexec_fn=limit)
    except subprocess.TimeoutExpired:
        pytest.fail(f"the child hung for {CHILD_LIMIT_S} s")
    return proc.returncode, proc.stdout + proc.stderr


def _glsl(tmp_path: Path, fragment: str, files: dict | None = None) -> tuple[int, str]:
    """Expand and build ``fragment`` (files beside it) as pbrlab builds any program."""
    for name, text in (files or {}).items():
        (tmp_path / name).write_text(text)
    (tmp_path / "entry.frag").write_text(fragment)
    return _child(f"""
        from pbrlab.foundation.errors import PbrlabError
        from pbrlab.gpu import gl, shaders
        try:
            fragment = shaders.expand_file("entry.frag")
            shaders.build_program(gl.create_context(), shaders.expand({VERTEX!r}, "v.vert"), fragment)
            print("BUILT")
        except PbrlabError as exc:
            print("REFUSED", exc)
        """, tmp_path)


def _hlsl(tmp_path: Path, entry: str, files: dict | None = None) -> tuple[int, str]:
    """Compile ``entry`` (files beside it) through glslang as the HLSL path does."""
    for name, text in (files or {}).items():
        (tmp_path / name).write_text(text)
    (tmp_path / "entry.txt").write_text(entry)  # read by the child: too long for its command line
    return _child(f"""
        from pathlib import Path
        from pbrlab.foundation.errors import PbrlabError
        from pbrlab.gpu import hlsl
        try:
            hlsl.compile_spirv(Path("entry.txt").read_text(), "entry.hlsl", [{str(tmp_path)!r}])
            print("BUILT")
        except PbrlabError as exc:
            print("REFUSED", exc)
        """, tmp_path)


def _refused(result, *pieces):
    status, output = result
    assert status == 0 and "REFUSED" in output, f"status {status}:\n{output[-3000:]}"
    assert "Traceback" not in output, output
    for piece in pieces:
        assert piece in output, output


HLSL_MAIN = "float4 main() : SV_Target { return float4(1, 1, 1, 1); }\n"
FRAG_MAIN = "out vec4 c;\nvoid main() { c = vec4(1.0); }\n"


def test_an_hlsl_include_cycle_is_refused_before_glslang(tmp_path, census):
    """Main: glslang followed a.hlsl -> b.hlsl -> a.hlsl until memory ran out."""
    files = {"a.hlsl": '#include "b.hlsl"\nfloat a() { return 1; }\n',
             "b.hlsl": '#include "a.hlsl"\nfloat b() { return 2; }\n'}
    _refused(_hlsl(tmp_path, '#include "a.hlsl"\n' + HLSL_MAIN, files), "include cycle", "a.hlsl", "b.hlsl")
    census["limits round three", "refused cleanly"] += 1


def test_an_hlsl_include_cycle_through_guarded_files_still_compiles(tmp_path, census):
    """The control: the same cycle behind #ifndef guards ends, and builds (glslang does not
    implement #pragma once: that cycle is refused like an unguarded one)."""
    files = {"a.hlsl": '#ifndef A_H\n#define A_H\n#include "b.hlsl"\nfloat a() { return 1; }\n#endif\n',
             "b.hlsl": '#ifndef B_H\n#define B_H\n#include "a.hlsl"\nfloat b() { return 2; }\n#endif\n'}
    status, output = _hlsl(tmp_path, '#include "a.hlsl"\n' + HLSL_MAIN, files)
    assert status == 0 and "BUILT" in output, output
    census["limits round three", "handled"] += 1


@pytest.mark.parametrize("language", ["glsl", "hlsl"])
def test_an_include_chain_past_the_depth_limit_is_refused(tmp_path, language, census):
    """400 files, each including the next (no cycle). Main, GLSL: RecursionError (a traceback)."""
    depth = 400
    suffix = "glsl" if language == "glsl" else "hlsl"
    files = {f"f{i}.{suffix}": (f'#include "f{i + 1}.{suffix}"\n' if i + 1 < depth else "") + f"float f{i}() {{ return 1.0; }}\n"
             for i in range(depth)}
    if language == "glsl":
        result = _glsl(tmp_path, '#version 330\n#include "f0.glsl"\n' + FRAG_MAIN, files)
    else:
        result = _hlsl(tmp_path, '#include "f0.hlsl"\n' + HLSL_MAIN, files)
    _refused(result, "includes nested", f"limit of {source_limits.MAX_INCLUDE_DEPTH}")
    census["limits round three", "refused cleanly"] += 1


def _doubling_macros(levels: int) -> str:
    return "#define A0 1.0\n" + "".join(f"#define A{k} (A{k - 1} + A{k - 1})\n" for k in range(1, levels + 1))


@pytest.mark.parametrize("language", ["glsl", "hlsl"])
def test_an_object_macro_bomb_is_refused_before_the_compiler(tmp_path, language, census):
    """2^40 leaves. Main: Mesa crashed (SIGSEGV at 5.5 GB); under the child's 4 GiB it dies."""
    if language == "glsl":
        result = _glsl(tmp_path, "#version 330\n" + _doubling_macros(40) + "out vec4 c;\nvoid main() { c = vec4(A40); }\n")
    else:
        result = _hlsl(tmp_path, _doubling_macros(40) + "float4 main() : SV_Target { return float4(A40, 0, 0, 1); }\n")
    _refused(result, "macros expand", "MAX_EXPANDED_TOKENS")
    census["limits round three", "refused cleanly"] += 1


def test_a_function_macro_bomb_is_refused(tmp_path, census):
    """F(x) doubles its argument; 40 nested calls are 2^40 tokens."""
    text = "#version 330\n#define F(x) (x + x)\nout vec4 c;\nvoid main() { c = vec4(" + "F(" * 40 + "1.0" + ")" * 40 + "); }\n"
    _refused(_glsl(tmp_path, text), "entry.frag", "MAX_EXPANDED_TOKENS")
    census["limits round three", "refused cleanly"] += 1


def test_macros_under_the_budget_still_compile(tmp_path, census):
    """The control: 2^12 leaves (about 16,000 tokens) of the same doubling builds."""
    status, output = _glsl(tmp_path, "#version 330\n" + _doubling_macros(12) + "out vec4 c;\nvoid main() { c = vec4(A12); }\n")
    assert status == 0 and "BUILT" in output, output
    census["limits round three", "handled"] += 1


@pytest.mark.parametrize("language", ["glsl", "hlsl"])
def test_a_million_element_local_array_is_refused(tmp_path, language, census):
    if language == "glsl":
        result = _glsl(tmp_path, "#version 330\nuniform int k;\nout vec4 c;\nvoid main() {\n  float a[1000000];\n"
                                 "  a[k] = 1.0;\n  c = vec4(a[k]);\n}\n")
    else:
        result = _hlsl(tmp_path, "int k;\nfloat4 main() : SV_Target {\n  float a[1000000];\n  a[k] = 1;\n"
                                 "  return float4(a[k], 0, 0, 1);\n}\n")
    _refused(result, ":3: an array of 1000000 elements" if language == "hlsl" else "entry.frag:5: an array",
             "MAX_ARRAY_ELEMENTS")
    census["limits round three", "refused cleanly"] += 1


@pytest.mark.parametrize("language", ["glsl", "hlsl"])
def test_an_included_file_over_the_size_limit_is_refused_unread(tmp_path, language, census):
    """A 17 MiB include of comments (the issue's was 100 MB; any size over the limit is
    refused by its size alone)."""
    suffix = "glsl" if language == "glsl" else "hlsl"
    with open(tmp_path / f"big.{suffix}", "w") as out:
        line = "// " + "x" * 60 + "\n"
        out.write(line * ((source_limits.MAX_SOURCE_BYTES + (1 << 20)) // len(line)))
    if language == "glsl":
        result = _glsl(tmp_path, '#version 330\n#include "big.glsl"\n' + FRAG_MAIN)
    else:
        result = _hlsl(tmp_path, '#include "big.hlsl"\n' + HLSL_MAIN)
    _refused(result, f"big.{suffix}", "MAX_SOURCE_BYTES")
    census["limits round three", "refused cleanly"] += 1


@pytest.mark.parametrize("language", ["glsl", "hlsl"])
def test_a_hundred_thousand_nested_parentheses_are_refused(tmp_path, language, census):
    n = 100_000
    if language == "glsl":
        result = _glsl(tmp_path, "#version 330\nout vec4 c;\nvoid main() {\n  c = vec4(" + "(" * n + "1.0" + ")" * n + ");\n}\n")
    else:
        result = _hlsl(tmp_path, "float4 main() : SV_Target {\n  return float4(" + "(" * n + "1" + ")" * n + ", 0, 0, 1);\n}\n")
    _refused(result, "brackets nested", "MAX_NESTING")
    census["limits round three", "refused cleanly"] += 1


def test_the_library_programs_are_within_every_limit(census):
    """The control on real content: every harness template with the whole library, GLSL
    and HLSL, passes the checks (a limit that refused them would break every render)."""
    from pbrlab.gpu import hlsl, programs, shaders

    for name in ("sphere.frag", "mesh.frag", "resolve.frag", "prefilter.frag"):
        source = programs.template_source(name, {})
        source_limits.check_text(source.text, shaders.source_locator(source))
    for name in ("sphere.hlsl", "mesh.hlsl"):
        text, include_dirs = programs.hlsl_template_text(name, {})
        hlsl.check_limits(text, name, include_dirs)
    census["limits round three", "handled"] += 1


def _slow_surface_scene(tmp_path: Path) -> Path:
    """A surface of 1,000 dependent sin/cos statements: llvmpipe compiles it at the first
    draw in about 30 s (measured: 700 statements, 16.8 s for the whole render)."""
    salt = time.time_ns() % 1000 * 1e-9  # a text no earlier run compiled (Mesa's shader cache, if on)
    body = "".join(f"    x = sin(x * {1 + i * 1e-4 + salt:.9f} + y); y = cos(y + x * {i % 7 + 1}.0);\n" for i in range(1000))
    (tmp_path / "slow.glsl").write_text("void surf(Input IN, inout SurfaceOutputStandard o) {\n"
                                        "    float x = IN.uv.x, y = IN.uv.y;\n" + body +
                                        "    o.Albedo = vec3(fract(x), fract(y), 0.5);\n}\n")
    (tmp_path / "scene.json").write_text(
        '{"camera": {"position": [0, 0, 6], "target": [0, 0, 0], "fov_y_deg": 30, "size": [8, 6]},'
        ' "lights": [{"type": "directional", "direction": [0.2, -0.4, -1], "intensity": 2.0}],'
        ' "materials": {"m": {"surface": "slow.glsl"}},'
        ' "objects": [{"sphere": {"center": [0, 0, 0], "radius": 1.0}, "material": "m"}]}')
    return tmp_path / "scene.json"


def _cpu_seconds(pid: int) -> float:
    fields = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")  # utime + stime


# The render's CPU time when the signal is sent: past start-up (imports, context, scene:
# about 2 s of CPU measured) and well inside the 30 s compile.
SIGNAL_AT_CPU_S = 6.0
# The requirement: stopped within 1 s of the signal.
STOP_WITHIN_S = 1.0


@pytest.mark.parametrize("signum,status", [(signal.SIGTERM, 143), (signal.SIGINT, 130)], ids=["SIGTERM", "SIGINT"])
def test_a_signal_during_a_long_compile_stops_the_render_within_a_second(tmp_path, signum, status, census):
    """Main: SIGTERM waited for the compile to end (about 30 s here)."""
    scene = _slow_surface_scene(tmp_path)
    proc = subprocess.Popen([sys.executable, "-m", "pbrlab.commands.cli", "render", str(scene), "-o", "out.png"],
                            cwd=tmp_path, env=dict(os.environ, PYTHONPATH=str(HARNESS),
                                                   MESA_SHADER_CACHE_DISABLE="true"),  # compile it every time
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        deadline = time.monotonic() + 120
        while _cpu_seconds(proc.pid) < SIGNAL_AT_CPU_S:
            assert proc.poll() is None, proc.communicate()
            assert time.monotonic() < deadline, "the render never got going"
            time.sleep(0.05)
        sent = time.monotonic()
        proc.send_signal(signum)
        try:
            out, err = proc.communicate(timeout=60)
        except subprocess.TimeoutExpired:
            pytest.fail("the render ignored the signal for 60 s")
        waited = time.monotonic() - sent
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.communicate()
    # Killed by the signal (the kernel's default action: status 128 + N to a shell), or,
    # had it arrived between draws, exited with 128 + N by pbrlab's own handler.
    assert proc.returncode in (-signum, status), (proc.returncode, err)
    assert waited < STOP_WITHIN_S, f"stopped {waited:.2f} s after the signal"
    assert "Traceback" not in err, err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["scene.json", "slow.glsl"]  # no output, no temporary
    census["limits round three", "handled"] += 1


def test_a_million_zero_scale_instances_are_refused_by_count(tmp_path, census):
    """EXT_mesh_gpu_instancing with 10^6 instances of scale 0. Main: the import placed every
    one (130 us each, measured) before finding "no triangle to draw", minutes later."""
    n = 1_000_000
    scales = np.zeros((n, 3), np.float32)
    _write_instanced_quads(tmp_path, n, [{}], scales)
    _refused(_import_in_child(tmp_path), "m.gltf", "1000000 instances, over the limit of 65536")
    census["limits round three", "refused cleanly"] += 1


# The limit the test sets: the slow surface's first draw runs for about 30 s, so a 3 s
# limit is crossed inside the compile whatever the machine's load (start-up is excluded:
# the clock starts at the draw). The wait allowed is the limit, the watchdog's 2 s before
# SIGKILL and start-up (3 to 8 s measured on the loaded 2-core machine): 60 s separates
# "stopped by the limit" from "ran the whole compile" (30 s and more) only loosely, so the
# test also requires the message, which only the watchdog writes.
TEST_LIMIT_S = 3


def test_a_compile_past_the_driver_time_limit_ends_the_render_with_a_message(tmp_path, census):
    """Main: nothing limited the time of a compile inside Mesa (one C call holding the
    interpreter lock: neither a thread nor a handler could stop it)."""
    scene = _slow_surface_scene(tmp_path)
    env = dict(os.environ, PYTHONPATH=str(HARNESS), MESA_SHADER_CACHE_DISABLE="true",
               PBRLAB_DRIVER_TIME_LIMIT_S=str(TEST_LIMIT_S))
    started = time.monotonic()
    proc = subprocess.run([sys.executable, "-m", "pbrlab.commands.cli", "render", str(scene), "-o", "out.png"],
                          cwd=tmp_path, env=env, capture_output=True, text=True, timeout=120)
    took = time.monotonic() - started
    assert proc.returncode in (-signal.SIGTERM, -signal.SIGKILL), (proc.returncode, proc.stderr)
    assert f"over the driver time limit of {TEST_LIMIT_S} s" in proc.stderr, proc.stderr
    assert "scene.json: objects[0]" in proc.stderr and "PBRLAB_DRIVER_TIME_LIMIT_S" in proc.stderr
    assert "Traceback" not in proc.stderr, proc.stderr
    assert took < 25.0, f"the render took {took:.1f} s: the compile alone is about 30 s, so the limit did not act"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["scene.json", "slow.glsl"]  # no output, no temporary
    census["limits round three", "refused cleanly"] += 1


def test_a_program_inside_the_driver_time_limit_renders(tmp_path, census):
    """Control: the same limit leaves an ordinary surface alone (its compile takes well
    under a second), and the watchdog ends with the render."""
    (tmp_path / "plain.glsl").write_text("void surf(Input IN, inout SurfaceOutputStandard o) {\n"
                                         "    o.Albedo = vec3(0.8, 0.2, 0.1);\n}\n")
    scene = _slow_surface_scene(tmp_path)
    scene.write_text(scene.read_text().replace("slow.glsl", "plain.glsl"))
    env = dict(os.environ, PYTHONPATH=str(HARNESS), PBRLAB_DRIVER_TIME_LIMIT_S=str(TEST_LIMIT_S))
    proc = subprocess.run([sys.executable, "-m", "pbrlab.commands.cli", "render", str(scene), "-o", "out.png"],
                          cwd=tmp_path, env=env, capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr
    assert (tmp_path / "out.png").stat().st_size > 0
    census["limits round three", "handled"] += 1


def test_instances_over_many_nodes_are_refused_by_their_total(tmp_path, census):
    """Three nodes of 30,000 instances each: within the limit a node, over the file's limit
    of placed objects (instancing.MAX_PLACED_OBJECTS). Main: accepted, 90,000 objects (about
    80 s of rendering; a thousand such nodes, 65 million)."""
    _write_instanced_quads(tmp_path, 30_000, [{"translation": [0, k, 0]} for k in range(3)])
    _refused(_import_in_child(tmp_path), "m.gltf", "nodes[2]: the file places over 65536 objects")
    census["limits round three", "refused cleanly"] += 1


def _write_instanced_quads(folder: Path, n: int, nodes: list, scales=None) -> None:
    """m.gltf (+ m.bin) in ``folder``: the quad of gltf_helpers placed by one node per entry of
    ``nodes`` (extra node fields), each with ``n`` EXT_mesh_gpu_instancing instances 1 mm apart
    (and ``scales``, an (n, 3) array, when given)."""
    import base64
    import json

    sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "importers" / "gltf"))
    from gltf_helpers import quad_document

    doc = quad_document()
    blob = base64.b64decode(doc["buffers"][0]["uri"].split(",", 1)[1])
    translations = np.zeros((n, 3), np.float32)
    translations[:, 0] = np.arange(n) * 1e-3
    attributes = {}
    for name, values in (("TRANSLATION", translations), ("SCALE", scales)):
        if values is None:
            continue
        doc["bufferViews"].append({"buffer": 0, "byteOffset": len(blob), "byteLength": values.nbytes})
        doc["accessors"].append({"bufferView": len(doc["bufferViews"]) - 1, "componentType": 5126,
                                 "count": n, "type": "VEC3"})
        attributes[name] = len(doc["accessors"]) - 1
        blob += values.tobytes()
    (folder / "m.bin").write_bytes(blob)
    doc["buffers"] = [{"byteLength": len(blob), "uri": "m.bin"}]
    doc["nodes"] = [{**extra, "mesh": 0, "extensions": {"EXT_mesh_gpu_instancing": {"attributes": attributes}}}
                    for extra in nodes]
    doc["scenes"] = [{"nodes": list(range(len(nodes)))}]
    doc["extensionsUsed"] = ["EXT_mesh_gpu_instancing"]
    (folder / "m.gltf").write_text(json.dumps(doc))


def _import_in_child(folder: Path) -> tuple[int, str]:
    """Import m.gltf in a child (its time and address space limited): BUILT or REFUSED <message>."""
    return _child("""
        from pbrlab.foundation.errors import PbrlabError
        from pbrlab.importers.gltf import load_gltf
        try:
            load_gltf("m.gltf", size=(8, 6), emit_warnings=False)
            print("BUILT")
        except PbrlabError as exc:
            print("REFUSED", exc)
        """, folder)
