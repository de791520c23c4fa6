"""ShaderLab's ``Stencil { ... }`` command, read into the stencil state its pass draws with
(``gpu.stencil_state.StencilState``).

    state.stencil = read_stencil(command, props, path, warnings)

Unity's manual, "Stencil command in ShaderLab reference": every parameter is optional;
``Ref``, ``ReadMask``, ``WriteMask`` are 0..255 integers (defaults 0, 255, 255); ``Comp``
(default Always), ``Pass``, ``Fail``, ``ZFail`` (default Keep) apply to every pixel, front- or
back-facing, and ``CompFront``/``PassFront``/... and ``CompBack``/``PassBack``/... set one
facing's, whatever their order in the block. A value is a number, a name (the comparisons
Never, Less, Equal, LEqual, Greater, NotEqual, GEqual, Always; the operations Keep, Zero,
Replace, IncrSat, DecrSat, Invert, IncrWrap, DecrWrap; ShaderLab's names are
case-insensitive), or ``[_Property]``: the material's value, read as Unity's enums number them
(scripting reference, Rendering.CompareFunction: Disabled 0, Never 1, Less 2, Equal 3,
LessEqual 4, Greater 5, NotEqual 6, GreaterEqual 7, Always 8; Rendering.StencilOp: Keep 0,
Zero 1, Replace 2, IncrementSaturate 3, DecrementSaturate 4, Invert 5, IncrementWrap 6,
DecrementWrap 7). The enums' own names are taken as words too (LessEqual, IncrementSaturate).
A comparison of Disabled ("the stencil test is disabled") leaves that facing's pixels
untested and unwritten; with both facings disabled the pass draws with the test off.

The test: ``(Ref & ReadMask) Comp (stencil & ReadMask)``, the writes through ``WriteMask``:
OpenGL's, one to one (stencil_state.py). A parameter Unity would not read (an unknown word, a
value out of range, a missing value) is a ``UnityShaderError`` naming the file and line.
"""

from __future__ import annotations

import re
from pathlib import Path

from ...gpu.stencil_state import ALL_BITS, StencilFace, StencilState
from .source_text import UnityShaderError

_COMPARE_ENUM = ("disabled", "never", "less", "equal", "lequal", "greater", "notequal", "gequal", "always")
_COMPARE_WORDS = {**{name: name for name in _COMPARE_ENUM},
                  "lessequal": "lequal", "greaterequal": "gequal"}
_OPERATION_ENUM = ("keep", "zero", "replace", "incr", "decr", "invert", "incr_wrap", "decr_wrap")
_OPERATION_WORDS = {"keep": "keep", "zero": "zero", "replace": "replace", "incrsat": "incr", "decrsat": "decr",
                    "invert": "invert", "incrwrap": "incr_wrap", "decrwrap": "decr_wrap",
                    "incrementsaturate": "incr", "decrementsaturate": "decr", "incrementwrap": "incr_wrap",
                    "decrementwrap": "decr_wrap"}
_NUMBERS = {"ref": "ref", "readmask": "read_mask", "writemask": "write_mask"}
# a facing's parameters: ShaderLab's word -> StencilFace's field
_FACE_FIELDS = {"comp": "compare", "pass": "pass_op", "fail": "fail_op", "zfail": "depth_fail_op"}
_FACINGS = ("", "front", "back")
_PARAMETERS = "Ref, ReadMask, WriteMask, Comp, Pass, Fail, ZFail (and Comp/Pass/Fail/ZFail + Front or Back)"
_TOKEN = re.compile(r"\[\s*\w+\s*\]|[^\s\[\]]+|\S")


def _property_value(word: str, props: dict, where: str, warnings: list, key: str):
    """The integer a ``[_Property]`` holds, or None for a global the engine sets (warned)."""
    name = word.strip("[] ")
    prop = props.get(name)
    if prop is None:
        warnings.append(f"{where}: Stencil {key} {word}: set by the engine at run time, not by a property; "
                        f"the default {key} stands")
        return None
    if prop.is_texture or isinstance(prop.default, tuple):
        raise UnityShaderError(f"{where}: Stencil {key} {word} names no Float/Int/Range property")
    return int(prop.default)


