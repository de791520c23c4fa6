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
import signal
import shutil
import subprocess
import tempfile
import urllib.parse
from pathlib import Path

from ..foundation.errors import PbrlabError, ShaderCompileError
from ..foundation.file_identity import FileCache, followed_key, include_closure
from ..foundation.locations import locate
from .compile_messages import compile_failure
from . import source_limits
from .shaders import GLSL_ROOT, _is_guarded, strip_bom

HLSL_ROOT = locate("hlsl_ports")  # $PBRLAB_HLSL_ROOT, the wheel's package data, or the checkout
UMBRELLA_INCLUDE = "pbr/pbr.hlsl"
GLSLANG = "glslangValidator"
SPIRV_CROSS = "spirv-cross"
_INSTALL_HINT = ("install the Debian/Ubuntu packages glslang-tools and spirv-cross "
                 "(sudo apt-get install glslang-tools spirv-cross; in a pbrlab checkout, "
                 "scripts/setup.sh does)")
# Each tool run's limits: 60 s of wall time (the slowest compile measured in this project is
# llvmpipe's 38 s for 4,000 statements, issue 26; glslang compiles the library's largest
# program in under 1 s) and an address space of 4 GiB (the process's whole mapping, glslang's
# code included; the runaway include cycle of issue 39 reached 5.8 GB). Over either, the
# compile is a ShaderLimitError naming the limit.
_TIMEOUT_S = 60
TOOL_ADDRESS_SPACE_BYTES = 4 << 30
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


def _bom_free_search(text: str, include_dirs, tmp: Path, replaced=None) -> list[Path]:
    """The -I directories for glslang, which reads includes itself and fails on a UTF-8
    byte-order mark ("unexpected HASH_TOKEN"). When a file the text includes (recursively,
    from ``include_dirs``) starts with one, every included file is copied, without BOMs, into
    a mirror of the file system under ``tmp`` (at its absolute path), and each directory is
    preceded by its mirror: every include resolves to the same file as before, minus the mark,
    including one that climbs out of its directory (``../Include/x.hlsl``) and one resolved
    from the including file's folder (a copy's folder holds its siblings' copies too).
    ``replaced``: {resolved path: text} compiled in those files' place (the same mirror)."""
    dirs = [Path(d).resolve() for d in include_dirs]
    closure = include_closure(text, dirs)
    replaced = {Path(p).resolve(): t for p, t in (replaced or {}).items()}
    # a replaced file's own includes, which its text may name otherwise than the file on disk
    pending = [path for path in closure if path.resolve() in replaced]
    while pending:
        path = pending.pop()
        for found in include_closure(replaced[path.resolve()], dirs, here=path.parent):
            if found not in closure:
                closure.append(found)
                pending += [found] if found.resolve() in replaced else []
    if not replaced and not any(path.read_bytes().startswith(_BOM) for path in closure):
        return dirs
    mirror = tmp / "bom-free"

    def mirrored(path: Path) -> Path:
        return mirror.joinpath(path.drive.strip(":\\/") or "root", path.relative_to(path.anchor))

    for path in closure:
        copy = mirrored(path)
        copy.parent.mkdir(parents=True, exist_ok=True)
        data = replaced[path.resolve()].encode("utf-8") if path.resolve() in replaced else path.read_bytes()
        copy.write_bytes(data[len(_BOM):] if data.startswith(_BOM) else data)
    search = []
    for directory in dirs:
        mirrored(directory).mkdir(parents=True, exist_ok=True)  # a "../x" from it must resolve
        search += [mirrored(directory), directory]
    return search


_HLSL_INCLUDE = re.compile(r'^[ \t]*#[ \t]*include[ \t]*[<"]([^">]+)[">]', re.M)


def check_limits(text: str, name: str, include_dirs) -> None:
    """Refuse, before glslang reads it, an HLSL text whose includes form a cycle through a
    file without an #ifndef include guard (glslang would follow it until memory ran out: 5.8 GB,
    issue 39) or nest deeper than source_limits.MAX_INCLUDE_DEPTH, a file over
    MAX_SOURCE_BYTES, or a text (all its files) over the other source_limits. Includes are
    resolved as glslang does: the including file's folder, then ``include_dirs``, then
    HLSL_ROOT; every #include counts, whichever #if holds it."""
    search = tuple(Path(d) for d in include_dirs) + (HLSL_ROOT,)
    texts: dict[Path, str] = {}
    height: dict[Path, int] = {}  # deepest include chain below a file already walked
    pieces = [(name, text)]

    def walk(includes: list, display: str, stack: tuple) -> int:
        deepest = 0
        for line, target in includes:
            if target is None:
                continue  # glslang reports it, at this line
            where = f"{display}:{line}"
            if target in stack:
                if target in texts and _is_guarded(texts[target]):
                    continue  # the #ifndef guard ends the cycle (glslang does not implement #pragma once)
                chain = " -> ".join(str(p) for p in (*stack[1:], target))
                raise source_limits.ShaderLimitError(f"{where}: include cycle: {chain}")
            if target not in height:
                source_limits.check_file_size(target, f"{where}: ")
                texts[target], below = _included_file(target, search)
                pieces.append((str(target), texts[target]))
                height[target] = 0
                source_limits.check_include_depth(len(stack), where)
                height[target] = walk(below, str(target), stack + (target,))
            source_limits.check_include_depth(len(stack) + height[target], where)
            deepest = max(deepest, 1 + height[target])
        return deepest

    walk(_includes(text, None, search), name, ("<entry>",))
    starts, offset = [], 0
    for display, piece in pieces:
        starts.append((offset, display))
        offset += piece.count("\n") + 1

    def locate(n: int) -> str:
        first, display = next((start, shown) for start, shown in reversed(starts) if start < n)
        return f"{display}:{n - first}"

    source_limits.check_pieces([piece for _, piece in pieces], locate)


