"""Generate hlsl_ports/ from glsl/: the mechanical GLSL -> HLSL port (STYLE 9).

    python -m pbrlab.gpu.port_hlsl            # rewrite hlsl_ports/ from glsl/
    python -m pbrlab.gpu.port_hlsl --check    # exit 1 (and list the files) if hlsl_ports/ is stale

The HLSL twins are generated, never edited: tests/gpu/hlsl/test_port_generation.py fails when
regenerating would change a committed file. The rules below are the whole port; everything
else is copied byte for byte, so an HLSL body reads line for line as its GLSL source.

  1. Names of files: ``pbr/<path>.glsl`` -> ``pbr/<path>.hlsl`` (includes and comments),
     include guards ``PBR_<PATH>_GLSL`` -> ``PBR_<PATH>_HLSL``, "relative to glsl/" ->
     "relative to hlsl_ports/".
  2. One line is inserted after the include guard's ``#define``:
     ``#include "pbr/common/shim.hlsl"`` with a do-not-edit notice. The shim
     (hand-written, the port's only hand-written code) gives HLSL the GLSL spellings the
     bodies use: ``vecN``/``ivecN``/``uvecN``/``bvecN``, ``mix`` (``lerp``, and the
     boolean-select form), ``fract`` (``frac``), ``inversesqrt`` (``rsqrt``), a
     GLSL-semantics ``mod`` (not ``fmod``), ``greaterThan`` and friends. Line N of a GLSL
     file is line N of its twin up to the guard and line N + 1 after it.
  3. In code (never in comments): a one-argument vector constructor ``vec3(x)`` becomes the
     cast ``((vec3)(x))``. HLSL has no splat constructor; the cast splats a scalar and
     truncates a longer vector, as GLSL's constructor does.
  4. In code: ``atan(y, x)`` with two arguments becomes ``atan2(y, x)`` (same argument
     order; HLSL's ``atan`` takes one).
  5. Refused, with the GLSL file and line (PortError): matrix types (GLSL ``m * v`` is
     HLSL ``mul(v, m)`` or ``mul(m, v)`` depending on the storage order, which a textual
     port cannot know), struct constructors and array constructors (HLSL has neither:
     write field assignments), and HLSL reserved words used as identifiers.
  6. An ``#error`` message, bare in the GLSL, is quoted in the twin (before rules 1 to 5, which
     then leave it alone as they leave string literals). The GLSL cannot quote it: naga's
     preprocessor (the GLSL front end of wgpu, docs/wgsl.md) rejects a quote character anywhere,
     even in a skipped ``#if`` branch. The HLSL keeps it quoted because glslang, which compiles
     the twins here, prints bare ``#error`` tokens spaced apart (``PBR_TONEMAP : unknown
     value``), while DXC, Slang and glslang print a quoted message as written.
"""

from __future__ import annotations

import argparse
import re
import sys
from pathlib import Path

from ..foundation import outputs
from ..foundation.errors import PbrlabError
from ..foundation.locations import locate
from .shaders import GLSL_ROOT

HLSL_ROOT = locate("hlsl_ports")
SHIM_INCLUDE = "pbr/common/shim.hlsl"
GENERATOR = "harness/pbrlab/gpu/port_hlsl.py"

# Words that are reserved or typed in HLSL but free identifiers in GLSL (Microsoft's HLSL
# keyword list, minus those GLSL reserves as well). A GLSL identifier spelled like one of
# these would not compile as HLSL.
HLSL_RESERVED = frozenset("""
    asm asm_fragment BlendState cbuffer centroid column_major compile compile_fragment
    ComputeShader DepthStencilState DepthStencilView DomainShader double dword export
    extern GeometryShader globallycoherent groupshared half HullShader inline interface
    line lineadj linear matrix min10float min12int min16float min16int min16uint
    namespace nointerpolation noperspective packoffset pass PixelShader point precise
    RasterizerState register RenderTargetView row_major sample sampler SamplerState
    shared snorm stateblock stateblock_state static string tbuffer technique technique10
    technique11 texture Texture1D Texture2D Texture3D TextureCube triangle triangleadj
    typedef unorm vector VertexShader volatile
""".split())

