"""Read a Unity surface shader: a ShaderLab ``.shader`` file (``Properties``, pass state,
one ``CGPROGRAM ... ENDCG`` block) or bare CGPROGRAM text, into a ``model.SurfaceShader``.

    shader = parse_file(Path("rim.shader"))

What the harness cannot honour is reported, never dropped: unknown ``#pragma surface``
options and ShaderLab state other than Cull/ZWrite/Blend become warnings on the model
(``shader.warnings``, raised as ``UnityShaderWarning`` by ``load_shader``); what would make
the render wrong (no ``#pragma surface``, a missing surface/vertex/final-colour/lighting
function, an Input member nothing fills) is a ``UnityShaderError`` naming file and line.
"""

from __future__ import annotations

import re
from pathlib import Path

from ..errors import PbrlabError
from . import model as M

PORT_MARKER = "// pbrlab port-unity:"  # port.py writes it first; the text is then GLSL


class UnityShaderError(PbrlabError):
    """A Unity shader the front end cannot run as Unity would; the message says where."""


# Options with no effect here: the harness has no shadows, lightmaps, deferred or
# prepass paths, fog, instancing or meta pass (README, "Unity surface shaders").
NO_EFFECT_OPTIONS = frozenset("""
    addshadow fullforwardshadows noshadow nolightmap nodirlightmap nodynlightmap
    noforwardadd nometa noinstancing nofog nolppv noshadowmask novertexlights
    keepalpha dualforward softvegetation nodynlightmap
""".split())
NO_EFFECT_PREFIXES = ("exclude_path:", "interpolateview", "halfasview", "approxview")
ALPHA_OPTIONS = {"alpha": "fade", "alpha:auto": "fade", "alpha:blend": "fade",
                 "alpha:fade": "fade", "alpha:premul": "transparent"}
PASS_STATE_HONOURED = ("Cull", "ZWrite", "Blend")
PASS_STATE_IGNORED = ("ZTest", "ColorMask", "Offset", "Stencil", "AlphaToMask", "BlendOp",
                      "Conservative", "ZClip")

_COMMENT = re.compile(r"//[^\n]*|/\*.*?\*/", re.S)
_IDENT = r"[A-Za-z_]\w*"


def _blank_comments(text: str) -> str:
    """Comments replaced by spaces, newlines kept (offsets and line numbers survive)."""
    return _COMMENT.sub(lambda m: re.sub(r"[^\n]", " ", m.group(0)), text)


def _line_of(text: str, index: int) -> int:
    return text.count("\n", 0, index) + 1


def _matching_brace(text: str, open_index: int) -> int:
    depth = 0
    for i in range(open_index, len(text)):
        if text[i] == "{":
            depth += 1
        elif text[i] == "}":
            depth -= 1
            if depth == 0:
                return i
    return -1


# --- ShaderLab --------------------------------------------------------------------------

_PROPERTY = re.compile(
    r'^\s*(?P<attrs>(?:\[[^\]]*\]\s*)*)(?P<name>' + _IDENT + r')\s*\(\s*"(?P<display>[^"]*)"\s*,\s*'
    r'(?P<kind>Range\s*\(\s*(?P<lo>[-+.\deE]+)\s*,\s*(?P<hi>[-+.\deE]+)\s*\)|\w+)\s*\)\s*=\s*(?P<default>.+?)\s*$')


def _number(text: str, where: str) -> float:
    try:
        return float(text)
    except ValueError:
        raise UnityShaderError(f"{where}: expected a number, got {text!r}") from None


