"""Shared pieces of the HLSL-port tests: parsing both trees, ulp distances, the agreement log.

Imported by the test modules as ``hlsl_helpers`` (a plain module, like
tests/library/library_helpers.py). The parser reads what a C-like preprocessor would
see at file scope: functions (return type, name, parameters with qualifiers), structs
(fields) and ``#define`` lines; comments are masked first (pbrlab.gpu.port_hlsl._mask).
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from pbrlab.gpu import hlsl, shaders
from pbrlab.gpu.port_hlsl import SHIM_INCLUDE, _mask

GLSL_ROOT = shaders.GLSL_ROOT
HLSL_ROOT = hlsl.HLSL_ROOT

_FUNCTION = re.compile(r"^[ \t]*(?:(?:const|highp|mediump|lowp|inline|static)\s+)*"
                       r"(\w+)\s+(\w+)\s*\(([^()]*)\)\s*\{", re.M)
_STRUCT = re.compile(r"\bstruct\s+(\w+)\s*\{([^}]*)\}", re.S)
_DEFINE = re.compile(r"^[ \t]*#[ \t]*define[ \t]+(\w+)(\([^)]*\))?[ \t]*(.*?)[ \t]*$", re.M)
_GUARD = re.compile(r"^#ifndef\s+(\w+)\s*\n#define\s+\1\b", re.M)
_NOT_TYPES = {"return", "else", "if", "while", "for", "switch", "do"}

# HLSL spellings -> the GLSL ones, so that a hand-written float3 compares equal to vec3.
_HLSL_TYPE = [(re.compile(r"\bfloat([234])\b"), r"vec\1"), (re.compile(r"\bint([234])\b"), r"ivec\1"),
              (re.compile(r"\buint([234])\b"), r"uvec\1"), (re.compile(r"\bbool([234])\b"), r"bvec\1")]


def normalise_type(text: str) -> str:
    text = " ".join(text.split())
    for pattern, repl in _HLSL_TYPE:
        text = pattern.sub(repl, text)
    return text


@dataclass(frozen=True)
class Param:
    qualifier: str      # "", "in", "out", "inout"
    type: str           # normalised (GLSL spelling)
    name: str
    array: str          # "" or "[9]"


@dataclass(frozen=True)
class Function:
    file: str           # path relative to the language root, without the extension
    return_type: str
    name: str
    params: tuple[Param, ...]

    @property
    def signature(self) -> str:
        args = ", ".join(" ".join(x for x in (p.qualifier, p.type, p.name + p.array) if x) for p in self.params)
        return f"{self.return_type} {self.name}({args})"

    @property
    def key(self) -> tuple:
        """Overloads differ by parameter types: (name, types)."""
        return (self.name, tuple(p.type + p.array for p in self.params))


@dataclass
class Tree:
    files: dict[str, str] = field(default_factory=dict)          # stem -> include guard
    headers: dict[str, str] = field(default_factory=dict)        # stem -> first comment line
    functions: dict[tuple, Function] = field(default_factory=dict)
    structs: dict[str, tuple[tuple[str, str], ...]] = field(default_factory=dict)
    macros: dict[tuple[str, str], str] = field(default_factory=dict)  # (file, name) -> value(s)


def _params(text: str) -> tuple[Param, ...]:
    text = " ".join(text.split())
    if not text or text == "void":
        return ()
    out = []
    for part in text.split(","):
        m = re.match(r"^\s*(?:(in|out|inout)\s+)?(?:const\s+)?(\w+)\s+(\w+)\s*(\[\s*\w*\s*\])?\s*$", part)
        if m is None:
            raise ValueError(f"cannot parse parameter {part!r}")
        out.append(Param(m.group(1) or "", normalise_type(m.group(2)), m.group(3),
                         (m.group(4) or "").replace(" ", "")))
    return tuple(out)


def parse_file(text: str, stem: str, tree: Tree, language: str) -> None:
    mask = _mask(text)
    guard = _GUARD.search(mask)
    tree.files[stem] = guard.group(1) if guard else ""
    tree.headers[stem] = text.splitlines()[0] if text else ""
    for m in _FUNCTION.finditer(mask):
        if m.group(1) in _NOT_TYPES:
            continue
        fn = Function(stem, normalise_type(m.group(1)), m.group(2), _params(m.group(3)))
        tree.functions[fn.key] = fn
    for m in _STRUCT.finditer(mask):
        fields = tuple((normalise_type(t), n) for t, n in re.findall(r"(\w+)\s+(\w+)\s*;", m.group(2)))
        tree.structs[m.group(1)] = fields
    values: dict[str, list[str]] = {}
    for m in _DEFINE.finditer(mask):
        name = m.group(1)
        if guard and name == guard.group(1):
            continue
        values.setdefault(name, []).append((m.group(2) or "") + " " + m.group(3))
    for name, vals in values.items():
        tree.macros[(stem, name)] = " | ".join(v.strip() for v in vals)


def parse_tree(root: Path, language: str) -> Tree:
    ext = ".glsl" if language == "glsl" else ".hlsl"
    tree = Tree()
    for path in sorted((root / "pbr").rglob("*" + ext)):
        rel = path.relative_to(root).as_posix()
        if rel == SHIM_INCLUDE:
            continue
        parse_file(path.read_text(encoding="utf-8"), rel[: -len(ext)], tree, language)
    return tree


def parity_problems(glsl: Tree, hlsl_tree: Tree, normalise_value=lambda v: v) -> list[str]:
    """Everything that exists in one tree and not the other, or differs."""
    problems = []
    for stem in sorted(set(glsl.files) | set(hlsl_tree.files)):
        if stem not in hlsl_tree.files:
            problems.append(f"{stem}: GLSL file without an HLSL twin")
        elif stem not in glsl.files:
            problems.append(f"{stem}: HLSL file without a GLSL source")
        else:
            want = re.sub(r"_GLSL$", "_HLSL", glsl.files[stem])
            if hlsl_tree.files[stem] != want:
                problems.append(f"{stem}: include guard {hlsl_tree.files[stem]!r}, expected {want!r}")
            if hlsl_tree.headers[stem] != glsl.headers[stem].replace(".glsl", ".hlsl"):
                problems.append(f"{stem}: header line differs")
    g_by_name = {f.name for f in glsl.functions.values()}
    h_by_name = {f.name for f in hlsl_tree.functions.values()}
    for key in sorted(set(glsl.functions) | set(hlsl_tree.functions)):
        g, h = glsl.functions.get(key), hlsl_tree.functions.get(key)
        if g is None:
            what = "signature differs from the GLSL" if key[0] in g_by_name else "not in the GLSL"
            problems.append(f"function {h.signature} ({h.file}): {what}")
        elif h is None:
            what = "signature differs in the HLSL" if key[0] in h_by_name else "missing in the HLSL"
            problems.append(f"function {g.signature} ({g.file}): {what}")
        elif (g.return_type, g.file, [p.qualifier or "in" for p in g.params]) != \
                (h.return_type, h.file, [p.qualifier or "in" for p in h.params]):
            problems.append(f"function {g.signature} ({g.file}) vs {h.signature} ({h.file}): differ")
    for name in sorted(set(glsl.structs) | set(hlsl_tree.structs)):
        if glsl.structs.get(name) != hlsl_tree.structs.get(name):
            problems.append(f"struct {name}: {glsl.structs.get(name)} (GLSL) vs {hlsl_tree.structs.get(name)} (HLSL)")
    for key in sorted(set(glsl.macros) | set(hlsl_tree.macros)):
        g, h = glsl.macros.get(key), hlsl_tree.macros.get(key)
        if g is None or h is None or normalise_value(g) != h:
            problems.append(f"macro {key[1]} ({key[0]}): {g!r} (GLSL) vs {h!r} (HLSL)")
    return problems


# ---- ulps ----------------------------------------------------------------------------

def ordered_bits(x: np.ndarray) -> np.ndarray:
    """float32 -> int64 that is monotonic in the value, with +0 and -0 both at 0."""
    i = np.asarray(x, np.float32).view(np.int32).astype(np.int64)
    return np.where(i < 0, -(i & 0x7FFFFFFF), i)


def ulp_distance(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """|a - b| in float32 ulps; 0 where both are NaN, a huge number where only one is."""
    a, b = np.asarray(a, np.float32), np.asarray(b, np.float32)
    d = np.abs(ordered_bits(a) - ordered_bits(b))
    both_nan = np.isnan(a) & np.isnan(b)
    one_nan = np.isnan(a) ^ np.isnan(b)
    return np.where(both_nan, 0, np.where(one_nan, np.iinfo(np.int64).max // 2, d))


# Measured agreement per function signature, printed at the end of a run (conftest.py):
# label -> (max ulp, max relative difference, samples).
AGREEMENT: dict[str, tuple[int, float, int]] = {}
