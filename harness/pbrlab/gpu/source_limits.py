"""Limits on shader text, checked before any compiler reads it (issue 39).

A shader's text can make a compiler hang, crash or take the machine's memory long before it
reports an error: an include cycle glslang follows for ever, a macro whose expansion doubles
forty times, a file of 100 MB. pbrlab checks each program's text against these limits
first, and a text over one is a ShaderLimitError naming the file, the line and the limit.
Each limit protects a stated budget of one compile: 1 GiB of memory and 5 s of preprocessing
on llvmpipe (Mesa 22.3, measured on this project's 2-core machine; figures beside each):

* MAX_SOURCE_BYTES, one program's text after its includes: 16 MiB. The slowest reader is
  this module's own scan, measured at 4 MB/s of dense code (10 MB in 2.5 s) and 35 MB/s
  of comments (Mesa's preprocessor: 32 MB/s of comments, 10 MB in 0.32 s), so 16 MiB is at
  most about 4 s of the 5 s budget; a shader file larger than that is refused by its
  size, before it is read.
* MAX_INCLUDE_DEPTH, files open at once through #include: 64. Both include expanders keep
  one frame a file (ours: Python recursion, about 3 frames a level against Python's limit
  of 1,000; glslang: a stack of open files); a cycle is refused wherever it is found.
* MAX_EXPANDED_TOKENS, tokens after macro expansion: 2^22 (4.2 million). Measured: 2^17
  leaves of a doubling macro (5.2e5 tokens) took Mesa 0.65 s and 130 MiB, about 250 bytes
  and 1.2 us a token, so 1 GiB / 256 bytes = 2^22 tokens, 5 s.
* MAX_NESTING, brackets ( [ { open at once: 256. Mesa's parser stops at 10,000 with
  "memory exhausted" (bison's YYMAXDEPTH, measured); glslang's parser and this module's
  macro scan recurse once a level, the scan within Python's 1,000 frames (a quarter of
  them); C99's minimum for a compiler is 63 levels of parentheses (5.2.4.1).
* MAX_ARRAY_ELEMENTS, elements of one array with a literal size: 16,384. llvmpipe runs a
  shader on its rasteriser threads, a local array on the thread's stack once per SIMD lane
  (LLVM allocas; 4 lanes at 128 bits, 8 at 256): the widest element, a vec4 of 16 bytes, in
  8 lanes takes 128 bytes an element, and a quarter of the 8 MiB default thread stack
  (RLIMIT_STACK) is 2 MiB / 128 bytes = 16,384 elements. The GL's own uniform arrays stay
  far below it (GL_MAX_FRAGMENT_UNIFORM_VECTORS: 4,096 here).

The checks read the text as a C preprocessor would tokenise it (comments removed, lines
joined at a backslash); they over-approximate (every #define counts, whichever #if branch
holds it), which only matters for texts near a limit.
"""

from __future__ import annotations

import hashlib
import re
from pathlib import Path

from ..foundation.errors import PbrlabError
from ..foundation.file_identity import FileCache

MAX_SOURCE_BYTES = 16 * 1024 * 1024
MAX_INCLUDE_DEPTH = 64
MAX_EXPANDED_TOKENS = 1 << 22
MAX_NESTING = 256
MAX_ARRAY_ELEMENTS = 1 << 14


class ShaderLimitError(PbrlabError):
    """A shader's text is over one of this module's limits."""


def check_file_size(path: Path, where: str = ""):
    """Refuse a shader file over MAX_SOURCE_BYTES before reading it."""
    try:
        size = Path(path).stat().st_size
    except OSError:
        return  # the reader reports it
    if size > MAX_SOURCE_BYTES:
        raise ShaderLimitError(f"{where}{path}: {size} bytes, over the shader size limit of "
                               f"{MAX_SOURCE_BYTES} bytes (source_limits.MAX_SOURCE_BYTES)")


def check_include_depth(depth: int, where: str):
    if depth > MAX_INCLUDE_DEPTH:
        raise ShaderLimitError(f"{where}: includes nested {depth} deep, over the limit of "
                               f"{MAX_INCLUDE_DEPTH} (source_limits.MAX_INCLUDE_DEPTH)")


_COMMENT_OR_STRING = re.compile(r'//[^\n]*|/\*.*?(?:\*/|\Z)|"(?:\\.|[^"\\\n])*"', re.S)
_TOKEN = re.compile(r"[A-Za-z_]\w*|\d[\w.]*|\.\d\w*|##|#|\S")
_DEFINE = re.compile(r"^\s*#\s*define\s+([A-Za-z_]\w*)(\(([^)]*)\))?(.*)$")
_ARRAY = re.compile(r"\[\s*(\d+)[uU]?\s*\]")