_VECTOR_CTOR = re.compile(r"\b(?:(?P<vec>(?:float|int|uint|bool)[234])|(?P<atan>atan))\s*\(")
# Rule 3: GLSL spellings -> HLSL ones, in code only.
_VECTOR_TYPE = re.compile(r"\b([biu]?)vec([234])\b")
_SCALAR_OF = {"": "float", "i": "int", "u": "uint", "b": "bool"}
_FUNCTION_NAMES = {"fract": "frac", "inversesqrt": "rsqrt", "mix": "lerp", "mod": "pbr_mod"}
_FUNCTION_CALL = re.compile(r"\b(" + "|".join(_FUNCTION_NAMES) + r")(?=\s*\()")
_COMPARISON = re.compile(r"\b(greaterThan|lessThan|greaterThanEqual|lessThanEqual|equal|notEqual|not)\s*\(")
_BOOLEAN_HINT = re.compile(r"\bbvec[234]\b|\bbool\b|\btrue\b|\bfalse\b|[<>]|==|!=|&&|\|\|")
_MATRIX = re.compile(r"\b[d]?mat[234](?:x[234])?\b")
_ARRAY_CTOR = re.compile(r"\b\w+\s*\[\s*\w*\s*\]\s*\(")
_STRUCT = re.compile(r"\bstruct\s+(\w+)")
_IDENT = re.compile(r"\b[A-Za-z_]\w*\b")
_GUARD_DEFINE = re.compile(r"^#\s*ifndef\s+(\w+)\s*\n#\s*define\s+\1\b[^\n]*\n", re.M)
_LIBRARY_PATH = re.compile(r"(?<![\w.])((?:pbr/)?[\w/]*?[a-z0-9_]+)\.glsl\b")
_GUARD_NAME = re.compile(r"\b(PBR_[A-Za-z0-9_<>]*?)_GLSL\b")
_BARE_ERROR = re.compile(r'^([ \t]*#[ \t]*error[ \t]+)([^"\s][^\n]*?)[ \t]*$', re.M)


class PortError(PbrlabError):
    """A GLSL construct the mechanical port does not translate (file:line: why)."""


def _mask(text: str) -> str:
    """``text`` with comments and string literals blanked (newlines kept): code only."""
    out = list(text)
    i, n = 0, len(text)
    while i < n:
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
        elif text[i] == '"':
            j = text.find('"', i + 1)
            j = n if j < 0 else j + 1
        else:
            i += 1
            continue
        for k in range(i, j):
            if out[k] != "\n":
                out[k] = " "
        i = j
    return "".join(out)


def _closing(mask: str, open_index: int, where) -> int:
    depth = 0
    for k in range(open_index, len(mask)):
        if mask[k] == "(":
            depth += 1
        elif mask[k] == ")":
            depth -= 1
            if depth == 0:
                return k
    raise PortError(f"{where(open_index)}: unbalanced parenthesis")


def _top_level_commas(mask: str, start: int, end: int) -> int:
    depth, commas = 0, 0
    for ch in mask[start:end]:
        if ch in "([":
            depth += 1
        elif ch in ")]":
            depth -= 1
        elif ch == "," and depth == 0:
            commas += 1
    return commas


def _rewrite_code(text: str, mask: str, start: int, end: int, where) -> str:
    """Rules 3 and 4 on text[start:end], recursively inside the arguments."""
    out, i = [], start
    while True:
        m = _VECTOR_CTOR.search(mask, i, end)
        if m is None:
            out.append(text[i:end])
            return "".join(out)
        open_index = m.end() - 1
        close = _closing(mask, open_index, where)
        inner = _rewrite_code(text, mask, open_index + 1, close, where)
        commas = _top_level_commas(mask, open_index + 1, close)
        out.append(text[i:m.start()])
        if m.group("vec") and commas == 0 and mask[open_index + 1:close].strip():
            out.append(f"(({m.group('vec')})({inner}))")
        elif m.group("atan") and commas == 1:
            out.append(f"atan2({inner})")
        else:
            out.append(text[m.start():open_index + 1] + inner + ")")
        i = close + 1


