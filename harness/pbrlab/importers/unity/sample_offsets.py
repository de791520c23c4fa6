"""A texture lookup's offset that is a parameter of the function it sits in, given a constant by
each call (HengyuanLee's BilateralBlur: ``float4 BilateralBlur(..., int2 delta, Texture2D depth,
...) { ... depth.Sample(s, uv, delta * -1) ... }`` called as ``BilateralBlur(IN, int2(1, 0),
...)``): HLSL asks the offset of Sample, SampleLevel, SampleBias, SampleGrad, SampleCmp(LevelZero)
and Load to be an immediate (Microsoft's HLSL reference, "Sample (DirectX HLSL Texture Object)":
"offset ... must be an immediate"), which FXC checks after it has inlined every function (FXC
inlines all calls), so a constant passed down is one. glslang keeps the function and its
parameter, and GLSL's textureOffset refuses a parameter ("must be a constant expression").

Spelled as FXC reads it: the function is specialised per distinct constant its calls pass for the
parameter. Each specialisation drops the parameter from its signature and declares it a ``static
const`` of its type with the call's constant at the body's start (both languages fold it into the
lookup's offset); each call calls its specialisation, without the argument. Only where every call
passes a constant (an integer literal or an int vector's constructor of literals) for every such
parameter; otherwise the text is left as written and the compilers name it. Lines are kept: the
first specialisation is the function where it stands, any further one is appended to its closing
brace's line (its comments blanked, its line breaks spaces; a body with a preprocessor line is
left as written).

    text = specialised_offsets(text)
"""

from __future__ import annotations

import re

from .source_text import blank_comments, call_arguments, matching_brace, matching_paren

# (a method and the index of its offset argument)
_OFFSET_INDEX = {"Sample": 2, "SampleLevel": 3, "SampleBias": 3, "SampleGrad": 4, "SampleCmp": 3,
                 "SampleCmpLevelZero": 3, "Load": 1}
_METHOD = re.compile(r"\.\s*(" + "|".join(_OFFSET_INDEX) + r")\s*\(")
_FUNCTION = re.compile(r"\b([A-Za-z_]\w*)\s+([A-Za-z_]\w*)\s*\(")
_CONSTANT = re.compile(r"\s*(?:[-+]?\s*\d+[uU]?|(?:u?int[234]?)\s*\(\s*[-+]?\s*\d+[uU]?\s*(?:,\s*[-+]?\s*\d+[uU]?\s*)*\))\s*")
_PARAMETER = re.compile(r"^\s*(?:in\s+|uniform\s+)?([A-Za-z_]\w*)\s+([A-Za-z_]\w*)\s*$")
_KEYWORDS = {"return", "else", "if", "for", "while", "switch", "do", "case"}


def _definitions(masked: str):
    """(name, its offset, '(' offset, ')' offset, '{' offset, '}' offset) of each function defined
    in ``masked``."""
    for m in _FUNCTION.finditer(masked):
        if m.group(1) in _KEYWORDS:
            continue
        close = matching_paren(masked, m.end() - 1)
        if close < 0:
            continue
        head = re.match(r"\s*(?::\s*\w+\s*)?\{", masked[close + 1:])  # an optional return semantic
        if head is None:
            continue
        open_brace = close + head.end()
        end = matching_brace(masked, open_brace)
        if end > 0:
            yield m.group(2), m.start(2), m.end() - 1, close, open_brace, end


def _offset_parameters(body: str, names: list) -> set:
    """The indices of ``names`` (the parameters) that an offset argument in ``body`` reads."""
    found = set()
    for m in _METHOD.finditer(body):
        found_args = call_arguments(body, m.end() - 1)
        if found_args is None:
            continue
        args = found_args[0]
        index = _OFFSET_INDEX[m.group(1)]
        if index < len(args):
            found |= {i for i, n in enumerate(names) if re.search(rf"\b{n}\b", args[index])}
    return found


