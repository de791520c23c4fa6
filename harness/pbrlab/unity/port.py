"""``pbrlab port-unity``: the mechanical renames that turn a surface shader's CGPROGRAM into
GLSL the harness's GLSL path compiles (types, constructors, global uniforms, scalar-to-vector
assignments); the Cg intrinsics (saturate, lerp, tex2D, ...) are not renamed, they come from
``unity_compat/cg_compat.glsl``.

    text = port_program(shader)        # from a parsed model.SurfaceShader

Rules, applied to code only (comments and strings untouched):
  1. Types: (float|half|fixed|min16float)N -> vecN, ...NxN -> matN, scalar half/fixed ->
     float, intN -> ivecN, boolN -> bvecN, uintN -> uvecN.
  2. HLSL-only words: ``inline`` and ``static`` (before const) dropped; ``uniform`` added to
     the shader's global variable declarations (Unity's globals are uniforms).
  3. Assignments and initialisations whose target has a known vector type (locals declared
     in the function, output-struct fields such as ``o.Albedo``) wrap the value in that type's
     constructor, which splats a scalar (``o.Albedo = 1`` -> ``o.Albedo = vec3(1)``) and keeps
     a vector; ``return x;`` in a function returning a vector likewise.
  4. Casts ``(float3)x`` -> ``vec3(x)``.
  5. HLSL semantics after a member or parameter (``float4 color : COLOR;``) dropped.
  6. ``pow`` -> ``pbr_unity_pow`` (cg_compat.glsl: HLSL's pow(float3, 2.2) promotes the
     scalar; GLSL neither has that overload nor lets a shader overload a built-in).
"""

from __future__ import annotations

import re

from . import model as M
from .parse import PORT_MARKER

_TYPE = re.compile(r"\b(?:float|half|fixed|min16float)([234])(?:x([234]))?\b")
_SCALAR = re.compile(r"\b(?:half|fixed|min16float)\b")
_INT = re.compile(r"\b(int|bool|uint)([234])\b")
# HLSL semantics (rule 5): the D3D9/10 names a surface shader's structs and parameters carry.
_SEMANTIC = re.compile(r"(\w)\s*:\s*(?:POSITION|NORMAL|TANGENT|BINORMAL|COLOR|TEXCOORD|BLENDWEIGHT|"
                       r"BLENDINDICES|PSIZE|FOG|DEPTH|VFACE|VPOS|SV_\w+?)\d*\s*(?=[;,)])")
_COMMENT_OR_STRING = re.compile(r'//[^\n]*|/\*.*?\*/|"[^"\n]*"', re.S)


def _rename_types(code: str) -> str:
    code = _TYPE.sub(lambda m: f"mat{m.group(1)}" + (f"x{m.group(2)}" if m.group(2) != m.group(1) else "")
                     if m.group(2) else f"vec{m.group(1)}", code)
    code = _SCALAR.sub("float", code)
    return _INT.sub(lambda m: {"int": "ivec", "bool": "bvec", "uint": "uvec"}[m.group(1)] + m.group(2), code)


def _code_segments(text: str):
    """[(is_code, text)] alternating code and comments/strings."""
    out, last = [], 0
    for m in _COMMENT_OR_STRING.finditer(text):
        out.append((True, text[last:m.start()]))
        out.append((False, m.group(0)))
        last = m.end()
    out.append((True, text[last:]))
    return out


def _globals_uniform(code: str) -> str:
    """``uniform`` before global variable declarations (brace depth 0, not functions/structs)."""
    lines, depth, out = code.split("\n"), 0, []
    decl = re.compile(r"^(\s*)((?:vec[234]|mat[234]|float|int|sampler2D|samplerCUBE|samplerCube|sampler3D)\s+\w+\s*(?:\[\s*\d+\s*\])?\s*;)")
    for line in lines:
        if depth == 0 and not line.lstrip().startswith("#"):
            m = decl.match(line)
            if m:
                line = f"{m.group(1)}uniform {m.group(2)}{line[m.end():]}"
        depth += line.count("{") - line.count("}")
        out.append(line)
    return "\n".join(out)