def _includes(body: str, folder: Path | None, search: tuple) -> list:
    """(line, resolved file or None) of each #include of ``body``, as glslang resolves it: the
    including file's ``folder``, then ``search``."""
    out = []
    for m in _HLSL_INCLUDE.finditer(body):
        line = body.count("\n", 0, m.start()) + 1
        out.append((line, next(((d / m.group(1)).resolve() for d in ([folder] if folder else []) + list(search)
                                if (d / m.group(1)).is_file()), None)))
    return out


def _included_file(path: Path, search: tuple) -> tuple:
    """(the text of the include file ``path``, without a byte-order mark, and _includes of
    it), kept per process (``_INCLUDED_FILES``) and read again when the file or a folder an
    include of it was looked for in changed: each pass of a many-pass shader checks the same
    files (a 256-pass Amplify preview: ~0.2 s a stage to resolve them again)."""
    def build():
        body = strip_bom(path.read_text(encoding="utf-8", errors="replace"))
        names = [m.group(1) for m in _HLSL_INCLUDE.finditer(body)]
        looked = [(d / name).parent for name in names for d in (path.parent, *search)]
        return (body, _includes(body, path.parent, search)), [path, *looked]

    return _INCLUDED_FILES.get((str(path), tuple(map(str, search))), build)


# _included_file's answers: a file's text and its includes, for the files read last.
INCLUDED_FILES_CACHED = 512
_INCLUDED_FILES = FileCache(INCLUDED_FILES_CACHED, identity=followed_key)


def _limit_address_space():  # runs in the child, between fork and exec
    import resource
    hard = resource.getrlimit(resource.RLIMIT_AS)[1]  # a limit can be lowered, never raised
    cap = TOOL_ADDRESS_SPACE_BYTES if hard == resource.RLIM_INFINITY else min(hard, TOOL_ADDRESS_SPACE_BYTES)
    resource.setrlimit(resource.RLIMIT_AS, (cap, cap))


def _run_tool(cmd: list, name: str, **kwargs) -> subprocess.CompletedProcess:
    """``cmd`` under the limits above; over one, a ShaderLimitError naming it and ``name``."""
    try:
        proc = subprocess.run(cmd, capture_output=True, text=True, timeout=_TIMEOUT_S,
                              preexec_fn=_limit_address_space, **kwargs)
    except subprocess.TimeoutExpired:
        raise source_limits.ShaderLimitError(
            f"{name}: {Path(cmd[0]).name} ran over the compile time limit of {_TIMEOUT_S} s "
            "(hlsl._TIMEOUT_S) and was stopped") from None
    if proc.returncode < 0 or "std::bad_alloc" in proc.stderr:
        # (a signal's name where Python knows it: SIGSEGV, a crash of the tool, as glslang 12's on
        # a uniform redeclared with another type, user_definitions.retyped_prelude_globals)
        try:
            signal_name = f" {signal.Signals(-proc.returncode).name}" if proc.returncode < 0 else ""
        except ValueError:
            signal_name = ""
        raise source_limits.ShaderLimitError(
            f"{name}: {Path(cmd[0]).name} ended without a result (signal {-proc.returncode}{signal_name}"
            f"{', out of memory' if 'bad_alloc' in proc.stderr else ''}) under the memory limit of "
            f"{TOOL_ADDRESS_SPACE_BYTES >> 30} GiB (hlsl.TOOL_ADDRESS_SPACE_BYTES)")
    return proc


def compile_spirv(text: str, name: str = "<hlsl>", include_dirs=(), *, optimize: bool = False,
                  extra_args=(), stage: str = "frag", entry: str = "main", replaced=None) -> bytes:
    """HLSL source -> SPIR-V bytes; ShaderCompileError (mapped messages) if it fails.
    ``replaced``: {path: text} read in place of those included files (_bom_free_search)."""
    glslang = tool(GLSLANG)
    check_limits(text, name, include_dirs)
    with tempfile.TemporaryDirectory(prefix="pbrlab-hlsl-") as tmp:
        search = _bom_free_search(text, include_dirs, Path(tmp), replaced)
        include_args = [f"-I{d}" for d in search] + [f"-I{HLSL_ROOT.resolve()}"]
        src = Path(tmp) / _ENTRY_NAME
        out = Path(tmp) / "out.spv"
        src.write_text(strip_bom(text), encoding="utf-8")
        cmd = [glslang, "-D", "-V", "-e", entry, "-S", stage, "--auto-sampled-textures",
               *([] if optimize else ["-Od"]), *extra_args, *include_args, src.name, "-o", out.name]
        proc = _run_tool(cmd, name, cwd=tmp)
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
        proc = _run_tool([cross, "--version", str(version), "--no-es", *flags, str(path)], "<SPIR-V>")
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