def _split_arguments(mask: str, open_index: int, close: int) -> list[tuple[int, int]]:
    """(start, end) of each top-level argument between the parentheses at open_index/close."""
    spans, depth, start = [], 0, open_index + 1
    for k in range(open_index + 1, close):
        ch = mask[k]
        if ch in "([":
            depth += 1
        elif ch in ")]":
            depth -= 1
        elif ch == "," and depth == 0:
            spans.append((start, k))
            start = k + 1
    spans.append((start, close))
    return spans


def _rename_tokens(text: str) -> str:
    """Rule 3: vecN/ivecN/uvecN/bvecN -> floatN/intN/uintN/boolN, fract -> frac,
    inversesqrt -> rsqrt, mix -> lerp, mod -> pbr_mod; in code, never in comments."""
    mask = _mask(text)
    edits = [(m.start(), m.end(), _SCALAR_OF[m.group(1)] + m.group(2)) for m in _VECTOR_TYPE.finditer(mask)]
    edits += [(m.start(), m.end(), _FUNCTION_NAMES[m.group(1)]) for m in _FUNCTION_CALL.finditer(mask)]
    out, i = [], 0
    for start, end, word in sorted(edits):
        out.append(text[i:start])
        out.append(word)
        i = end
    out.append(text[i:])
    return "".join(out)


def _check_portable(mask: str, structs: set[str], where) -> None:
    for m in _COMPARISON.finditer(mask):
        raise PortError(f"{where(m.start())}: {m.group(1)}(): a component-wise comparison function has "
                        "no HLSL name (nor a GLSL ES 1.00 form for a select); compare per component")
    booleans = set(re.findall(r"\b(?:bvec[234]|bool)\s+(\w+)", mask))  # names declared boolean
    for m in re.finditer(r"\bmix\s*\(", mask):
        close = _closing(mask, m.end() - 1, where)
        args = _split_arguments(mask, m.end() - 1, close)
        selector = mask[args[-1][0]:args[-1][1]]
        if len(args) == 3 and (_BOOLEAN_HINT.search(selector) or booleans & set(_IDENT.findall(selector))):
            raise PortError(f"{where(m.start())}: mix() with a boolean selector: HLSL lerp has none "
                            "(nor GLSL ES 1.00); select per component")
    for m in _MATRIX.finditer(mask):
        raise PortError(f"{where(m.start())}: matrix type {m.group(0)!r}: GLSL m * v and HLSL "
                        "mul() disagree on the order; the port refuses matrices")
    for m in _ARRAY_CTOR.finditer(mask):
        raise PortError(f"{where(m.start())}: array constructor: HLSL has none; assign the elements")
    for m in _IDENT.finditer(mask):
        word = m.group(0)
        if word in HLSL_RESERVED:
            raise PortError(f"{where(m.start())}: {word!r} is reserved in HLSL; rename it in the GLSL")
        if word in structs:
            tail = mask[m.end():m.end() + 64].lstrip()
            if tail.startswith("(") and not re.search(r"\bstruct\s+$", mask[max(0, m.start() - 16):m.start()]):
                raise PortError(f"{where(m.start())}: struct constructor {word}(...): HLSL has none; "
                                "assign the fields")


def _quote_error_messages(text: str) -> str:
    """Rule 6: ``#error message`` -> ``#error "message"``."""
    return _BARE_ERROR.sub(lambda m: f'{m.group(1)}"{m.group(2)}"', text)


def _rename_files(text: str) -> str:
    """Rule 1 (code and comments alike)."""
    text = _LIBRARY_PATH.sub(lambda m: m.group(0) if m.group(1).startswith("glsl") else m.group(1) + ".hlsl", text)
    text = _GUARD_NAME.sub(lambda m: m.group(1) + "_HLSL", text)
    return text.replace("relative to glsl/)", "relative to hlsl_ports/)")