def _wrap_assignments(code: str, shader: M.SurfaceShader) -> str:
    """Rule 3: scalar-to-vector assignments through the target's constructor."""
    fields = {f: n for f, n in shader.output_fields.items() if n > 1}
    local = {}
    for m in re.finditer(r"\b(vec[234])\s+(\w+)\s*[=;,)]", code):
        local[m.group(2)] = m.group(1)

    def target_type(lhs: str):
        lhs = lhs.strip()
        fm = re.fullmatch(r"\w+\.(\w+)", lhs)
        if fm and fm.group(1) in fields:
            return f"vec{fields[fm.group(1)]}"
        if re.fullmatch(r"\w+", lhs) and lhs in local:
            return local[lhs]
        return None

    def assign(m):
        decl, lhs, rhs = m.group(1) or "", m.group(2), m.group(3)
        kind = decl.split()[0] if decl else target_type(lhs)
        if not kind or not kind.startswith("vec"):
            return m.group(0)
        return f"{decl}{lhs} = {kind}({rhs.strip()});"

    code = re.sub(r"(\b(?:vec[234])\s+)?(\b[\w.]+)\s*=(?!=)\s*([^;{}]+);", assign, code)
    # return <expr>; inside functions returning vectors
    out, pos = [], 0
    for fm in re.finditer(r"\b(vec[234])\s+\w+\s*\([^)]*\)\s*\{", code):
        start = fm.end()
        depth, i = 1, start
        while i < len(code) and depth:
            depth += {"{": 1, "}": -1}.get(code[i], 0)
            i += 1
        body = re.sub(r"\breturn\s+([^;]+);", lambda r: f"return {fm.group(1)}({r.group(1).strip()});",
                      code[start:i])
        out.append(code[pos:start] + body)
        pos = i
    out.append(code[pos:])
    return "".join(out)


def port_code_types(code: str) -> str:
    """Rule 1 alone (a type name, e.g. an Input member's)."""
    return _rename_types(code)


def port_code(code: str, shader: M.SurfaceShader) -> str:
    code = _rename_types(code)
    code = _SEMANTIC.sub(r"\1", code)
    code = re.sub(r"\)(\s*):\s*[A-Za-z_]\w*(\s*)(?=\{)", r")\1\2", code)  # a function's return semantic
    code = re.sub(r"\binline\s+", "", code)
    code = re.sub(r"\bpow\s*\(", "pbr_unity_pow(", code)
    code = re.sub(r"\bstatic\s+(?=const\b)", "", code)
    code = re.sub(r"\(\s*(vec[234]|float)\s*\)\s*(\w+(?:\.\w+)*)", r"\1(\2)", code)
    code = _globals_uniform(code)
    return _wrap_assignments(code, shader)


def port_program(shader: M.SurfaceShader) -> str:
    """The shader's CGPROGRAM with the renames, line for line (comments kept)."""
    return port_text(shader.program, shader)


def port_text(text: str, shader: M.SurfaceShader) -> str:
    """``text`` (the program, or a file it includes) with the renames, line for line."""
    segments = _code_segments(text)
    code = "".join(t if is_code else _placeholder(i) for i, (is_code, t) in enumerate(segments))
    code = port_code(code, shader)
    for i, (is_code, t) in enumerate(segments):
        if not is_code:
            code = code.replace(_placeholder(i), t, 1)
    return code


def _property_line(prop: M.Property) -> str:
    attrs = "".join(f"[{a}] " for a in prop.attributes)
    kind = f"Range({prop.range[0]:g}, {prop.range[1]:g})" if prop.kind == "Range" else prop.kind
    if prop.is_texture:
        default = f'"{prop.default}" {{}}'
    elif isinstance(prop.default, tuple):
        default = "(" + ", ".join(f"{x:g}" for x in prop.default) + ")"
    else:
        default = f"{prop.default:g}"
    return f'//@property {attrs}{prop.name} ("{prop.display}", {kind}) = {default}'


def port_file(shader: M.SurfaceShader) -> str:
    """The text ``pbrlab port-unity`` writes: a header, the Properties and pass state as
    ``//@property`` / ``//@state`` lines (the front end reads them back), and the renamed
    program. A material's ``surface`` may name it for the GLSL path."""
    lines = [f"{PORT_MARKER} GLSL port of {shader.path.name} (\"{shader.name}\"); regenerate with",
             f"//   pbrlab port-unity {shader.path.name} -o {shader.path.stem}.glsl",
             "// Needs unity_compat/cg_compat.glsl and the pbr/unity/ includes (the harness adds them).",
             *(_property_line(p) for p in shader.properties.values() if "implicit" not in p.attributes)]
    if shader.state.cull != "back":
        lines.append(f"//@state Cull {shader.state.cull.capitalize()}")
    if shader.state.zwrite is not None:
        lines.append(f"//@state ZWrite {'On' if shader.state.zwrite else 'Off'}")
    return "\n".join(lines) + "\n" + port_program(shader).strip("\n") + "\n"


def _placeholder(i: int) -> str:
    return f"__PBRLAB_KEEP_{i}__"
