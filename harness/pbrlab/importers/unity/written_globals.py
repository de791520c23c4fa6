"""Globals a Unity program assigns to (``float2 uv; ... uv = i.uv * 2.0;`` at global scope):
Unity compiles Direct3D programs with FXC's backwards-compatibility mode, which lets a program
write a global; the value written lives in that invocation only (the global is the uniform's
value until then). glslang and GLSL refuse a write to a uniform. So each written global keeps
its uniform (its material property binds as before), the functions read and write a
``static`` copy, ``pbrlab_written_<name>``, and the pass's entry points set the copy from the
uniform before calling the program (generate_pass: the same in both stages). Lines are kept.

    program, written = copied_written_globals(program, active_program)
    statements = copy_statements(written)     # an entry point's, before the program runs

A global declared and written in one of the shader's own include files (``float4 _Wind_ST;``
in a pass's .hlsl, ``_Wind_ST.zw += ...`` in its vertex function) is copied the same way in that
file's text (``copied_in_includes``); both languages compile the rewritten text in the file's
place (program.program_include for the GLSL port, hlsl.compile_spirv's ``replaced`` for glslang).
A global the program declares and one of its own include files writes (``float _CircleAngle;`` in
the pass's CBUFFER, ``_CircleAngle = Remap(_CircleAngle, ...)`` in a Shapes.hlsl it includes after)
is copied in the program, and read and written through the copy in the include's functions
(``copied_across_includes``). A global one include declares and another writes is not found:
the compiler names the write.
"""

from __future__ import annotations

import re

from pathlib import Path

from .conditionals import active_text
from .engine_inputs import _outside_braces
from .cg_types import library
from .source_text import CGINC, PACKAGE_STAND_INS, _read_include, blank_comments, call_arguments, included_files

PREFIX = "pbrlab_written"


def copy_name(name: str) -> str:
    """The static copy's name (no double underscore: GLSL reserves it)."""
    return PREFIX + ("" if name.startswith("_") else "_") + name
_TYPE = r"(?:float|half|fixed|int|uint|bool|min16float)(?:[1-4](?:x[1-4])?)?"
# a global's declaration at brace depth 0: qualifier (1), type (2), names (3); not static, const
_DECLARATION = r"^[ \t]*(uniform[ \t]+)?({type})[ \t]+(\w+(?:[ \t]*,[ \t]*\w+)*|\w+[ \t]*=[^;{{}}]*)[ \t]*;"
_DECLARED = re.compile(_DECLARATION.format(type=_TYPE), re.M)
# a program's own name for a type (``#define vec2 float2``: a ShaderToy port's, yunyufeiwei's fog.shader)
_TYPE_ALIAS = re.compile(r"^[ \t]*#[ \t]*define[ \t]+(\w+)[ \t]+" + _TYPE + r"[ \t]*$", re.M)


def _declarations(active_program: str) -> re.Pattern:
    """_DECLARED, with the type names ``active_program`` #defines to a numeric type besides."""
    aliases = sorted(set(_TYPE_ALIAS.findall(active_program)))
    if not aliases:
        return _DECLARED
    return re.compile(_DECLARATION.format(type="|".join([_TYPE, *map(re.escape, aliases)])), re.M)
# a function body: the brace after a parameter list (and an optional ": SEMANTIC")
_BODY_OPEN = re.compile(r"\)\s*(?::\s*\w+\s*)?\{")


def _declared_names(names: str) -> list:
    """The names of _DECLARED's third group: ``a, b`` or one ``name = initialiser`` (whose
    commas, ``float3(0, 0, 0)``, are the initialiser's)."""
    return [names.split("=")[0].strip()] if "=" in names else [n.strip() for n in names.split(",")]


def _function_bodies(active: str) -> list:
    out, depth, start = [], 0, None
    for i, ch in enumerate(active):
        if ch == "{":
            if depth == 0:
                head = active[max(0, i - 300):i + 1]
                m = None
                for m in _BODY_OPEN.finditer(head):
                    pass
                start = i + 1 if m is not None and m.end() == len(head) else None
            depth += 1
        elif ch == "}":
            depth -= 1
            if depth == 0 and start is not None:
                out.append((start, i))
                start = None
    return out


def _written(name: str, body: str, program: str = "") -> bool:
    """Whether ``body`` assigns to ``name`` (=, op=, ++, --; a member or element of it too), or
    passes it to an ``out`` or ``inout`` parameter (``DiffuseAndSpecularFromMetallic(a, m, spec,
    oneMinusReflectivity)``) of a function of ``program`` (the active text holding ``body``) or
    of the library the port includes (cg_types.library)."""
    target = rf"(?<![\w.])\b{re.escape(name)}\b(?:\s*\.\s*\w+|\s*\[[^\]]*\])*"
    if re.search(target + r"\s*(?:[-+*/%&|^]|<<|>>)?=(?!=)", body) is not None or \
            re.search(rf"(?:\+\+|--)\s*{target}|{target}\s*(?:\+\+|--)", body) is not None:
        return True
    for call in re.finditer(rf"\b([A-Za-z_]\w*)\s*\((?=(?:[^()]*,)?\s*{target}\s*[,)])", body):
        found = call_arguments(body, call.end() - 1)
        if found is None:
            continue
        whole = [i for i, a in enumerate(found[0]) if re.fullmatch(r"\s*" + target + r"\s*", a)]
        if set(whole) & _out_positions(call.group(1), len(found[0]), program):
            return True
    return False


