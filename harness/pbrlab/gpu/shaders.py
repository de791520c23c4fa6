"""GLSL source assembly: ``#include`` resolution, ``#line`` bookkeeping, error mapping.

``#include "pbr/brdf/d_ggx.glsl"`` is resolved against the include path: the caller's
directories first, then the library root ``glsl/``. A file is expanded where it is
included; a file wrapped in its own include guard is expanded once when its first
inclusion was outside any ``#if`` (a second copy would preprocess to nothing), so the
compiler reads each library file once. A file that includes itself is an error.

Each expanded file k gets a GLSL source-string number k and its lines are numbered
from ``k * LINE_BLOCK``, both announced with ``#line``. The file is recovered from the
line number alone, because Mesa's compiler sometimes reports the source-string number
of the file that was being read when the error surfaced rather than the file of the
line (seen with Mesa 22.3: an undeclared identifier in an include blamed on the
includer). A message "N:L(col): error: ..." maps back to ``path:line:col``.
``ShaderCompileError`` carries the mapped messages: ``path:line:col: error: ...``, the first
error first and follow-ons after (compile_messages.py).
"""

from __future__ import annotations

import functools
import re
import warnings
from dataclasses import dataclass, field
from pathlib import Path

import moderngl

from ..foundation import safe_paths
from ..foundation.errors import LoopLimitWarning, PbrlabError, ShaderCompileError
from ..foundation.file_identity import FileCache, followed_key
from ..foundation.locations import locate
from .compile_messages import compile_failure
from . import source_limits
from ..foundation import disk_cache
from .cancellation import dies_on_signal
from .driver_time_limit import within_time_limit

GLSL_ROOT = locate("glsl")  # $PBRLAB_GLSL_ROOT, the wheel's package data, or the checkout
UMBRELLA_INCLUDE = "pbr/pbr.glsl"
LINE_BLOCK = 100000  # lines per file in the #line numbering; files are far shorter

# Files whose lines were classified (_scan), by content: a scene's dozen programs read the
# same thirty library files, and classifying their lines again cost 0.3 s of a render.
_SCANS_KEPT = 512
_INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"\s*(//.*)?$')
_VERSION = re.compile(r"^\s*#\s*version\b")
_IF = re.compile(r"^\s*#\s*if(n?def)?\b")
_ENDIF = re.compile(r"^\s*#\s*endif\b")
# A guard opens with ``#ifndef X`` or its long form ``#if !defined X`` / ``#if !defined(X)``
# (the C preprocessor's, which Unity's shaders also write: hyunxiGit's incDeferLight.cginc).
_GUARD = re.compile(r"\A(?:\s*//[^\n]*\n|\s*\n)*\s*#\s*(?:ifndef\s+(\w+)|if\s*!\s*defined\s*(?:\(\s*(\w+)\s*\)|\s(\w+)))"
                    r"\s*\n\s*#\s*define\s+(?:\1|\2|\3)\b.*#\s*endif[^\n]*\s*\Z", re.S)


@functools.lru_cache(maxsize=_SCANS_KEPT)
def _is_guarded(text: str) -> bool:
    """True when the whole file sits inside its own #ifndef/#define/#endif guard."""
    return _GUARD.match(text) is not None
# Mesa: "0:12(5): error: ...", its preprocessor's "0:2(9): preprocessor warning: ..." (a
# warning, as ``#define A__B`` draws: the program still compiles);  glslang: "ERROR: 0:12: ..."
_MESA_MESSAGE = re.compile(r"^(\d+):(\d+)\((\d+)\):\s*(?:preprocessor\s+)?(error|warning)?:?\s*(.*)$")


@dataclass(frozen=True)
class VirtualFile:
    """Text that ``expand`` includes under a name without a file on disk: a program made in
    memory (a Unity shader's GLSL port), reported as the file ``display`` from line
    ``first_line`` (where that text starts in it)."""

    text: str
    display: str
    first_line: int = 1