def _logical_lines(text: str, ends: list | None = None):
    """(first physical line number, logical line) with comments blanked (newlines kept, so
    the numbers hold) and backslash-newlines joined. ``ends``, when given, gets whether the
    text ends inside a line that goes on (an unterminated ``/*`` comment, a last line ending in
    a backslash): the next text joined to it would be read as part of it."""
    open_comment = []

    def blank(m):
        if m.group(0).startswith("/*") and (len(m.group(0)) < 4 or not m.group(0).endswith("*/")):
            open_comment.append(True)  # ran to the end of the text
        return " " + "\n" * m.group(0).count("\n")
    stripped = _COMMENT_OR_STRING.sub(blank, text)
    number, pending, start = 0, [], 1
    for number, line in enumerate(stripped.split("\n"), start=1):
        if not pending:
            start = number
        if line.endswith("\\"):
            pending.append(line[:-1])
            continue
        pending.append(line)
        yield start, " ".join(pending)
        pending = []
    if pending:
        yield start, " ".join(pending)
    if ends is not None:
        ends.append(bool(pending or open_comment))


def _scanned(text: str) -> tuple:
    """(the lines of ``text`` the checks read, whether the text ends inside a line that goes
    on: _logical_lines' ``ends``). Each line: (its number, the name a ``#define`` defines or
    None for code, the macro's parameters, its tokens (a macro's body), the brackets among
    them, an array size over MAX_ARRAY_ELEMENTS written on it or None); other directives
    are not read."""
    lines, ends = [], []
    for number, line in _logical_lines(text, ends):
        definition = _DEFINE.match(line)
        if definition:
            params = None if definition.group(2) is None else [p.strip() for p in definition.group(3).split(",") if p.strip()]
            name, tokens = definition.group(1), _TOKEN.findall(definition.group(4))
        elif line.lstrip().startswith("#"):
            continue
        else:
            name, params, tokens = None, None, _TOKEN.findall(line)
        brackets = "".join(t for t in tokens if t in _BRACKETS)
        over = next((m.group(1) for m in _ARRAY.finditer(line) if int(m.group(1)) > MAX_ARRAY_ELEMENTS), None)
        lines.append((number, name, params, tokens, brackets, over))
    return lines, ends[0]


_BRACKETS = frozenset("()[]{}")
# _scanned's answers for the texts seen last (check_pieces: each pass of a many-pass shader
# checks the same include files again), under a digest of the text: more than the files of a
# few programs (a built-in program reads ~90 files, a URP one up to ~150), or every pass
# would push out the files the next one reads.
SCANNED_CACHED = 1024
_SCANNED = FileCache(SCANNED_CACHED)


def _scanned_kept(text: str) -> tuple:
    key = hashlib.sha256(text.encode("utf-8", "surrogatepass")).digest()
    return _SCANNED.get(key, lambda: (_scanned(text), []))


def check_text(text: str, locate) -> None:
    """Refuse ``text`` (one program, includes expanded or not) over MAX_SOURCE_BYTES,
    MAX_NESTING, MAX_ARRAY_ELEMENTS or MAX_EXPANDED_TOKENS; ``locate(line)`` names where a
    line of ``text`` came from ("file:line"). An expanded text is checked in the pieces its
    ``#line`` directives start (check_pieces: each file's lines scanned once a process)."""
    starts = [0, *(m.start() + 1 for m in _LINE_DIRECTIVE.finditer(text))]
    check_pieces([text[a:b - 1] for a, b in zip(starts, starts[1:])] + [text[starts[-1]:]], locate)


_LINE_DIRECTIVE = re.compile(r"\n(?=#line )")


def check_pieces(pieces: list[str], locate) -> None:
    """check_text of ``"\n".join(pieces)`` (a program and the files it includes), each
    piece's scan kept for the pieces seen last: the same answer, and a file read by many
    programs is scanned once. Where a piece ends inside a line that goes on into the next,
    the joined text is scanned as one."""
    scans = [_scanned_kept(piece) for piece in pieces]
    if any(ends for _, ends in scans[:-1]):
        pieces = ["\n".join(pieces)]
        scans = [_scanned(pieces[0])]
    _check(pieces, [lines for lines, _ in scans], locate)