def _property(line: str, where: str) -> M.Property:
    m = _PROPERTY.match(line)
    if not m:
        raise UnityShaderError(f"{where}: cannot read this Properties line: {line.strip()!r} "
                               '(expected _Name ("Label", Type) = default)')
    attrs = tuple(a.strip() for a in re.findall(r"\[([^\]]*)\]", m.group("attrs")))
    kind = m.group("kind")
    rng = None
    if kind.startswith("Range"):
        rng = (_number(m.group("lo"), where), _number(m.group("hi"), where))
        kind = "Range"
    default_text = m.group("default")
    kind = {"cube": "Cube", "2d": "2D", "3d": "3D"}.get(kind.lower(), kind)
    if kind in ("Float", "Range", "Int", "Integer"):
        default = _number(default_text, where)
        kind = "Int" if kind == "Integer" else kind
    elif kind in ("Color", "Vector"):
        v = re.fullmatch(r"\(\s*([^)]*)\)", default_text)
        parts = [p for p in v.group(1).split(",")] if v else []
        if len(parts) != 4:
            raise UnityShaderError(f"{where}: {kind} default must be (x, y, z, w), got {default_text!r}")
        default = tuple(_number(p.strip(), where) for p in parts)
    elif kind in ("2D", "Cube", "3D"):
        t = re.fullmatch(r'"(\w*)"\s*(\{\s*\})?', default_text)
        if not t:
            raise UnityShaderError(f'{where}: texture default must be "white", "black", "gray", '
                                   f'"bump" or "red" (with optional {{}}), got {default_text!r}')
        default = t.group(1) or "gray"
    else:
        raise UnityShaderError(f"{where}: property type {kind!r} is not one of Float, Range, Int, "
                               "Color, Vector, 2D, Cube, 3D")
    return M.Property(m.group("name"), m.group("display"), kind, default, attrs, rng)


def _properties(masked: str, text: str, path: Path) -> dict:
    m = re.search(r"\bProperties\s*\{", masked)
    if not m:
        return {}
    end = _matching_brace(masked, m.end() - 1)
    props = {}
    for offset, line in enumerate(text[m.end():end].split("\n")):
        clean = _blank_comments(line).strip()
        if not clean:
            continue
        where = f"{path}:{_line_of(text, m.end()) + offset}"
        prop = _property(clean, where)
        props[prop.name] = prop
    return props


def _pass_state(masked: str, program_span, path: Path, shader: M.SurfaceShader) -> None:
    outside = masked[:program_span[0]] + " " * (program_span[1] - program_span[0]) + masked[program_span[1]:]
    props = re.search(r"\bProperties\s*\{", outside)
    if props:
        end = _matching_brace(outside, props.end() - 1)
        outside = outside[:props.start()] + " " * (end + 1 - props.start()) + outside[end + 1:]
    for m in re.finditer(r"^\s*(\w+)\b([^\n{]*)", outside, re.M):
        word, rest = m.group(1), m.group(2).strip()
        where = f"{path}:{_line_of(masked, m.start(1))}"
        if word == "Cull":
            value = rest.lower()
            if value not in ("back", "front", "off"):
                raise UnityShaderError(f"{where}: Cull {rest}: expected Back, Front or Off")
            shader.state.cull = value
        elif word == "ZWrite":
            if rest.lower() not in ("on", "off"):
                raise UnityShaderError(f"{where}: ZWrite {rest}: expected On or Off")
            shader.state.zwrite = rest.lower() == "on"
        elif word == "Blend":
            shader.state.blend = rest
            shader.warnings.append(
                f"{where}: Blend {rest}: a surface shader's blending comes from its #pragma "
                "surface alpha option here (alpha, alpha:fade, alpha:premul); this line is not applied")
        elif word in PASS_STATE_IGNORED:
            shader.warnings.append(f"{where}: {word} {rest}: not supported by the harness, ignored")


# --- CGPROGRAM ---------------------------------------------------------------------------

def _pragma(program: str, where) -> tuple:
    found = list(re.finditer(r"^[ \t]*#[ \t]*pragma[ \t]+surface[ \t]+(\w+)[ \t]+(\w+)([^\n]*)$", program, re.M))
    if not found:
        raise UnityShaderError(f"{where(0)}: no '#pragma surface <function> <LightingModel>' line: "
                               "only surface shaders are supported (vertex/fragment shaders are not)")
    if len(found) > 1:
        raise UnityShaderError(f"{where(found[1].start())}: a second #pragma surface")
    m = found[0]
    pragma = M.Pragma(function=m.group(1), model=m.group(2))
    accepted, unsupported = [], []
    for option in m.group(3).split():
        key, _, value = option.partition(":")
        if key == "vertex" and value:
            pragma.vertex = value
        elif key == "finalcolor" and value:
            pragma.finalcolor = value
        elif option in ALPHA_OPTIONS:
            pragma.alpha_mode = ALPHA_OPTIONS[option]
        elif key == "alphatest" and value:
            pragma.alpha_mode = "cutout"
            pragma.cutoff_property = value
        elif option in NO_EFFECT_OPTIONS or option.startswith(NO_EFFECT_PREFIXES):
            accepted.append(option)
        else:
            unsupported.append(option)
    pragma.accepted = tuple(accepted)
    pragma.unsupported = tuple(unsupported)
    return pragma, m.start()