def port_text(text: str, name: str = "<glsl>", structs: set[str] | None = None) -> str:
    """The HLSL twin of one GLSL library file (``name`` is used in messages)."""
    text = _quote_error_messages(text)
    structs = set(structs or ()) | set(_STRUCT.findall(_mask(text)))

    def where(index: int) -> str:
        return f"{name}:{text.count(chr(10), 0, index) + 1}"

    _check_portable(_mask(text), structs, where)
    renamed = _rename_tokens(text)
    code = _rewrite_code(renamed, _mask(renamed), 0, len(renamed), where)
    code = _rename_files(code)
    guard = _GUARD_DEFINE.search(code)
    if guard is None:
        raise PortError(f"{name}: no include guard (#ifndef X / #define X) to put the shim after")
    source = name if name.startswith("glsl/") else f"glsl/{name}"
    notice = (f'#include "{SHIM_INCLUDE}"  // generated from {source} by {GENERATOR}: '
              "edit the GLSL, then regenerate")
    if name.endswith("common/shim.glsl"):
        raise PortError(f"{name}: the shim is HLSL-only and hand-written")
    return code[:guard.end()] + notice + "\n" + code[guard.end():]


def port_expression(expression: str) -> str:
    """Rules 3 to 5 on a GLSL expression (tests evaluate one expression in both languages)."""
    renamed = _rename_tokens(expression)
    return _rewrite_code(renamed, _mask(renamed), 0, len(renamed), lambda i: "<expression>")


def library_structs(glsl_root: Path = GLSL_ROOT) -> set[str]:
    names: set[str] = set()
    for path in sorted((glsl_root / "pbr").rglob("*.glsl")):
        names |= set(_STRUCT.findall(_mask(path.read_text(encoding="utf-8"))))
    return names


def generate(glsl_root: Path = GLSL_ROOT, hlsl_root: Path = HLSL_ROOT) -> dict[Path, str]:
    """{hlsl path: text} for every library file (the shim is not generated)."""
    structs = library_structs(glsl_root)
    out = {}
    for path in sorted((glsl_root / "pbr").rglob("*.glsl")):
        rel = path.relative_to(glsl_root)
        text = path.read_text(encoding="utf-8")
        out[hlsl_root / rel.with_suffix(".hlsl")] = port_text(text, rel.as_posix(), structs)
    return out


def stale_files(glsl_root: Path = GLSL_ROOT, hlsl_root: Path = HLSL_ROOT) -> list[str]:
    """Ports that differ from what the generator writes, are missing, or have no source."""
    expected = generate(glsl_root, hlsl_root)
    problems = [f"{p.relative_to(hlsl_root)}: differs from the generated text" if p.is_file()
                else f"{p.relative_to(hlsl_root)}: missing"
                for p, text in expected.items()
                if not p.is_file() or p.read_text(encoding="utf-8") != text]
    shim = hlsl_root / SHIM_INCLUDE
    for path in sorted((hlsl_root / "pbr").rglob("*.hlsl")):
        if path not in expected and path != shim:
            problems.append(f"{path.relative_to(hlsl_root)}: no GLSL source (delete it)")
    return problems


def write(glsl_root: Path = GLSL_ROOT, hlsl_root: Path = HLSL_ROOT) -> list[Path]:
    """Write the ports that changed, all or none (outputs.transaction)."""
    changed = {path: text for path, text in generate(glsl_root, hlsl_root).items()
               if not path.is_file() or path.read_text(encoding="utf-8") != text}
    for path in changed:
        path.parent.mkdir(parents=True, exist_ok=True)
    with outputs.transaction(changed) as tx:
        for path, text in changed.items():
            tx.write_text(path, text)
    return list(changed)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="python -m pbrlab.gpu.port_hlsl", description=__doc__.split("\n\n")[0])
    parser.add_argument("--check", action="store_true", help="report stale ports, write nothing")
    parser.add_argument("--glsl-root", type=Path, default=GLSL_ROOT)
    parser.add_argument("--hlsl-root", type=Path, default=HLSL_ROOT)
    args = parser.parse_args(argv)
    try:
        if args.check:
            problems = stale_files(args.glsl_root, args.hlsl_root)
            for line in problems:
                print(line)
            if problems:
                print("regenerate with: python -m pbrlab.gpu.port_hlsl", file=sys.stderr)
            return 1 if problems else 0
        for path in write(args.glsl_root, args.hlsl_root):
            print(f"wrote {path}")
        return 0
    except PbrlabError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 1


if __name__ == "__main__":
    sys.exit(main())