def _out_positions(function: str, count: int, program: str) -> set:
    """The argument positions an ``out`` or ``inout`` parameter takes in any ``count``-parameter
    definition of ``function`` in ``program`` or the port's library."""
    out = {i for sig in library().functions.get(function, ()) if len(sig.params) == count
           for i, p in enumerate(sig.params) if p.qual in ("out", "inout")}
    for m in re.finditer(rf"\b{re.escape(function)}\s*\(([^()]*)\)\s*(?::\s*\w+\s*)?\{{", program):
        params = m.group(1).split(",")
        if len(params) == count:
            out |= {i for i, p in enumerate(params) if re.match(r"\s*(?:out|inout)\b", p)}
    return out


def copied_written_globals(program: str, active_program: str) -> tuple[str, tuple]:
    """(``program`` with each global it writes read and written through its ``static`` copy in
    its functions, the copy declared before the global, on its line; ((name, type), ...) so copied).
    ``active_program``: ``program`` with comments and undrawn branches blanked (same offsets)."""
    top = _outside_braces(active_program)
    bodies = _function_bodies(active_program)
    found = []
    for m in _declarations(active_program).finditer(top):
        if re.match(r"\s*(?:static|const)\b", m.group(0)):
            continue
        for name in _declared_names(m.group(3)):
            if any(_written(name, active_program[s:e], active_program) for s, e in bodies):
                found.append((m, name, m.group(2)))
    if not found:
        return program, ()
    return _copied(program, active_program, found, bodies), tuple((name, kind) for _, name, kind in found)


def _copied(program: str, active_program: str, found: list, bodies: list, declare: bool = True) -> str:
    """``program`` with each found global's uses in ``bodies`` read through its copy, and (with
    ``declare``) the copies declared before the globals (copied_written_globals)."""
    text = program
    edits = []  # (start, end, replacement), applied from the end
    for s, e in bodies:
        for _, name, _ in found:
            for use in re.finditer(rf"(?<![\w.])\b{re.escape(name)}\b", active_program[s:e]):
                edits.append((s + use.start(), s + use.end(), copy_name(name)))
    by_declaration = {}
    for m, name, kind in found if declare else ():
        by_declaration.setdefault((m.start(), kind), []).append(copy_name(name))
    for (start, kind), copies in by_declaration.items():  # at the line's start, one declaration:
        edits.append((start, start, f"static {kind} {', '.join(copies)}; "))  # the GLSL port reads it there
    for start, end, replacement in sorted(edits, key=lambda x: (x[0], x[1]), reverse=True):
        text = text[:start] + replacement + text[end:]
    return text


def copy_statements(written) -> str:
    """An entry point's statements that give each copy its uniform's value."""
    return "".join(f"    {copy_name(name)} = {name};\n" for name, _ in written)


def copied_in_includes(program: str, folder: Path, defines) -> tuple[dict, tuple]:
    """({resolved path: its text rewritten by copied_written_globals}, ((name, type), ...)) of
    the shader's own files ``program`` includes (pbrlab's stand-ins write no global) that
    declare a global and write it; ``defines``: the drawn variant's (conditionals.defines_of)."""
    rewritten, written = {}, ()
    stand_ins = (CGINC.resolve(), PACKAGE_STAND_INS.resolve())
    for path in included_files(program, folder):
        if any(path.is_relative_to(root) for root in stand_ins):
            continue
        text = _read_include(path)
        if text is None:
            continue
        copied, found = copied_written_globals(text, active_text(blank_comments(text), defines))
        if found:
            rewritten[path], written = copied, written + found
    return rewritten, written


def copied_across_includes(program: str, folder: Path, defines, rewritten: dict, known=()) -> tuple:
    """(``program`` with a copy of each global it declares that one of its own include files
    writes, ``rewritten`` with those files' functions reading and writing the copy, ((name,
    type), ...)); ``known``: the globals copied already (copied_written_globals and
    copied_in_includes)."""
    active_program = active_text(blank_comments(program), defines)
    top = _outside_braces(active_program)
    declared = []
    for m in _declarations(active_program).finditer(top):
        if re.match(r"\s*(?:static|const)\b", m.group(0)):
            continue
        declared += [(m, name, m.group(2)) for name in _declared_names(m.group(3))
                     if name not in {k for k, _ in known}]
    stand_ins = (CGINC.resolve(), PACKAGE_STAND_INS.resolve())
    files = []  # (path, text, its active text, its function bodies)
    for path in included_files(program, folder) if declared else ():
        if any(path.is_relative_to(root) for root in stand_ins):
            continue
        text = rewritten.get(path) or _read_include(path)
        if text is not None:
            active = active_text(blank_comments(text), defines)
            files.append((path, text, active, _function_bodies(active)))
    found = [d for d in declared
             if any(_written(d[1], active[s:e], active) for _, _, active, bodies in files for s, e in bodies)]
    if not found:
        return program, rewritten, ()
    out = dict(rewritten)
    for path, text, active, bodies in files:
        if any(re.search(rf"(?<![\w.])\b{re.escape(name)}\b", active[s:e]) for _, name, _ in found for s, e in bodies):
            out[path] = _copied(text, active, [(None, name, kind) for _, name, kind in found], bodies, declare=False)
    return _copied(program, active_program, found, _function_bodies(active_program)), out, \
        tuple((name, kind) for _, name, kind in found)
