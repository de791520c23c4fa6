"""The HLSL toolchain: HLSL -> SPIR-V (glslang's HLSL front end) -> GLSL 330 (spirv-cross).

    glsl_text = hlsl_to_glsl(hlsl_text, name="<evaluate>")

``pbrlab.evaluate(..., language="hlsl")`` runs HLSL through this path and then through the
same GL evaluator as GLSL (one readback path, STYLE 10). The commands are

    glslangValidator -D -V -e main -S frag [-Od] -I<dirs> --auto-sampled-textures FILE -o OUT.spv
    spirv-cross --version 330 --no-es OUT.spv

``--auto-sampled-textures`` turns the template's ``Texture2D`` inputs into combined image
samplers, so spirv-cross writes ``uniform sampler2D pbrlab_in_<name>`` and ``texelFetch``:
the names and the bit-exact fetch of the GLSL template. ``#include "pbr/..."`` is resolved
by glslang against the caller's directories, then ``hlsl_ports/``; compile errors are
reported at the original file and line (``pbr/brdf/d_ggx.hlsl:41: error: ...``).

Optimisation: by default glslang legalises HLSL with SPIRV-Tools passes that also fold and
reassociate float arithmetic (e.g. ``y / 2.4`` becomes ``y * 0.41666666``), which a D3D
compiler need not do in the same way. The evaluator passes ``-Od`` (``optimize=False``) so
the SPIR-V keeps the port's arithmetic as written and the comparison with the GLSL twin
tests the port, not SPIRV-Tools; the compilation matrix (tests/gpu/hlsl) compiles every port
with the optimising default as well.
"""

from __future__ import annotations

import re
import shutil
import subprocess
import tempfile
import urllib.parse
from pathlib import Path

from ..foundation.errors import PbrlabError, ShaderCompileError
from ..foundation.file_identity import FileCache, include_closure
from ..foundation.locations import locate
from .compile_messages import compile_failure
from .shaders import GLSL_ROOT, strip_bom

HLSL_ROOT = locate("hlsl_ports")  # $PBRLAB_HLSL_ROOT, the wheel's package data, or the checkout
UMBRELLA_INCLUDE = "pbr/pbr.hlsl"
GLSLANG = "glslangValidator"
SPIRV_CROSS = "spirv-cross"
_INSTALL_HINT = ("install the Debian/Ubuntu packages glslang-tools and spirv-cross "
                 "(sudo apt-get install glslang-tools spirv-cross; in a pbrlab checkout, "
                 "scripts/setup.sh does)")
_TIMEOUT_S = 60
# glslang: "ERROR: path:line: message" / "WARNING: path:line: message"
_GLSLANG_MESSAGE = re.compile(r"^(ERROR|WARNING): (.+?):(\d+): (.*)$")
_ENTRY_NAME = "pbrlab_entry.hlsl"
_BOM = b"\xef\xbb\xbf"  # UTF-8 byte-order mark (shaders.strip_bom)


def tool(name: str) -> str:
    """Absolute path of ``name`` on PATH, or a PbrlabError saying how to get it."""
    path = shutil.which(name)
    if path is None:
        raise PbrlabError(f"{name} not found on PATH: the HLSL path needs it; {_INSTALL_HINT}")
    return path


# A file name a #line "..." string cannot carry (glslang reads no escapes in it: a double
# quote ends it, a backslash is refused) is written percent-encoded behind this marker, and
# map_messages decodes it: messages name the file as it is.
_ENCODED_NAME = "pbrlab-encoded-name="
_NOT_IN_LINE_STRING = re.compile(r'["\\\x00-\x1f\x7f]')
_ENCODED = re.compile(re.escape(_ENCODED_NAME) + r"([\w.~/%-]+)")  # quote(safe="/") writes these


def line_directive(line: int, display: str) -> str:
    """``#line LINE "display"`` for glslang's HLSL front end, any file name made safe."""
    if _NOT_IN_LINE_STRING.search(display):
        display = _ENCODED_NAME + urllib.parse.quote(display, safe="/")
    return f'#line {line} "{display}"'


def _display(path: str, name: str, include_dirs) -> str:
    if path.startswith(_ENCODED_NAME):
        path = urllib.parse.unquote(path[len(_ENCODED_NAME):])
    if Path(path).name == _ENTRY_NAME:
        return name
    p = Path(path)
    for root in (HLSL_ROOT, *[Path(d) for d in include_dirs]):
        try:
            return p.resolve().relative_to(Path(root).resolve()).as_posix()
        except ValueError:
            continue
    return path


def map_messages(log: str, name: str, include_dirs=()) -> str:
    """glslang's messages as ``file:line: error: message`` (the library file, not a temp)."""
    out = []
    for line in log.splitlines():
        line = line.rstrip()
        m = _GLSLANG_MESSAGE.match(line)
        if m:
            kind = "error" if m.group(1) == "ERROR" else "warning"
            out.append(f"{_display(m.group(2), name, include_dirs)}:{m.group(3)}: {kind}: {m.group(4)}")
        elif line and not line.endswith(_ENTRY_NAME) and "SPIR-V is not generated" not in line \
                and not re.match(r"^ERROR: \d+ compilation errors", line):
            out.append(_ENCODED.sub(lambda e: urllib.parse.unquote(e.group(1)),
                                    line.replace(_ENTRY_NAME, name)))
    return "\n".join(out)