def _function(masked: str, name: str):
    """(match, body) of the definition of function ``name``, or None."""
    for m in re.finditer(r"\b(" + _IDENT + r")\s+" + re.escape(name) + r"\s*\(([^)]*)\)\s*\{", masked):
        if m.group(1) in ("return", "else"):
            continue
        end = _matching_brace(masked, m.end() - 1)
        return m, masked[m.end():end]
    return None


def _params(text: str):
    """[(qualifier, type, name)] of a parameter list."""
    out = []
    for part in [p.strip() for p in text.split(",") if p.strip()]:
        part = re.sub(r":\s*\w+$", "", part).strip()  # HLSL semantic
        words = part.split()
        qual = words[0] if words[0] in ("in", "out", "inout", "uniform") else ""
        words = words[1:] if qual else words
        if len(words) < 2:
            return None
        out.append((qual, words[-2], words[-1]))
    return out


def _struct_fields(masked: str, name: str):
    m = re.search(r"\bstruct\s+" + re.escape(name) + r"\s*\{", masked)
    if not m:
        return None, None
    end = _matching_brace(masked, m.end() - 1)
    return m, masked[m.end():end]


_SIZE = {"": 1, "2": 2, "3": 3, "4": 4}


def _members(body: str):
    """[(type, name)] of a struct body; INTERNAL_DATA flagged as ('INTERNAL_DATA', '')."""
    out = []
    for decl in body.split(";"):
        decl = re.sub(r":\s*\w+\s*$", "", decl.strip())
        if not decl:
            continue
        if decl == "INTERNAL_DATA" or decl.startswith("INTERNAL_DATA"):
            out.append(("INTERNAL_DATA", ""))
            rest = decl[len("INTERNAL_DATA"):].strip()
            if not rest:
                continue
            decl = rest
        words = decl.replace(",", " , ").split()
        kind, names = words[0], [w for w in words[1:] if w != ","]
        out.extend((kind, n) for n in names)
    return out


def _component_count(kind: str) -> int:
    m = re.fullmatch(r"(?:float|half|fixed|int|uint|bool|min16float)([234]?)", kind)
    if m:
        return _SIZE[m.group(1)]
    m = re.fullmatch(r"[iub]?vec([234])", kind)  # a port-unity port's GLSL types
    return int(m.group(1)) if m else (1 if kind in ("float", "int", "uint", "bool") else 0)


def _lighting(masked: str, model: str, where) -> M.LightingFunction:
    if model in M.BUILTIN_MODELS:
        out = M.BUILTIN_MODELS[model]
        form = M.FORM_GI if model == "Lambert" else M.FORM_GI_VIEW
        return M.LightingFunction(model, form, out, has_gi=True)
    found = _function(masked, "Lighting" + model)
    if found is None:
        raise UnityShaderError(
            f"{where(0)}: #pragma surface names lighting model {model!r}, but there is no "
            f"Lighting{model}(...) function (built in: {', '.join(M.BUILTIN_MODELS)})")
    m, _ = found
    params = _params(m.group(2)) or []
    types = [t for _, t, _ in params]
    has_gi = _function(masked, f"Lighting{model}_GI") is not None
    if len(params) == 3 and types[2] == "UnityGI":
        form = M.FORM_GI_VIEW
    elif len(params) == 2 and types[1] == "UnityGI":
        form = M.FORM_GI
    elif len(params) == 3:
        form = M.FORM_LIGHT_DIR
    elif len(params) == 4:
        form = M.FORM_LIGHT_VIEW_DIR
    else:
        raise UnityShaderError(
            f"{where(m.start())}: Lighting{model}({m.group(2).strip()}) is none of Unity's forms: "
            "(s, lightDir, atten), (s, lightDir, viewDir, atten), (s, viewDir, UnityGI gi), (s, UnityGI gi)")
    if form in (M.FORM_GI_VIEW, M.FORM_GI) and not has_gi:
        raise UnityShaderError(f"{where(m.start())}: Lighting{model} takes UnityGI, so Unity also needs "
                               f"void Lighting{model}_GI(SurfaceOutput s, UnityGIInput data, inout UnityGI gi); "
                               "there is none")
    return M.LightingFunction(model, form, types[0], has_gi)