@dataclass
class Source:
    """An expanded shader: GLSL text plus the table from source-string number to path."""

    text: str
    files: list[str] = field(default_factory=list)
    paths: list[Path] = field(default_factory=list)  # every include file read (resolved)
    probed: list[Path] = field(default_factory=list)  # every place an include was looked for

    def map_messages(self, log: str) -> str:
        """Rewrite compiler messages from 'N:L(C)' to 'path:L:C'."""
        out = []
        for line in log.splitlines():
            m = _MESA_MESSAGE.match(line.strip())
            if m:
                file_index, line_number = divmod(int(m.group(2)), LINE_BLOCK)
                if file_index >= len(self.files):
                    out.append(line.rstrip())
                    continue
                kind = m.group(4) or "error"
                out.append(f"{self.files[file_index]}:{line_number}:{m.group(3)}: {kind}: {m.group(5)}")
            elif line.strip() and not set(line.strip()) <= {"="} and line.strip() != "GLSL Compiler failed":
                out.append(line.rstrip())
        return "\n".join(out)


# What an include-not-found message suggests: the ways a user adds a folder to the search.
INCLUDE_DIRS_HINT = ("add the folder that holds it with -I DIR (pbrlab eval, pbrlab amalgamate) or "
                     "include_dirs=[DIR] (pbrlab.evaluate); a material's surface file finds its includes "
                     "relative to its own folder")


def include_path(extra_dirs=()) -> list[Path]:
    """The directories searched for an include, in order."""
    return [Path(d) for d in extra_dirs] + [GLSL_ROOT]


def resolve_include(name: str, search: list[Path], probed: list | None = None) -> Path | None:
    """The first file ``name`` in ``search``; each place looked at is added to ``probed``
    (a file created there later would change the answer: source_cache checks them). A file
    reached through a symbolic link out of its folder is refused (safe_paths.inside)."""
    for directory in search:
        candidate = directory / name
        if probed is not None:
            probed.append(candidate)
        if candidate.is_file():
            return safe_paths.inside(directory, name, f'#include "{name}" (searched in {directory})', climb=True)
    return None


def _resolve_include_kept(name: str, search: list[Path], probed: list) -> Path | None:
    """resolve_include, its answer and the places it looked at kept per process
    (``_RESOLVED_INCLUDES``) and found again when a folder looked in, or the file found,
    changed: each pass of a many-pass shader expands the same includes (a 256-pass Amplify
    preview: ~90 names a stage)."""
    def build():
        looked: list = []
        target = resolve_include(name, search, looked)
        return (target, looked), [*(p.parent for p in looked), *([target] if target else [])]
    key = (name, tuple(map(str, search)), safe_paths.reading_rules())
    target, looked = _RESOLVED_INCLUDES.get(key, build)
    probed.extend(looked)
    return target


# _resolve_include_kept's answers: a few paths each.
RESOLVED_INCLUDES_CACHED = 1024
_RESOLVED_INCLUDES = FileCache(RESOLVED_INCLUDES_CACHED, identity=followed_key)


@functools.lru_cache(maxsize=8)
def _resolved(folder: Path) -> Path:
    return folder.resolve()


def _display_name(path: Path) -> str:
    try:
        return str(path.relative_to(_resolved(GLSL_ROOT)))
    except ValueError:
        return str(path)


def _ends_in_block_comment(line: str, in_comment: bool) -> bool:
    """Whether a ``/* */`` comment is still open at the end of ``line`` (open at its start
    when ``in_comment``); ``//`` ends the line's code."""
    if "/" not in line:  # no comment opens or closes here
        return in_comment
    i = 0
    while i < len(line):
        pair = line[i:i + 2]
        if in_comment:
            if pair == "*/":
                in_comment, i = False, i + 2
                continue
        elif pair == "//":
            return False
        elif pair == "/*":
            in_comment, i = True, i + 2
            continue
        i += 1
    return in_comment


@dataclass(frozen=True)
class _Line:
    """One line of a shader file as ``expand`` reads it (_scan)."""
    text: str              # as written
    out: str               # as emitted when it is not an include: '#include' neutralised
    in_comment: bool       # starts inside a /* */ comment: commentary, whatever it holds
    depth_step: int        # +1 for #if/#ifdef/#ifndef, -1 for #endif, else 0
    version: bool          # a #version line
    include: str | None    # the name of an #include "..." line