def _bom_free_search(text: str, include_dirs, tmp: Path) -> list[Path]:
    """The -I directories for glslang, which reads includes itself and fails on a UTF-8
    byte-order mark ("unexpected HASH_TOKEN"). When a file the text includes (recursively,
    from ``include_dirs``) starts with one, every included file is copied, without BOMs, into
    a mirror of the file system under ``tmp`` (at its absolute path), and each directory is
    preceded by its mirror: every include resolves to the same file as before, minus the mark,
    including one that climbs out of its directory (``../Include/x.hlsl``) and one resolved
    from the including file's folder (a copy's folder holds its siblings' copies too)."""
    dirs = [Path(d).resolve() for d in include_dirs]
    closure = include_closure(text, dirs)
    if not any(path.read_bytes().startswith(_BOM) for path in closure):
        return dirs
    mirror = tmp / "bom-free"

    def mirrored(path: Path) -> Path:
        return mirror.joinpath(path.drive.strip(":\\/") or "root", path.relative_to(path.anchor))

    for path in closure:
        copy = mirrored(path)
        copy.parent.mkdir(parents=True, exist_ok=True)
        data = path.read_bytes()
        copy.write_bytes(data[len(_BOM):] if data.startswith(_BOM) else data)
    search = []
    for directory in dirs:
        mirrored(directory).mkdir(parents=True, exist_ok=True)  # a "../x" from it must resolve
        search += [mirrored(directory), directory]
    return search


def compile_spirv(text: str, name: str = "<hlsl>", include_dirs=(), *, optimize: bool = False,
                  extra_args=(), stage: str = "frag", entry: str = "main") -> bytes:
    """HLSL source -> SPIR-V bytes; ShaderCompileError (mapped messages) if it fails."""
    glslang = tool(GLSLANG)
    with tempfile.TemporaryDirectory(prefix="pbrlab-hlsl-") as tmp:
        search = _bom_free_search(text, include_dirs, Path(tmp))
        include_args = [f"-I{d}" for d in search] + [f"-I{HLSL_ROOT.resolve()}"]
        src = Path(tmp) / _ENTRY_NAME
        out = Path(tmp) / "out.spv"
        src.write_text(strip_bom(text), encoding="utf-8")
        cmd = [glslang, "-D", "-V", "-e", entry, "-S", stage, "--auto-sampled-textures",
               *([] if optimize else ["-Od"]), *extra_args, *include_args, src.name, "-o", out.name]
        proc = subprocess.run(cmd, cwd=tmp, capture_output=True, text=True, timeout=_TIMEOUT_S)
        if proc.returncode != 0 or not out.is_file():
            log = (proc.stdout + proc.stderr).replace(str(Path(tmp) / "bom-free" / "root"), "")
            messages = map_messages(log, name, search)  # a BOM-free copy named as its original
            raise ShaderCompileError(compile_failure("HLSL failed to compile (glslang)", messages))
        return out.read_bytes()


def cross_to_glsl(spirv: bytes, version: int = 330, *, plain_uniforms: bool = False) -> str:
    """SPIR-V -> desktop GLSL ``#version <version>`` with spirv-cross; ``plain_uniforms``
    writes the cbuffers as uniform structs (set with glUniform) instead of uniform blocks."""
    cross = tool(SPIRV_CROSS)
    with tempfile.TemporaryDirectory(prefix="pbrlab-spirv-") as tmp:
        path = Path(tmp) / "in.spv"
        path.write_bytes(spirv)
        flags = ["--glsl-emit-ubo-as-plain-uniforms"] if plain_uniforms else []
        proc = subprocess.run([cross, "--version", str(version), "--no-es", *flags, str(path)],
                              capture_output=True, text=True, timeout=_TIMEOUT_S)
    if proc.returncode != 0:
        raise ShaderCompileError(f"spirv-cross failed:\n{(proc.stdout + proc.stderr).strip()}")
    return proc.stdout


# Cross-compiled shaders kept per process; each entry is rebuilt when a file the HLSL
# includes changed on disk (file_identity.FileCache). Strings of a few tens of kB.
CROSS_COMPILED_CACHED = 256
_CROSS_COMPILED = FileCache(CROSS_COMPILED_CACHED)


def hlsl_to_glsl(text: str, name: str = "<hlsl>", include_dirs=(), *, optimize: bool = False,
                 plain_uniforms: bool = False, version: int = 330) -> str:
    """A pixel shader (entry ``main``) in HLSL -> the GLSL ``version`` (330 unless the
    shader needs more) that spirv-cross writes."""
    include_dirs = tuple(str(d) for d in include_dirs)

    def build():
        glsl = cross_to_glsl(compile_spirv(text, name, include_dirs, optimize=optimize), version,
                             plain_uniforms=plain_uniforms)
        return glsl, include_closure(text, [*include_dirs, HLSL_ROOT])

    return _CROSS_COMPILED.get((text, name, include_dirs, optimize, plain_uniforms, version), build)