def parse_program(program: str, path: Path, first_line: int = 1, shader: M.SurfaceShader | None = None,
                  name: str | None = None) -> M.SurfaceShader:
    """The model of a CGPROGRAM text (``first_line``: where it starts in ``path``)."""
    masked = _blank_comments(program)

    def where(index: int) -> str:
        return f"{path}:{first_line - 1 + _line_of(program, index)}"

    pragma, pragma_at = _pragma(masked, where)
    if shader is None:
        shader = M.SurfaceShader(path=path, name=name or path.stem, program=program,
                                 program_line=first_line, pragma=pragma)
    shader.program, shader.program_line, shader.pragma = program, first_line, pragma
    for option in pragma.unsupported:
        shader.warnings.append(f"{where(pragma_at)}: #pragma surface option {option!r} is not supported "
                               "by pbrlab and has no effect")
    # The surface function and the output struct it fills.
    found = _function(masked, pragma.function)
    if found is None:
        raise UnityShaderError(f"{where(0)}: #pragma surface names {pragma.function!r}, but no "
                               f"function {pragma.function}(Input IN, inout SurfaceOutput... o) is defined")
    m, body = found
    params = _params(m.group(2))
    if not params or len(params) != 2 or params[0][1] != "Input" or params[1][0] != "inout":
        raise UnityShaderError(f"{where(m.start())}: {pragma.function}({m.group(2).strip()}): expected "
                               f"(Input IN, inout <SurfaceOutput type> o)")
    shader.output_type = params[1][1]
    out_name = params[1][2]
    shader.writes_normal = re.search(r"\b" + re.escape(out_name) + r"\.Normal\s*[-+*/]?=(?!=)", body) is not None
    shader.lighting = _lighting(masked, pragma.model, where)
    if shader.lighting.output_type != shader.output_type:
        raise UnityShaderError(
            f"{where(m.start())}: {pragma.function} fills {shader.output_type}, but lighting model "
            f"{pragma.model} takes {shader.lighting.output_type}")
    if shader.output_type in M.OUTPUT_FIELDS:
        shader.output_fields = dict(M.OUTPUT_FIELDS[shader.output_type])
    else:
        sm, sbody = _struct_fields(masked, shader.output_type)
        if sm is None:
            raise UnityShaderError(f"{where(m.start())}: output struct {shader.output_type} is not defined")
        shader.output_fields = {n: _component_count(t) for t, n in _members(sbody)}
    # struct Input.
    im, ibody = _struct_fields(masked, "Input")
    if im is None:
        raise UnityShaderError(f"{where(0)}: no struct Input {{ ... }} (Unity requires one, even if empty "
                               "but for one member)")
    members = _members(ibody)
    shader.internal_data = any(t == "INTERNAL_DATA" for t, _ in members)
    shader.input_members = [(t, n) for t, n in members if t != "INTERNAL_DATA"]
    # vertex: and finalcolor: functions.
    if pragma.vertex:
        found = _function(masked, pragma.vertex)
        vp = _params(found[0].group(2)) if found else None
        if not vp or vp[0][0] != "inout" or (len(vp) == 2 and (vp[1][0], vp[1][1]) != ("out", "Input")) or len(vp) > 2:
            raise UnityShaderError(f"{where(found[0].start() if found else 0)}: vertex:{pragma.vertex} needs "
                                   f"void {pragma.vertex}(inout appdata_full v) or "
                                   f"(inout appdata_full v, out Input o)")
        written = ()
        if len(vp) == 2:
            written = tuple(sorted(set(re.findall(r"\b" + re.escape(vp[1][2]) + r"\.(\w+)\s*[-+*/]?=(?!=)", found[1]))))
        shader.vertex = M.VertexFunction(pragma.vertex, vp[0][1], written, vp[1][2] if len(vp) == 2 else None)
    if pragma.finalcolor:
        found = _function(masked, pragma.finalcolor)
        fp = _params(found[0].group(2)) if found else None
        if not fp or len(fp) != 3 or fp[0][1] != "Input" or fp[2][0] != "inout":
            raise UnityShaderError(f"{where(found[0].start() if found else 0)}: finalcolor:{pragma.finalcolor} "
                                   f"needs void {pragma.finalcolor}(Input IN, {shader.output_type} o, "
                                   "inout fixed4 color)")
    # Input members nothing fills.
    written = set(shader.vertex.writes_input) if shader.vertex else set()
    for kind, member in shader.custom_members():
        if member not in written:
            raise UnityShaderError(
                f"{where(im.start())}: Input.{member} is not a name Unity fills (uv_<Texture>, "
                f"uv2_<Texture>, {', '.join(M.FILLED_INPUTS)}, INTERNAL_DATA) and no vertex: "
                "function writes it")
    shader.declared = frozenset(re.findall(r"^\s*(?:uniform\s+)?(?:static\s+)?(?:const\s+)?\w+\s+(" + _IDENT +
                                           r")\s*(?:=[^;]*)?;", _top_level(masked), re.M))
    return shader