@functools.lru_cache(maxsize=_SCANS_KEPT)
def _scan(body: str) -> tuple[_Line, ...]:
    """The lines of a file's text, classified once per distinct text (a file always starts
    outside a comment, so its lines classify the same wherever it is included)."""
    lines = []
    in_comment = False
    for line in body.splitlines():
        starts_in_comment, in_comment = in_comment, _ends_in_block_comment(line, in_comment)
        out = line.replace("#include", "# include")
        if starts_in_comment:
            lines.append(_Line(line, out, True, 0, False, None))
            continue
        step = 1 if _IF.match(line) else -1 if _ENDIF.match(line) else 0
        m = _INCLUDE.match(line)
        lines.append(_Line(line, out, False, step, _VERSION.match(line) is not None,
                           m.group(1) if m else None))
    return tuple(lines)


_BRANCH_END = re.compile(r"[ \t]*#[ \t]*(elif|else|endif)\b")


def expand(text: str, name: str = "<shader>", include_dirs=(), line_directives: bool = True,
           virtual: dict | None = None) -> Source:
    """Expand the includes of ``text`` (named ``name`` in messages).

    With ``line_directives`` every file switch emits ``#line``; without, files are
    separated by comments (for amalgamation). A ``#version`` line stays first.
    ``virtual`` maps include names to ``VirtualFile``s, found before any directory.
    """
    virtual = virtual or {}
    search = include_path(include_dirs)
    source = Source("", [])
    # A guarded file included once outside any #if is written once: a second copy would
    # be empty after preprocessing. Includes inside conditionals are always expanded.
    emitted_guarded: set[Path] = set()
    resolved: dict[str, Path | None] = {}  # include name -> file, once per expansion
    texts: dict[Path, str] = {}  # file -> its text, read once per expansion
    lines_out: list[str] = []
    version_line: list[str] = []

    def emit_line_marker(file_index: int, next_line: int):
        if line_directives:
            lines_out.append(f"#line {file_index * LINE_BLOCK + next_line} {file_index}")

    def walk(body: str, display: str, stack: tuple[Path, ...], conditional: bool, first_line: int = 1):
        file_index = len(source.files)
        source.files.append(display)
        emit_line_marker(file_index, first_line)
        depth = -1 if _is_guarded(body) else 0  # the file's own guard is not a condition
        # an include expanded in a branch the compiler skips has its #line markers skipped too
        # (a skipped group's directives are not read, C99 6.10.1), so its lines count as this
        # file's: after an include, each later #elif / #else / #endif marks this file's line again
        resync = False
        for number, scanned in enumerate(_scan(body), start=first_line):
            if scanned.in_comment:  # commentary, whatever it looks like (an #include, an #if)
                lines_out.append(scanned.out)
                continue
            depth += scanned.depth_step
            if scanned.version:
                if not version_line and not stack[:-1]:
                    version_line.append(scanned.text.strip())
                    lines_out.append("")  # keep line numbers: the #version line is hoisted
                    continue
                raise PbrlabError(f"{display}:{number}: #version is allowed only in the entry shader")
            if scanned.include is None:
                # moderngl resolves '#include' wherever it appears, comments included;
                # what is left after expansion is commentary, so it is neutralised.
                lines_out.append(scanned.out)
                if resync and _BRANCH_END.match(scanned.out):
                    emit_line_marker(file_index, number + 1)
                continue
            included = scanned.include
            resync = True
            if included in virtual:
                made = virtual[included]
                marker = Path(f"<virtual {included}>")
                if marker in stack:
                    if _is_guarded(made.text):  # its guard is defined by now: this copy is empty
                        lines_out.append(f"// ---- {included}: already open above (include guard)")
                        continue
                    raise PbrlabError(f"{display}:{number}: include cycle through {made.display}")
                walk(made.text, made.display, stack + (marker,), conditional or depth > 0, made.first_line)
                emit_line_marker(file_index, number + 1)
                continue
            if included not in resolved:  # once per name and expansion: the search path is fixed
                resolved[included] = _resolve_include_kept(included, search, source.probed)
            target = resolved[included]
            if target is None and (conditional or depth > 0):
                # under an #if: the compiler's preprocessor decides whether this line is read, so
                # the missing file is an #error there (reported at this file and line if it is)
                lines_out.append(f'#error cannot find include "{included}"')
                continue
            if target is None:
                raise PbrlabError(
                    f"{display}:{number}: cannot find include \"{included}\" "
                    f"(searched: {', '.join(str(d) for d in search)}); {INCLUDE_DIRS_HINT}")
            if target in stack:
                if _is_guarded(texts[target]):  # its guard is defined by now: this copy is empty
                    lines_out.append(f"// ---- {included}: already open above (include guard)")
                    continue
                chain = " -> ".join(_display_name(p) for p in stack[1:] + (target,))
                raise PbrlabError(f"{display}:{number}: include cycle: {chain}")
            source.paths.append(target)
            inside_conditional = conditional or depth > 0
            if target in emitted_guarded:  # read once already, in this expansion
                lines_out.append(f"// ---- {included}: already above (include guard)")
                continue
            if target not in texts:
                texts[target] = read_source(target, f"{display}:{number}: ")
            body = texts[target]
            if _is_guarded(body) and not inside_conditional:
                emitted_guarded.add(target)
            source_limits.check_include_depth(len(stack), f"{display}:{number}")
            if not line_directives:
                lines_out.append(f"// ---- begin {included}")
            walk(body, _display_name(target), stack + (target,), inside_conditional)
            if line_directives:
                emit_line_marker(file_index, number + 1)
            else:
                lines_out.append(f"// ---- end {included}")

    walk(text, name, (Path("<entry>"),), False)
    head = version_line or []
    source.text = "\n".join(head + lines_out) + "\n"
    return source