def _value(written: str, word: str, props: dict, where: str, warnings: list):
    """The value ``word`` of the parameter ``written`` (as the block spells it): an int for
    Ref/ReadMask/WriteMask, a stencil_state name for the others ("disabled" for
    CompareFunction.Disabled), None where the default stands."""
    key = written.lower()
    kind = _NUMBERS.get(key) or _FACE_FIELDS[key.removesuffix("front").removesuffix("back")]
    names, enum = ((_COMPARE_WORDS, _COMPARE_ENUM) if kind == "compare" else
                   (None, None) if kind in _NUMBERS.values() else (_OPERATION_WORDS, _OPERATION_ENUM))
    if word.startswith("["):
        number = _property_value(word, props, where, warnings, written)
        if number is None:
            return None
    elif word.isdigit():
        number = int(word)
    elif names is not None and word.lower() in names:
        return names[word.lower()]
    else:
        expected = ("a number 0..255 or [_Property]" if names is None else
                    f"one of {', '.join(sorted(set(names) - {'disabled'}))}, a number or [_Property]")
        raise UnityShaderError(f"{where}: Stencil {written} {word}: expected {expected}")
    if enum is None:
        if not 0 <= number <= ALL_BITS:
            raise UnityShaderError(f"{where}: Stencil {written} {word} = {number}: the stencil buffer holds 8 bits "
                                   f"(0..{ALL_BITS})")
        return number
    if not 0 <= number < len(enum):
        raise UnityShaderError(f"{where}: Stencil {written} {word} = {number} is outside the enum's 0..{len(enum) - 1}")
    return enum[number]


def read_stencil(command, props: dict, path: Path, warnings: list) -> StencilState | None:
    """The state of a ``Stencil { ... }`` command (``shaderlab.StateCommand``); None where both
    facings' comparison is Disabled (the test off)."""
    if not command.body_line:
        raise UnityShaderError(f"{path}:{command.line}: Stencil {command.args}: expected a block, "
                               "Stencil { Ref 1 Comp Equal ... }")
    numbers = {"ref": 0, "read_mask": ALL_BITS, "write_mask": ALL_BITS}
    faces = {facing: {} for facing in _FACINGS}  # facing -> {field: value}, as written
    tokens = [(m.group(0), command.body_line + command.body.count("\n", 0, m.start()))
              for m in _TOKEN.finditer(command.body)]
    for index in range(0, len(tokens), 2):
        word, line = tokens[index]
        where = f"{path}:{line}"
        key = word.lower()
        facing = next((f for f in ("front", "back") if key.endswith(f) and key[:-len(f)] in _FACE_FIELDS), "")
        if key not in _NUMBERS and key[:len(key) - len(facing)] not in _FACE_FIELDS:
            raise UnityShaderError(f"{where}: Stencil: {word!r} is not a Stencil parameter (expected {_PARAMETERS})")
        if index + 1 >= len(tokens):
            raise UnityShaderError(f"{where}: Stencil {word}: no value before the block's '}}'")
        value = _value(word, tokens[index + 1][0], props, f"{path}:{tokens[index + 1][1]}", warnings)
        if value is None:
            continue
        if key in _NUMBERS:
            numbers[_NUMBERS[key]] = value
        else:
            faces[facing][_FACE_FIELDS[key[:len(key) - len(facing)]]] = value
    sides, disabled = [], []
    for facing in ("front", "back"):
        fields = {**faces[""], **faces[facing]}  # a facing's own words over the shared ones
        off = fields.get("compare") == "disabled"  # that facing untested: it passes, writes nothing
        disabled.append(off)
        sides.append(StencilFace() if off else StencilFace(**fields))
    if all(disabled):
        return None
    return StencilState(ref=numbers["ref"], read_mask=numbers["read_mask"], write_mask=numbers["write_mask"],
                        front=sides[0], back=sides[1])


# What a pass's test gives where the stencil holds 0 (the frame's clear): (ref & read_mask) c 0.
_PASSES_ON_ZERO = {"never": lambda r: False, "less": lambda r: False, "equal": lambda r: r == 0,
                   "lequal": lambda r: r == 0, "greater": lambda r: r > 0, "notequal": lambda r: r != 0,
                   "gequal": lambda r: True, "always": lambda r: True}


def draws_nothing_alone(states: list) -> bool:
    """Whether passes of these render states (``model.RenderState``, in draw order), drawing one
    object on a stencil buffer cleared to 0, leave no colour because of their Stencil blocks: every
    pass that writes colour has a test that fails on 0 (for both facings), and no pass changes
    the stencil first (a failing test's Fail operation keeps it; a pass without a block writes
    none). Such a shader draws where a mask of another object's writes its Ref: alone, Unity's
    image of it is empty too."""
    tested = False
    for state in states:
        colour = state.color_mask.strip() != "0"
        stencil = state.stencil
        if stencil is None:
            if colour:
                return False
            continue
        reference = stencil.ref & stencil.read_mask
        for face in (stencil.front, stencil.back):
            if _PASSES_ON_ZERO[face.compare](reference):
                return False  # it draws, or writes the stencil for the passes after it
            if face.fail_op != "keep" and stencil.write_mask:
                return False
        tested = tested or colour
    return tested