def _top_level(masked: str) -> str:
    """Only the text at brace depth 0 (global declarations)."""
    out, depth = [], 0
    for ch in masked:
        if ch == "{":
            depth += 1
        if depth == 0 or ch == "\n":
            out.append(ch)
        if ch == "}":
            depth -= 1
            out.append(" ")
    return "".join(out)


def _implicit_texture_properties(shader: M.SurfaceShader) -> None:
    """A sampler the program declares without a Properties line still gets a texture, as in
    Unity (its default, white here; a samplerCUBE the environment) and _ST (1, 1, 0, 0)."""
    masked = _top_level(_blank_comments(shader.program))
    for kind, name in re.findall(r"\b(sampler2D|samplerCUBE|samplerCube)\s+(" + _IDENT + r")\s*;", masked):
        if name not in shader.properties:
            shader.properties[name] = M.Property(name, name, "2D" if kind == "sampler2D" else "Cube", "white",
                                                 ("implicit",))


def parse_text(text: str, path: Path) -> M.SurfaceShader:
    shader = _parse_text(text, path)
    _implicit_texture_properties(shader)
    return shader


def _parse_text(text: str, path: Path) -> M.SurfaceShader:
    masked = _blank_comments(text)
    starts = [m for m in re.finditer(r"\b(CGPROGRAM|HLSLPROGRAM|GLSLPROGRAM)\b", masked)]
    if not starts:  # bare CGPROGRAM text, or a port-unity port (its //@ lines: Properties, state)
        shader = parse_program(text, path, 1)
        if text.startswith(PORT_MARKER):
            shader.language = "glsl"
            for number, line in enumerate(text.splitlines(), start=1):
                where = f"{path}:{number}"
                if line.startswith("//@property "):
                    prop = _property(line[len("//@property "):], where)
                    shader.properties[prop.name] = prop
                elif line.startswith("//@state "):
                    state = " " * len("//@state ") + line[len("//@state "):]
                    _pass_state(state, (0, 0), path, shader)
        return shader
    if starts[0].group(1) != "CGPROGRAM":
        raise UnityShaderError(f"{path}:{_line_of(text, starts[0].start())}: {starts[0].group(1)} is not "
                               "supported: write the surface shader in a CGPROGRAM block")
    if len(starts) > 1:
        raise UnityShaderError(f"{path}:{_line_of(text, starts[1].start())}: a second program block: one "
                               "SubShader with one CGPROGRAM is supported")
    start = starts[0].end()
    end_m = re.compile(r"\bENDCG\b").search(masked, start)
    if end_m is None:
        raise UnityShaderError(f"{path}:{_line_of(text, starts[0].start())}: CGPROGRAM without ENDCG")
    name_m = re.search(r'\bShader\s+"([^"]*)"', masked[:starts[0].start()]) or re.search(r'\bShader\s+"([^"]*)"', text)
    program = text[start:end_m.start()]
    shader = parse_program(program, path, _line_of(text, start), name=name_m.group(1) if name_m else path.stem)
    shader.properties = _properties(masked, text, path)
    _pass_state(masked, (starts[0].start(), end_m.end()), path, shader)
    return shader


def is_unity_surface(path: Path) -> bool:
    """A ``.shader`` file, or text with a ``#pragma surface`` line."""
    if path.suffix == ".shader":
        return True
    try:
        text = path.read_text(encoding="utf-8", errors="replace")
    except OSError:
        return False
    return re.search(r"^[ \t]*#[ \t]*pragma[ \t]+surface\b", _blank_comments(text), re.M) is not None


def parse_file(path: Path) -> M.SurfaceShader:
    try:
        text = Path(path).read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as exc:
        raise UnityShaderError(f"{path}: cannot read: {exc}") from None
    return parse_text(text, Path(path))