BOM = "\ufeff"  # U+FEFF, a UTF-8 byte-order mark (EF BB BF) when it opens a file


def strip_bom(text: str) -> str:
    """``text`` without a leading byte-order mark, which editors on Windows write and no
    shader compiler reads (glslang: "unexpected HASH_TOKEN" at the first #)."""
    return text[1:] if text.startswith(BOM) else text


def read_source(path: Path, where: str = "") -> str:
    """A shader file's text; unreadable or non-UTF-8 files raise PbrlabError naming it
    (``where``: the includer's file and line, when there is one)."""
    source_limits.check_file_size(path, where)
    try:
        data = Path(path).read_bytes()
    except OSError as exc:
        raise PbrlabError(f"{where}cannot read shader file {path}: {exc.strerror or exc}") from None
    try:
        return strip_bom(data.decode("utf-8"))
    except UnicodeDecodeError as exc:
        line = data[:exc.start].count(b"\n") + 1
        raise PbrlabError(f"{where}{path}:{line}: not UTF-8 text (byte 0x{data[exc.start]:02x} "
                          f"at offset {exc.start}); save the shader as UTF-8") from None


def expand_file(path: str | Path, include_dirs=(), line_directives: bool = True) -> Source:
    path = Path(path)
    if not path.is_file():
        raise PbrlabError(f"{path}: no such shader file")
    source = expand(read_source(path), str(path),
                    include_dirs=(path.parent, *include_dirs), line_directives=line_directives)
    source.paths.insert(0, path.resolve())
    return source


def amalgamate(entry: str | Path, include_dirs=()) -> str:
    """One self-contained GLSL file: every include inlined, no #include left."""
    return expand_file(entry, include_dirs, line_directives=False).text


# llvmpipe (Mesa's gallivm) ends every loop after this many iterations, without an error:
# LP_MAX_TGSI_LOOP_ITERATIONS in src/gallium/auxiliary/gallivm/lp_bld_limits.h.
LLVMPIPE_LOOP_LIMIT = 65535
# for (int i = START; i < N; ...) / i <= N with literal START and N
_FOR_LOOP = re.compile(r"\bfor\s*\(\s*(?:int|uint|float)?\s*(\w+)\s*=\s*(-?\d+)[uU]?\s*;"
                       r"\s*\1\s*(<=?)\s*(\d+)[uU]?\s*;")
_LINE_DIRECTIVE = re.compile(r"^\s*#\s*line\s+(\d+)(?:\s+(\d+))?")


def loop_limit_warnings(source: Source, limit: int = LLVMPIPE_LOOP_LIMIT) -> list[str]:
    """``path:line: ...`` for each for-loop with literal bounds running past ``limit``.
    Loops with bounds known only at run time are not seen."""
    found = []
    file_index, line_number = 0, 0
    for raw in source.text.splitlines():
        if "line" not in raw and "for" not in raw:  # neither a #line nor a loop: skip the patterns
            line_number += 1
            continue
        m = _LINE_DIRECTIVE.match(raw)
        if m:  # the next line is line L of file K (#line K * LINE_BLOCK + L K)
            file_index, next_line = divmod(int(m.group(1)), LINE_BLOCK)
            line_number = next_line - 1
            continue
        line_number += 1
        loop = _FOR_LOOP.search(raw)
        if loop:
            count = int(loop.group(4)) - int(loop.group(2)) + (1 if loop.group(3) == "<=" else 0)
            if count > limit:
                where = source.files[file_index] if file_index < len(source.files) else "<shader>"
                found.append(f"{where}:{line_number}: a loop of {count} iterations; this renderer "
                             f"stops every loop after {limit} and uses the partial result")
    return found