def _check(pieces: list[str], scans: list, locate) -> None:
    """check_text's checks on the joined ``pieces``, from each piece's _scanned lines."""
    size = sum(len(piece.encode("utf-8", "surrogatepass")) for piece in pieces) + len(pieces) - 1
    if size > MAX_SOURCE_BYTES:
        raise ShaderLimitError(f"{locate(1)}: the program is {size} bytes with its includes, over the "
                               f"shader size limit of {MAX_SOURCE_BYTES} (source_limits.MAX_SOURCE_BYTES)")
    macros: dict[str, tuple[list[str] | None, list[str]]] = {}
    defined_at: dict[str, int] = {}
    code: list[str] = []
    depth = 0
    offset = 0  # lines of the pieces before
    for piece, lines in zip(pieces, scans):
        for number, name, params, tokens, brackets, over in lines:
            number += offset
            if name is not None:
                old = macros.get(name)
                if old is None or len(tokens) >= len(old[1]):  # a redefinition: keep the larger
                    macros[name] = (params, tokens)
                    defined_at[name] = number
            else:
                code.extend(tokens)
            for token in brackets:
                if token in "([{":
                    depth += 1
                    if depth > MAX_NESTING:
                        raise ShaderLimitError(f"{locate(number)}: brackets nested over {MAX_NESTING} deep "
                                               "(source_limits.MAX_NESTING)")
                else:
                    depth = max(depth - 1, 0)
            if over is not None:
                raise ShaderLimitError(f"{locate(number)}: an array of {over} elements, over the limit "
                                       f"of {MAX_ARRAY_ELEMENTS} (source_limits.MAX_ARRAY_ELEMENTS)")
        offset += piece.count("\n") + 1
    sizes = _ExpansionSize(macros)
    tokens = sizes.sequence(code, ())[0]
    if tokens > MAX_EXPANDED_TOKENS:
        largest = max(sizes.cost, key=lambda name: sum(sizes.cost[name]))  # the macro to blame
        raise ShaderLimitError(f"{locate(defined_at[largest])}: macros expand the program to about {tokens} "
                               f"tokens (the largest macro: {largest}, defined here), over "
                               f"the limit of {MAX_EXPANDED_TOKENS} (source_limits.MAX_EXPANDED_TOKENS)")


class _ExpansionSize:
    """An upper bound on the tokens a token sequence expands to. Every macro's expansion is
    linear in its largest argument's: (c, k) means c + k * A tokens for arguments of at most
    A tokens (k counts the parameter uses); a macro met again inside its own expansion stays
    one token (C99 6.10.3.4). Costs are computed once per macro, depth first without Python
    recursion over macros (a chain of thousands of #defines)."""

    def __init__(self, macros):
        self.macros = macros
        self.cost: dict[str, tuple[int, int]] = {}

    def macro_cost(self, name: str) -> tuple[int, int]:
        if name in self.cost:
            return self.cost[name]
        stack, active = [name], {name}
        while stack:
            top = stack[-1]
            params, body = self.macros[top]
            waiting = [t for t in body if t in self.macros and t not in self.cost and t not in active]
            if waiting:
                stack.append(waiting[0])
                active.add(waiting[0])
                continue
            self.cost[top] = self.sequence(body, tuple(params or ()), active)
            stack.pop()
            active.discard(top)
        return self.cost[name]

    def sequence(self, tokens: list[str], params: tuple, active=frozenset()) -> tuple[int, int]:
        """(c, k) of ``tokens``; a parameter of ``params`` counts as A."""
        c = k = 0
        i = 0
        while i < len(tokens):
            token = tokens[i]
            i += 1
            if token in params:
                k += 1
                continue
            if token not in self.macros or token in active:
                c += 1
                continue
            mc, mk = self.macro_cost(token) if token not in self.cost else self.cost[token]
            if self.macros[token][0] is None:  # object-like
                c, k = c + mc, k + mk
                continue
            if i >= len(tokens) or tokens[i] != "(":  # a function-like name without a call
                c += 1
                continue
            args, i = self._arguments(tokens, i)
            ac = ak = 0
            for arg in args:
                sc, sk = self.sequence(arg, params, active)
                ac, ak = max(ac, sc), max(ak, sk)
            c, k = c + mc + mk * ac, k + mk * ak
        return c, k

    @staticmethod
    def _arguments(tokens, i):
        """The argument token lists of the call whose "(" is at ``i``; the index after ")"."""
        args, current, depth = [], [], 0
        i += 1
        while i < len(tokens):
            token = tokens[i]
            i += 1
            if token == "(":
                depth += 1
            elif token == ")":
                if depth == 0:
                    break
                depth -= 1
            elif token == "," and depth == 0:
                args.append(current)
                current = []
                continue
            current.append(token)
        args.append(current)
        return args, i