def _calls(masked: str, name: str, definition: tuple):
    """(start, '(' offset, arguments, end) of each call of ``name`` outside its definition."""
    out = []
    for m in re.finditer(rf"\b{name}\s*\(", masked):
        if definition[0] <= m.end() - 1 <= definition[1] or re.search(r"\w\s+$", masked[:m.start()]) and \
                not re.search(r"\b(?:return|else)\s+$", masked[:m.start()]):
            continue  # the definition, or a prototype (a type before the name)
        found = call_arguments(masked, m.end() - 1)
        if found is None:
            return None
        out.append((m.start(), m.end() - 1, found[0], found[1]))
    return out


def _specialise(text: str) -> str | None:
    """``text`` with the first function that needs it specialised (module doc); None if none does."""
    masked = blank_comments(text)
    for name, head_start, open_paren, close_paren, open_brace, close_brace in _definitions(masked):
        parameters = masked[open_paren + 1:close_paren].split(",")
        parsed = [_PARAMETER.match(p) for p in parameters]
        if not all(parsed):
            continue
        names = [p.group(2) for p in parsed]
        offsets = sorted(_offset_parameters(masked[open_brace:close_brace], names))
        if not offsets:
            continue
        calls = _calls(masked, name, (open_paren, close_paren))
        if not calls or any(len(args) != len(names) or not all(_CONSTANT.fullmatch(args[i]) for i in offsets)
                            for _, _, args, _ in calls):
            continue
        keys = []
        for _, _, args, _ in calls:
            key = tuple(re.sub(r"\s+", "", args[i]) for i in offsets)
            if key not in keys:
                keys.append(key)
        body = text[open_brace + 1:close_brace]
        if len(keys) > 1 and re.search(r"^[ \t]*#", body, re.M):
            continue
        kept = [p for i, p in enumerate(parameters) if i not in offsets]
        dropped_lines = sum(p.count("\n") for i, p in enumerate(parameters) if i in offsets)

        return_type = re.search(r"(\w+)\s*$", masked[:head_start]).group(1)
        semantic = text[close_paren + 1:open_brace]

        def clone(k: int, one_line: bool) -> str:
            constants = " ".join(f"static const {parsed[i].group(1)} {names[i]} = {keys[k][j]};"
                                 for j, i in enumerate(offsets))
            signature = ",".join(kept)
            if one_line:
                flat = blank_comments(f"{signature}){semantic}{{ {constants}{body}}}").replace("\n", " ")
                return f" {return_type} {name}_pbrlab_offset{k}({flat}"
            return f"{name}_pbrlab_offset{k}({signature}{chr(10) * dropped_lines}){semantic}{{ {constants}{body}}}"

        # the calls, last first (offsets stay valid), each to its specialisation without the arguments
        out = text
        extra = "".join(clone(k, True) for k in range(1, len(keys)))
        pieces = [(head_start, close_brace + 1, clone(0, False) + extra)]
        for start, _, args, end in calls:
            key = tuple(re.sub(r"\s+", "", args[i]) for i in offsets)
            rest = [a for i, a in enumerate(args) if i not in offsets]
            call = f"{name}_pbrlab_offset{keys.index(key)}(" + ",".join(rest) + ")"
            call += "\n" * (text.count("\n", start, end) - call.count("\n"))
            pieces.append((start, end, call))
        for start, end, spelled in sorted(pieces, reverse=True):
            out = out[:start] + spelled + out[end:]
        return out
    return None


def _reads_a_named_offset(text: str) -> bool:
    """Whether a lookup in ``text`` passes an offset that names something (not literals only):
    the cheap test before the functions are read (most programs pass none)."""
    for m in _METHOD.finditer(text):
        found = call_arguments(text, m.end() - 1)
        index = _OFFSET_INDEX[m.group(1)]
        if found is not None and index < len(found[0]) and re.search(r"[A-Za-z_]", re.sub(
                r"\b(?:u?int[234]?)\s*\(", "(", found[0][index])):
            return True
    return False


def specialised_offsets(text: str) -> str:
    """``text`` with each function whose lookup offset is a parameter specialised per constant
    its calls pass (module doc)."""
    if not _reads_a_named_offset(text):
        return text
    for _ in range(32):  # one function a round; a program has few
        spelled = _specialise(text)
        if spelled is None:
            return text
        text = spelled
    return text