def source_locator(source: Source):
    """``locate(n)``: "file:line" of line n of ``source.text`` (its #line directives read)."""
    places = []
    file_index, line_number = 0, 0
    for raw in source.text.splitlines():
        m = _LINE_DIRECTIVE.match(raw) if "line" in raw else None
        if m:
            file_index, next_line = divmod(int(m.group(1)), LINE_BLOCK)
            line_number = next_line - 1
            places.append((file_index, 0))
            continue
        line_number += 1
        places.append((file_index, line_number))

    def locate(n: int) -> str:
        index, line = places[min(n, len(places)) - 1] if places else (0, 1)
        name = source.files[index] if index < len(source.files) else "<shader>"
        return f"{name}:{max(line, 1)}"
    return locate


WITHIN_LIMITS_KIND = "within-limits"
_LIMITS_CODE = Path(source_limits.__file__).read_bytes()


def check_limits(source: Source) -> None:
    """``source_limits.check_text`` on an expanded stage. A text that passed is remembered in
    the disk cache under its own text and the checks' code, so only a new text is scanned
    (measured, scenes/example.json's six stages: 0.1 s to scan them, 8 to 16 ms to find
    their verdicts)."""
    name = disk_cache.key(WITHIN_LIMITS_KIND, source.text, _LIMITS_CODE)
    if disk_cache.load(WITHIN_LIMITS_KIND, name) == b"ok":
        return
    source_limits.check_text(source.text, source_locator(source))
    disk_cache.store(WITHIN_LIMITS_KIND, name, b"ok")


_PACKAGE_FILES = (str(Path(__file__).resolve().parents[1]), str(GLSL_ROOT))


def program_label(vertex: Source, fragment: Source) -> str:
    """The files of a program a user wrote (not pbrlab's templates or library), for a
    message about the whole program; pbrlab's own entry files where there are none."""
    files = list(dict.fromkeys(fragment.files[:1] + vertex.files[:1] + fragment.files + vertex.files))
    own = [f for f in files if f and not f.startswith(_PACKAGE_FILES) and not f.startswith("<")]
    named = own or files[:2]
    more = f" and {len(own) - 3} more files" if len(own) > 3 else ""
    return "the program of " + ", ".join(named[:3]) + more


def build_program(ctx: moderngl.Context, vertex: Source, fragment: Source) -> moderngl.Program:
    """Compile and link; errors are reported at the original file and line. The texts are
    checked against source_limits first (size, nesting, arrays, macro expansion), and the
    compile, in-process in the driver, ends the process at once on SIGINT, SIGTERM or SIGHUP
    (cancellation.dies_on_signal). On llvmpipe a loop with literal bounds past its iteration
    cap gives a LoopLimitWarning naming it. Under the ``pbrlab`` command the compile has a
    time limit (driver_time_limit: the process ends with a message naming the program)."""
    for stage in (vertex, fragment):
        check_limits(stage)
    if "llvmpipe" in str(ctx.info.get("GL_RENDERER", "")).lower():
        for stage in (vertex, fragment):
            for message in loop_limit_warnings(stage):
                warnings.warn(message, LoopLimitWarning, stacklevel=2)
    try:
        with dies_on_signal(), within_time_limit(f"compiling {program_label(vertex, fragment)}"):
            return ctx.program(vertex_shader=vertex.text, fragment_shader=fragment.text)
    except moderngl.Error as exc:
        log = str(exc)
        stage, stage_name = ((fragment, "fragment") if "fragment_shader" in log
                             else (vertex, "vertex"))
        messages = "\n".join(line for line in stage.map_messages(log).splitlines()
                             if line.strip() not in ("fragment_shader", "vertex_shader"))
        raise ShaderCompileError(compile_failure(f"{stage_name} shader failed to compile", messages)) from None
