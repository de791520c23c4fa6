"""HLSL's geometry-shader syntax as a Unity program writes it, read without compiling:

    g = parse_geometry(text, "geom", where, offset)   # the function's signature (parse_pass: vf.geometry)
    text = spell_for_glsl(text)                        # the syntax in Cg the GLSL port reads (port.port_text)

``spell_for_glsl`` drops the ``[maxvertexcount]`` attribute, the primitive word (``triangle``)
and the stream parameter, and spells ``stream.Append(x)`` as ``PBRLAB_GEOMETRY_APPEND(x)`` and
``stream.RestartStrip()`` as ``PBRLAB_GEOMETRY_RESTART()``, line for line; a function taking the
stream loses that parameter and a call handing it on that argument. What the stage then does
with them, in both languages: geometry_stage.py.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from .source_text import IDENT, UnityShaderError, blank_comments, matching_brace

# HLSL's geometry input primitives and the GLSL layout each one is (GLSL 3.30, 4.3.8.1:
# points, lines, lines_adjacency, triangles, triangles_adjacency), with its vertex count.
PRIMITIVES = {"point": ("points", 1), "line": ("lines", 2), "lineadj": ("lines_adjacency", 4),
              "triangle": ("triangles", 3), "triangleadj": ("triangles_adjacency", 6)}
# HLSL's stream objects and the GLSL output layout each one writes.
STREAMS = {"PointStream": "points", "LineStream": "line_strip", "TriangleStream": "triangle_strip"}

_MAX_VERTEX_COUNT = re.compile(r"\[\s*maxvertexcount\s*\(((?:[^()]|\([^()]*\))*)\)\s*\]")
_PRIMITIVE_WORD = re.compile(r"\b(" + "|".join(PRIMITIVES) + r")\s+(?=" + IDENT + r"\s+" + IDENT + r"\s*\[)")
_STREAM_PARAM = re.compile(r"\binout\s+(" + "|".join(STREAMS) + r")\s*<\s*(" + IDENT + r")\s*>\s*(" + IDENT + r")")
_POSITION = ("SV_POSITION", "POSITION")


@dataclass
class GeometryFunction:
    name: str
    max_vertices: str            # the [maxvertexcount(...)] expression, as written
    primitive: str               # point, line, lineadj, triangle, triangleadj
    input_type: str              # the struct of one input vertex
    input_name: str
    output_type: str             # the stream's vertex struct
    stream: str                  # TriangleStream, LineStream, PointStream
    stream_name: str
    params: list                 # [(role, text as written, name)]: role input, stream, primitive_id
    where: str
    input_semantic: str = ""     # the input array's own semantic (a bare value per vertex: float4 IN[3] : SV_POSITION)


def _blank(text: str) -> str:
    """``text`` as spaces, its line breaks kept."""
    return re.sub(r"[^\n]", " ", text)


# A function whose parameters include a stream: its name, its parameter list, its body's "{".
_STREAM_FUNCTION = re.compile(r"\b" + IDENT + r"\s*\(([^()]*\binout\s+(?:" + "|".join(STREAMS) + r")\s*<[^()]*)\)"
                              r"\s*(?::\s*\w+\s*)?\{")


def _lines_only(m) -> str:
    return "\n" * m.group(0).count("\n")


def _stream_body(body: str, name: str) -> str:
    """A body of a function taking the stream ``name``: its Append and RestartStrip spelled,
    the stream dropped where it is handed on as an argument (line breaks kept)."""
    body = re.sub(r"\b" + name + r"\s*\.\s*Append\s*\(", "PBRLAB_GEOMETRY_APPEND(", body)
    body = re.sub(r"\b" + name + r"\s*\.\s*RestartStrip\s*\(\s*\)", "PBRLAB_GEOMETRY_RESTART()", body)
    body = re.sub(r"(?<=\()\s*" + name + r"\s*,\s*", _lines_only, body)
    body = re.sub(r"\s*,\s*" + name + r"\s*(?=[,)])", _lines_only, body)
    return re.sub(r"(?<=\()\s*" + name + r"\s*(?=\))", _lines_only, body)


def spell_for_glsl(text: str) -> str:
    """The geometry syntax of HLSL in ``text`` spelled in Cg for the GLSL port (module
    docstring), line for line, in each function that takes a stream; a text without it
    unchanged."""
    if "Stream" not in text and "maxvertexcount" not in text:
        return text
    text = _MAX_VERTEX_COUNT.sub(lambda m: _blank(m.group(0)), text)
    text = _PRIMITIVE_WORD.sub(lambda m: _blank(m.group(0)), text)
    masked = blank_comments(text)
    for m in reversed(list(_STREAM_FUNCTION.finditer(masked))):
        end = matching_brace(masked, m.end() - 1)
        if end is None:
            continue
        params = text[m.start(1):m.end(1)]
        names = [p.group(3) for p in _STREAM_PARAM.finditer(params)]
        # the stream parameter with the comma before it (or after it, when it comes first)
        params = re.sub(r",\s*" + _STREAM_PARAM.pattern, _lines_only, params)
        params = re.sub(_STREAM_PARAM.pattern + r"\s*,?", _lines_only, params)
        body = text[m.end():end]
        for name in names:
            body = _stream_body(body, name)
        text = text[:m.start(1)] + params + text[m.end(1):m.end()] + body + text[end:]
    return text


def _split_params(text: str) -> list[str]:
    out, depth, cur = [], 0, []
    for ch in text:
        if ch == "," and depth == 0:
            out.append("".join(cur).strip())
            cur = []
            continue
        depth += {"(": 1, ")": -1, "<": 1, ">": -1}.get(ch, 0)
        cur.append(ch)
    out.append("".join(cur).strip())
    return [p for p in out if p and p != "void"]


def parse_geometry(masked: str, name: str, where_of, pragma_offset: int) -> GeometryFunction:
    """The geometry function ``name`` of ``masked`` (the program and its includes, comments
    blanked, the drawn variant's branches); ``where_of(offset)`` names a place in the program."""
    where = where_of(pragma_offset)
    # (the attribute may be chosen by #if lines: `#ifdef _SUBDIVIDE [maxvertexcount(12)] #else
    # [maxvertexcount(3)] #endif void geom(...)`, the inactive branch already blanked)
    m = re.search(r"(" + _MAX_VERTEX_COUNT.pattern + r")?(?:\s|#[^\n]*)*+\bvoid\s+" + re.escape(name) + r"\s*\(",
                  masked)
    if m is None:
        raise UnityShaderError(f"{where}: #pragma geometry {name}: no function void {name}(...) is defined")
    if m.group(1) is None:
        raise UnityShaderError(f"{where}: #pragma geometry {name}: {name}() has no [maxvertexcount(N)] "
                               "attribute (HLSL requires one on a geometry function)")
    depth, i = 1, m.end()
    while i < len(masked) and depth:
        depth += {"(": 1, ")": -1}.get(masked[i], 0)
        i += 1
    params, found = [], {}
    for text in _split_params(masked[m.end():i - 1]):
        stream = _STREAM_PARAM.search(text)
        array = re.match(r"(?:(" + "|".join(PRIMITIVES) + r")\s+)(" + IDENT + r")\s+(" + IDENT + r")\s*\[\s*(\w+)\s*\](?:\s*:\s*(\w+))?", text)
        primitive_id = re.match(r"(?:in\s+)?(uint|int)\s+(" + IDENT + r")\s*:\s*SV_PrimitiveID\s*$", text, re.I)
        if stream:
            found["stream"] = stream.groups()
            params.append(("stream", text, stream.group(3)))
        elif array:
            if "input" in found:  # HLSL takes several per-vertex arrays; pbrlab one struct array
                raise UnityShaderError(f"{where}: {name}() takes its vertices as several arrays ({found['input'][2]}[], "
                                       f"{array.group(3)}[]): pbrlab runs a geometry function whose vertices come "
                                       "as one array of the vertex stage's output struct (triangle v2g IN[3])")
            found["input"] = array.groups()[:4]
            found["semantic"] = array.group(5) or ""
            params.append(("input", text, array.group(3)))
        elif primitive_id:
            params.append(("primitive_id", text, primitive_id.group(2)))
        else:
            raise UnityShaderError(f"{where}: {name}(): the parameter {text!r} is not one pbrlab runs "
                                   "(an input array such as triangle v2g IN[3], an inout TriangleStream<T>, "
                                   "a uint : SV_PrimitiveID)")
    if "input" not in found or "stream" not in found:
        raise UnityShaderError(f"{where}: {name}() needs an input array (triangle v2g IN[3]) and an "
                               "inout stream (TriangleStream<g2f>)")
    primitive, input_type, input_name, count = found["input"]
    if primitive not in ("triangle", "point"):
        # the harness draws triangles: a line geometry input would never be fed (a point input is
        # given each triangle's first vertex, as D3D11 drivers do: geometry_stage.py)
        raise UnityShaderError(f"{where}: {name}() takes {primitive} input: pbrlab draws triangle meshes, "
                               "so only a triangle or point geometry input is fed")
    if primitive == "point" and count != "1":
        raise UnityShaderError(f"{where}: {name}(): point {input_type} {input_name}[{count}]: a point input "
                               "array holds 1 vertex")
    return GeometryFunction(name=name, max_vertices=m.group(2).strip(), primitive=primitive,
                            input_type=input_type, input_name=input_name, output_type=found["stream"][1],
                            stream=found["stream"][0], stream_name=found["stream"][2], params=params,
                            where=where, input_semantic=found["semantic"])
