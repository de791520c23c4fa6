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

import difflib
import math
import re
from dataclasses import dataclass
from pathlib import Path

from ...scene.surface_layers import written_layers
from . import model as M
from .conditionals import active_text, defines_of
from .compute_buffers import check_compute_buffers
from .engine_inputs import check_engine_inputs
from .lightmaps import ENGINE_SET_TEXTURES
from . import fixed_function, render_objects, shaderlab, texture_objects, texture_structs
from .include_case import respell_package_includes
from .include_separators import forward_slashed_includes
from .generate_pass import colour_output
from .parse_pass import _structs, parse_pass
from .stencil_block import draws_nothing_alone, read_stencil
from .written_globals import copied_written_globals
from .source_text import (IDENT, PORT_MARKER, UnityIncludeRefusal, UnityShaderError, blank_comments,
                          check_refusals, component_count, included_text, line_of, matching_brace, read_source,
                          top_level, declared_globals)

FLOAT32_MAX = 3.4028234663852886e38

# Options with no effect here: the harness has no shadows, lightmaps, deferred or
# prepass paths, fog, instancing or meta pass (README, "Unity shaders").
NO_EFFECT_OPTIONS = frozenset("""
    addshadow fullforwardshadows noshadow nolightmap nodirlightmap nodynlightmap
    noforwardadd nometa noinstancing nofog nolppv noshadowmask novertexlights
    keepalpha dualforward softvegetation nodynlightmap
""".split())
NO_EFFECT_PREFIXES = ("exclude_path:", "interpolateview", "halfasview", "approxview")
ALPHA_OPTIONS = {"alpha": "fade", "alpha:auto": "fade", "alpha:blend": "fade",
                 "alpha:fade": "fade", "alpha:premul": "transparent"}
PASS_STATE_HONOURED = ("Cull", "ZWrite", "Blend", "Stencil")
PASS_STATE_IGNORED = ("ZTest", "ColorMask", "Offset", "AlphaToMask", "BlendOp", "Conservative", "ZClip")


class _Lines:
    """Line numbers of increasing offsets into one text, each newline counted once (a count
    from the start per property made reading a Properties block quadratic: 6 s of 7 for
    20,000 properties)."""

    def __init__(self, text: str, first_line: int = 1):
        self.text, self.index, self.line = text, 0, first_line

    def at(self, index: int) -> int:
        if index < self.index:  # not expected: count afresh rather than go wrong
            self.index, self.line = 0, self.line - self.text.count("\n", 0, self.index)
        self.line += self.text.count("\n", self.index, index)
        self.index = index
        return self.line


# --- ShaderLab --------------------------------------------------------------------------

_PROPERTY = re.compile(
    r'(?P<attrs>(?:\[[^\]]*\]\s*)*)(?P<name>' + IDENT + r')\s*\(\s*"(?P<display>[^"]*)"\s*,\s*'
    r'(?P<kind>(?i:range)\s*\(\s*(?P<lo>[^,()]*),\s*(?P<hi>[^,()]*)\)|\w+)\s*\)\s*=\s*'
    r'(?P<default>\([^)]*\)|"[^"\n]*"\s*(?:\{[^}]*\})?|[^\s\[]+)')
# ShaderLab's type names, case-insensitive as ShaderLab reads them -> the model's spelling.
PROPERTY_KINDS = {"float": "Float", "range": "Range", "int": "Int", "integer": "Int", "color": "Color",
                  "vector": "Vector", "2d": "2D", "3d": "3D", "cube": "Cube", "2darray": "2DArray",
                  "cubearray": "CubeArray", "any": "2D",
                  # RECT: the legacy name of a 2D texture property (non-power-of-two "rectangle"
                  # textures of Unity's early versions; Unity's own editor shaders still write it)
                  "rect": "2D"}
TEXTURE_DEFAULTS = ("white", "black", "gray", "grey", "bump", "red", "linearGrey", "")


def _number(text: str, where: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise UnityShaderError(f"{where}: expected a number, got {text!r}") from None
    if not math.isfinite(value) or abs(value) > FLOAT32_MAX:
        raise UnityShaderError(f"{where}: {text!r} is not a finite float32 number")
    return value


def _property(m: re.Match, where: str, warnings: list) -> M.Property:
    attrs = tuple(a.strip() for a in re.findall(r"\[([^\]]*)\]", m.group("attrs")))
    kind_text = m.group("kind")
    rng = None
    if kind_text.lower().startswith("range"):
        rng = (_number(m.group("lo").strip(), where), _number(m.group("hi").strip(), where))
        if rng[0] > rng[1]:  # Unity draws the slider from the first value to the second
            warnings.append(f"{where}: {m.group('name')}: Range({m.group('lo').strip()}, {m.group('hi').strip()}) "
                            f"runs downward; its values are checked against [{rng[1]:g}, {rng[0]:g}]")
            rng = (rng[1], rng[0])
        kind_text = "range"
    kind = PROPERTY_KINDS.get(kind_text.lower())
    if kind is None:
        raise UnityShaderError(f"{where}: property type {kind_text!r} is not one of Float, Range, Int, "
                               "Color, Vector, 2D, 3D, Cube, 2DArray, CubeArray, Any")
    default_text = m.group("default").strip()
    name = m.group("name")
    if kind in ("Float", "Range", "Int"):
        default = _number(default_text, where)
        if rng is not None and not rng[0] <= default <= rng[1]:
            # Unity keeps it: a new material takes the default as written (ScriptReference,
            # Shader.GetPropertyDefaultFloatValue and GetPropertyRangeLimits give the two
            # apart), and the Range only bounds the Inspector's slider (MaterialEditor.
            # RangeProperty "draws a range slider"); nothing in Unity clamps it until a user
            # drags that slider.
            warnings.append(f"{where}: {name}: default {default_text} lies outside its Range({rng[0]:g}, "
                            f"{rng[1]:g}); used as written, as Unity does (its Range bounds the Inspector's "
                            "slider only)")
    elif kind in ("Color", "Vector"):
        v = re.fullmatch(r"\(\s*([^)]*)\)", default_text)
        parts = [p for p in v.group(1).split(",")] if v else []
        if len(parts) not in (3, 4) if kind == "Color" else len(parts) not in (2, 3, 4):
            raise UnityShaderError(f"{where}: {name}: {kind} default must be (x, y, z, w)"
                                   f"{' or (r, g, b)' if kind == 'Color' else ''}, got {default_text!r}")
        values = [_number(p.strip(), where) for p in parts]
        default = tuple(values + [1.0 if kind == "Color" else 0.0] * (4 - len(values)))
    else:
        t = re.fullmatch(r'"([^"]*)"\s*(\{[^}]*\})?', default_text)
        if not t:
            raise UnityShaderError(f'{where}: {name}: texture default must be a name in quotes '
                                   f'("white", "black", "gray", "bump", "red", ""), got {default_text!r}')
        default = t.group(1)
        if kind == "Cube":
            default = default or "gray"  # every Cube samples the scene's environment here
        elif default not in TEXTURE_DEFAULTS:
            warnings.append(f'{where}: {name}: default texture "{default}" is none of Unity\'s built-in '
                            'defaults (white, black, gray, bump, red); Unity shows gray, and so does pbrlab')
            default = "gray"
        default = {"": "gray", "linearGrey": "gray"}.get(default, default)
    return M.Property(name, m.group("display"), kind, default, attrs, rng)


def _properties_in(text: str, first_line: int, path: Path, warnings: list) -> dict:
    """Properties of the text inside ``Properties { ... }`` (comments blanked): several per
    line, attributes anywhere before a name, as ShaderLab reads them."""
    props, pos = {}, 0
    lines = _Lines(text, first_line)
    for m in _PROPERTY.finditer(text):
        gap = text[pos:m.start()]
        if gap.strip():
            raise UnityShaderError(f"{path}:{lines.at(pos + len(gap) - len(gap.lstrip()))}: "
                                   f"cannot read this Properties text: {gap.strip()[:60]!r} "
                                   '(expected _Name ("Label", Type) = default)')
        where = f"{path}:{lines.at(m.start('name'))}"
        prop = _property(m, where, warnings)
        props[prop.name] = prop
        pos = m.end()
    rest = text[pos:]
    if rest.strip():
        raise UnityShaderError(f"{path}:{first_line - 1 + line_of(text, pos + len(rest) - len(rest.lstrip()))}: "
                               f"cannot read this Properties text: {rest.strip()[:60]!r} "
                               '(expected _Name ("Label", Type) = default)')
    return props


# UnityEngine.Rendering enums, for state read from a property (``Cull [_Cull]``): the
# property's value is the enum's index (Unity's scripting reference: CullMode, BlendMode,
# CompareFunction).
_CULL_ENUM = ("off", "front", "back")
BLEND_FACTORS = shaderlab.BLEND_FACTORS
_ZTEST_ENUM = ("always", "never", "less", "equal", "lequal", "greater", "notequal", "gequal", "always")
ZTESTS = {"less": "less", "greater": "greater", "lequal": "lequal", "gequal": "gequal", "equal": "equal",
          "notequal": "notequal", "always": "always", "never": "never", "off": "always", "on": "lequal"}


def _state_words(args: str, props: dict, where: str, enum=None) -> list[str]:
    """The words of a state command, a ``[_Property]`` replaced by its default (through
    ``enum`` where the property holds an enum index)."""
    out = []
    for word in re.findall(r"\[\s*\w+\s*\]|[^\s,]+", args):
        if word.startswith("["):
            name = word.strip("[] ")
            prop = props.get(name)
            if prop is None:  # a global the engine sets (unity_GUIZTestMode): its default stands
                return None
            if prop.is_texture or isinstance(prop.default, tuple):
                raise UnityShaderError(f"{where}: {word} names no Float/Int/Range property")
            value = int(prop.default)
            if enum is not None:
                if not 0 <= value < len(enum):
                    raise UnityShaderError(f"{where}: {word} = {value} is outside the enum's 0..{len(enum) - 1}")
                word = enum[value]
            else:
                word = str(value)
        out.append(word)
    return out


def apply_state(commands, state: M.RenderState, props: dict, path: Path, warnings: list,
                surface: bool) -> None:
    """ShaderLab render state (a SubShader's, then a Pass's) onto ``state``."""
    for c in commands:
        where = f"{path}:{c.line}"
        word = c.word.lower()
        if word in shaderlab.FIXED_FUNCTION:
            continue  # fixed-function commands: fixed_function.py's (or ignored where a program draws)
        if "[" in c.args and _state_words(c.args, props, where) is None:
            warnings.append(f"{where}: {c.word} {c.args}: set by the engine at run time, not by a "
                            "property; the default state stands")
            continue
        if word == "cull":
            value = " ".join(_state_words(c.args, props, where, _CULL_ENUM)).lower()
            if value not in ("back", "front", "off"):
                raise UnityShaderError(f"{where}: Cull {c.args}: expected Back, Front or Off")
            state.cull = value
        elif word == "zwrite":
            value = " ".join(_state_words(c.args, props, where, ("off", "on"))).lower()
            if value not in ("on", "off"):
                raise UnityShaderError(f"{where}: ZWrite {c.args}: expected On or Off")
            state.zwrite = value == "on"
        elif word == "ztest":
            value = " ".join(_state_words(c.args, props, where, _ZTEST_ENUM)).lower()
            if value not in ZTESTS:
                raise UnityShaderError(f"{where}: ZTest {c.args}: expected one of Less, Greater, LEqual, "
                                       "GEqual, Equal, NotEqual, Always")
            if value == "on":  # ShaderLab takes it (tutorial shaders write it); the test is on: the default LEqual
                warnings.append(f"{where}: ZTest {c.args}: read as ZTest LEqual (the default depth test)")
            state.ztest = ZTESTS[value]
        elif word == "blend":
            words = _state_words(c.args, props, where, BLEND_FACTORS)
            state.blend = c.args
            if surface:
                warnings.append(f"{where}: Blend {c.args}: a surface shader's blending comes from its #pragma "
                                "surface alpha option here (alpha, alpha:fade, alpha:premul); this line is not applied")
                continue
            if len(words) == 1 and words[0].lower() == "off":
                state.blend_factors = None
                continue
            if len(words) and words[0].isdigit():  # Blend 0 SrcAlpha One: a render target's
                words = words[1:]
            known = {f.lower(): f for f in BLEND_FACTORS}
            if len(words) not in (2, 4) or any(w.lower() not in known for w in words):
                raise UnityShaderError(f"{where}: Blend {c.args}: expected Off or two (or four) of "
                                       f"{', '.join(BLEND_FACTORS)}")
            state.blend_factors = tuple(known[w.lower()] for w in words)
        elif word == "colormask":
            state.color_mask = " ".join(_state_words(c.args, props, where)).lower()
        elif word == "stencil":  # a block: its [_Property] values are read by read_stencil
            state.stencil = read_stencil(c, props, path, warnings)
        elif word in ("lod", "name", "tags"):
            continue
        elif c.word in PASS_STATE_IGNORED or word in ("offset", "alphatomask", "blendop", "fog", "conservative",
                                                      "zclip"):
            warnings.append(f"{where}: {c.word} {c.args}: not supported by the harness, ignored")
        else:
            warnings.append(f"{where}: {c.word} {c.args}: not a ShaderLab command pbrlab knows, ignored")


# --- CGPROGRAM ---------------------------------------------------------------------------

def _pragma(program: str, where) -> tuple:
    found = list(re.finditer(r"^[ \t]*#[ \t]*pragma[ \t]+surface[ \t]+(\w+)[ \t]+(\w+)([^\n]*)$", program, re.M))
    if not found:
        raise UnityShaderError(f"{where(0)}: no '#pragma surface <function> <LightingModel>' line: a file "
                               "without a Shader \"name\" { ... } block is read as a bare surface program "
                               "(a vertex/fragment program needs its ShaderLab Pass)")
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
    for m in re.finditer(r"\b(" + IDENT + r")\s+" + re.escape(name) + r"\s*\(([^)]*)\)\s*\{", masked):
        if m.group(1) in ("return", "else"):
            continue
        end = matching_brace(masked, m.end() - 1)
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
    end = matching_brace(masked, m.end() - 1)
    return m, masked[m.end():end]


def _members(body: str):
    """[(type, name)] of a struct body; INTERNAL_DATA flagged as ('INTERNAL_DATA', ''), a
    member with the VFACE semantic as ('VFACE', name). Preprocessor lines are passed over
    (the members of every #if branch count)."""
    out = []
    body = re.sub(r"^[ \t]*#[^\n]*", "", body, flags=re.M)
    for decl in body.split(";"):
        if re.search(r":\s*(?:VFACE|SV_IsFrontFace)\s*$", decl.strip(), re.I):
            out.append(("VFACE", decl.split(":")[0].split()[-1]))
            continue
        if re.search(r":\s*COLOR0?\s*$", decl.strip(), re.I):  # Unity fills it with the vertex colour
            words = decl.split(":")[0].split()
            out.append(("COLOR", words[-1]))
            out.append((words[-2], words[-1]))
            continue
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
    masked = blank_comments(program)
    check_refusals(program, path, first_line, path.parent)
    # what the program includes may define its parts (struct Input, vertex: functions, ...)
    everything = masked + "\n" + included_text(program, path.parent)
    defines = defines_of(everything)
    everything = active_text(everything, defines)  # the default variant's branches
    check_engine_inputs(everything[:len(masked)], path, first_line)  # a global only Unity's engine sets
    check_compute_buffers(everything[:len(masked)], path, first_line)  # data only the application has

    def where(index: int) -> str:  # an index past the program's text lies in an include
        return f"{path}:{first_line - 1 + line_of(program, min(index, len(program)))}"

    pragma, pragma_at = _pragma(masked, where)
    if shader is None:
        shader = M.SurfaceShader(path=path, name=name or path.stem, program=program,
                                 program_line=first_line, pragma=pragma)
    if shader.language == "hlsl":  # globals the program writes (FXC's compatibility mode): static copies
        program, shader.written_globals = copied_written_globals(program, active_text(masked, defines))
    shader.program, shader.program_line, shader.pragma = program, first_line, pragma
    for option in pragma.unsupported:
        shader.warnings.append(f"{where(pragma_at)}: #pragma surface option {option!r} is not supported "
                               "by pbrlab and has no effect")
    # The surface function and the output struct it fills.
    found = _function(everything, pragma.function)
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
    shader.lighting = _lighting(everything, pragma.model, where)
    if shader.lighting.output_type != shader.output_type:
        raise UnityShaderError(
            f"{where(m.start())}: {pragma.function} fills {shader.output_type}, but lighting model "
            f"{pragma.model} takes {shader.lighting.output_type}")
    if shader.output_type in M.OUTPUT_FIELDS:
        shader.output_fields = dict(M.OUTPUT_FIELDS[shader.output_type])
    else:
        sm, sbody = _struct_fields(everything, shader.output_type)
        if sm is None:
            raise UnityShaderError(f"{where(m.start())}: output struct {shader.output_type} is not defined")
        shader.output_fields = {n: component_count(t) for t, n in _members(sbody)}
    # struct Input.
    im, ibody = _struct_fields(everything, "Input")
    if im is None:
        raise UnityShaderError(f"{where(0)}: no struct Input {{ ... }} (Unity requires one, even if empty "
                               "but for one member)")
    members = _members(ibody)
    shader.internal_data = any(t == "INTERNAL_DATA" for t, _ in members)
    shader.facing_members = [n for t, n in members if t == "VFACE"]
    shader.color_members = [n for t, n in members if t == "COLOR"]
    shader.input_members = [(t, n) for t, n in members if t not in ("INTERNAL_DATA", "VFACE", "COLOR")]
    # vertex: and finalcolor: functions.
    if pragma.vertex:
        found = _function(everything, pragma.vertex)
        vp = _params(found[0].group(2)) if found else None
        if not vp or vp[0][0] != "inout" or (len(vp) == 2 and (vp[1][0], vp[1][1]) != ("out", "Input")) or len(vp) > 2:
            raise UnityShaderError(f"{where(found[0].start() if found else 0)}: vertex:{pragma.vertex} needs "
                                   f"void {pragma.vertex}(inout appdata_full v) or "
                                   f"(inout appdata_full v, out Input o)")
        written = ()
        if len(vp) == 2:
            # assigned, or handed to a macro or an out parameter (COMPUTE_EYEDEPTH(o.eyeDepth))
            written = tuple(sorted(set(re.findall(r"\b" + re.escape(vp[1][2]) + r"\.(\w+)", found[1]))))
        shader.vertex = M.VertexFunction(pragma.vertex, vp[0][1], written, vp[1][2] if len(vp) == 2 else None)
        if vp[0][1] not in ("appdata_full", "appdata_base", "appdata_tan"):
            own = _structs(everything).get(vp[0][1])
            if own is None:
                raise UnityShaderError(f"{where(found[0].start())}: vertex:{pragma.vertex} takes "
                                       f"{vp[0][1]}, a struct that is not defined")
            shader.vertex.appdata_members = own.members
    if pragma.finalcolor:
        found = _function(everything, pragma.finalcolor)
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
    shader.declared = declared_globals(everything)
    shader.light_keywords = tests_light_keywords(everything)
    if pragma.model in M.LAYERED_MODELS:
        # the layers whose fields it writes are compiled in (surface_layers.py)
        shader.layers = written_layers(everything)
        if shader.light_keywords:
            raise UnityShaderError(f"{where(pragma_at)}: lighting model {pragma.model} shades every light in "
                                   "one program, so it cannot test Unity's per-light keywords "
                                   f"({', '.join(LIGHT_KEYWORDS)}); use Standard, or remove those #if lines")
    return shader


# Unity's per-light keywords (ForwardBase: DIRECTIONAL; ForwardAdd: one per light type).
LIGHT_KEYWORDS = ("USING_DIRECTIONAL_LIGHT", "DIRECTIONAL", "POINT", "SPOT", "POINT_COOKIE",
                  "DIRECTIONAL_COOKIE")
_KEYWORD_TEST = re.compile(r"^[ \t]*#[ \t]*(?:if|ifdef|ifndef|elif)\b[^\n]*\b(?:" + "|".join(LIGHT_KEYWORDS) + r")\b", re.M)


def tests_light_keywords(masked: str) -> bool:
    """Whether preprocessor lines test a per-light keyword (then each light type gets its program)."""
    return _KEYWORD_TEST.search(masked) is not None


def _implicit_texture_properties(program: str, properties: dict) -> None:
    """A sampler the program declares without a Properties line still gets a texture, as in
    Unity (its default, white here; a samplerCUBE the environment) and _ST (1, 1, 0, 0)."""
    masked = top_level(blank_comments(program))
    masked = re.sub(r"\bUNITY_DECLARE_(?:DEPTH_TEXTURE|TEX2D|TEX2D_NOSAMPLER|SCREENSPACE_TEXTURE)\s*\(\s*(\w+)\s*\)",
                    r"sampler2D \1", masked)
    masked = re.sub(r"\bUNITY_DECLARE_TEXCUBE\s*\(\s*(\w+)\s*\)", r"samplerCUBE \1", masked)
    masked = re.sub(r"\bsampler2D_(?:float|half)\b", "sampler2D", masked)
    for kind, name in re.findall(r"\b(sampler2D|samplerCUBE|samplerCube)\s+(" + IDENT + r")\s*;", masked):
        if name not in properties and name not in ENGINE_SET_TEXTURES:  # (the object's lightmap: lightmaps.py)
            properties[name] = M.Property(name, name, "2D" if kind == "sampler2D" else "Cube", "white",
                                          ("implicit",))
    for name in re.findall(r"\bUNITY_DECLARE_TEX2DARRAY(?:_NOSAMPLER)?\s*\(\s*(" + IDENT + r")\s*\)", masked):
        if name not in properties:  # a texture array: one white layer (texture_arrays.py)
            properties[name] = M.Property(name, name, "2DArray", "white", ("implicit",))


def parse_text(text: str, path: Path) -> M.SurfaceShader:
    """The surface program of a shader's text (the first one, where a file has several)."""
    shader = read_text(text, path)
    if shader.surface is None:
        raise UnityShaderError(f"{path}: no surface program (#pragma surface) in the SubShader that runs")
    return shader.surface


# LightMode tags of passes the harness skips, with the reason said once per pass.
SKIPPED_LIGHT_MODES = {
    "shadowcaster": "no shadow maps here", "shadowcollector": "no shadow maps here",
    "meta": "no lightmap baking here", "deferred": "forward rendering only",
    "prepassbase": "forward rendering only", "prepassfinal": "forward rendering only",
    "motionvectors": "no motion vectors here", "sceneselectionpass": "an editor pass",
    "scenepickingpass": "an editor pass",
    "picking": "an editor pass",  # the Scene view's object picking (Terrain-Utilities' "Picking")
    # Unity draws a lightmapped object's VertexLM pass instead of its Vertex pass; here no
    # object has a lightmap, so the Vertex pass draws (legacy vertex-lit rendering)
    "vertexlm": "for lightmapped objects only (no lightmap here: the Vertex pass draws)",
    "vertexlmrgbm": "for lightmapped objects only (no lightmap here: the Vertex pass draws)",
}
DRAWN_LIGHT_MODES = ("always", "forwardbase", "forwardadd", "srpdefaultunlit", "vertex", "")


@dataclass(frozen=True)
class Pipeline:
    """The render pipeline a shader is read for: which passes it draws and skips (by
    LightMode), which program blocks it runs, and which SubShaders are its own (by their
    RenderPipeline tag; an untagged SubShader is every pipeline's)."""
    name: str
    drawn: tuple
    skipped: dict
    languages: tuple        # program block languages it runs ("CG", "HLSL")
    tags: tuple             # RenderPipeline tag values of its SubShaders (empty: it checks none)
    spellings: tuple = ()   # (pattern, replacement) applied to its programs' text: names its
                            # shaders use in signatures and directives, in the forms the reader knows
    srp: bool = False       # a Scriptable Render Pipeline: its programs are ported as SRP
                            # code (model.VertexFragmentPass.srp)
    rewrites: tuple = ()    # functions text -> text applied to its programs after the spellings
    keywords: tuple = ()    # keywords it enables where a program declares them (its renderer's)
    first_pass_per_light_mode: bool = False  # it draws a SubShader's first pass of each LightMode
                                             # alone (first_of_light_mode)


# Its passes run CGPROGRAM and HLSLPROGRAM blocks alike (Unity's manual, "HLSL in Unity": an
# HLSLPROGRAM only lacks CGPROGRAM's automatic HLSLSupport/UnityShaderVariables includes, which
# a built-in HLSLPROGRAM brings itself by including UnityCG.cginc; the reader declares Unity's
# built-in variables for either block).
# (LIGHTPROBE_SH: the engine's keyword for an object without a lightmap, light_probes.py; the
# lightmapped pipelines turn LIGHTMAP_ON / DYNAMICLIGHTMAP_ON on in its place)
BUILTIN = Pipeline("Unity's built-in render pipeline", DRAWN_LIGHT_MODES, SKIPPED_LIGHT_MODES, ("CG", "HLSL"), (),
                   keywords=("LIGHTPROBE_SH",))
# The Universal Render Pipeline (importers/urp/): forward passes drawn once with every light;
# a pass without a LightMode is SRPDefaultUnlit.
URP_SKIPPED_LIGHT_MODES = {
    "shadowcaster": "no shadow maps here", "depthonly": "no depth prepass here",
    "depthnormals": "no depth-normals prepass here", "depthnormalsonly": "no depth-normals prepass here",
    "meta": "no lightmap baking here", "universalgbuffer": "forward rendering only (no deferred G-buffer)",
    "universal2d": "the 2D renderer is not drawn", "motionvectors": "no motion vectors here",
    "xrmotionvectors": "no motion vectors here", "sceneselectionpass": "an editor pass",
    "scenepickingpass": "an editor pass", "picking": "an editor pass", "selection": "an editor pass",
    # URP's decal passes (the names of URP's DecalShaderPassNames): drawn only by the Decal
    # renderer feature, for a Decal Projector's box or a decal mesh, into the DBuffer, the
    # G-buffer or over the screen; pbrlab runs no decal feature
    **dict.fromkeys(("dbufferprojector", "decalprojectorforwardemissive", "decalscreenspaceprojector",
                     "decalgbufferprojector", "dbuffermesh", "decalmeshforwardemissive", "decalscreenspacemesh",
                     "decalgbuffermesh"),
                    "a URP decal pass, drawn only by URP's Decal renderer feature (for a Decal Projector or a "
                    "decal mesh), which pbrlab does not run"),
}
# Its RenderPipeline tags: URP sets Shader.globalRenderPipeline to "UniversalPipeline,LightweightPipeline"
# (UniversalRenderPipeline.cs: "for compatibility reasons" with LWRP's old tag), so a SubShader
# tagged LightweightPipeline runs under URP.
URP = Pipeline("the Universal Render Pipeline", ("universalforward", "universalforwardonly", "srpdefaultunlit", ""),
               URP_SKIPPED_LIGHT_MODES, ("CG", "HLSL"),
               ("UniversalPipeline", "UniversalRenderPipeline", "LightweightPipeline"),
               spellings=(
                   # Core RP's facing macros (a fragment parameter's type and semantic)
                   (re.compile(r"\bFRONT_FACE_TYPE\b"), "bool"),
                   (re.compile(r"\bFRONT_FACE_SEMANTIC\b"), "SV_IsFrontFace"),
                   # Unity 2022's include that also reads the file's #pragma lines: an include here
                   (re.compile(r"#(\s*)include_with_pragmas\b"), r"#\1include"),
               ),
               srp=True,
               # Shader Graph's texture objects (UnityTexture2D locals) spelled out
               rewrites=(texture_objects.spelled_out, texture_structs.spelled_out),
               # URP's default renderer: per-pixel additional lights
               keywords=("_ADDITIONAL_LIGHTS",),
               # URP's DrawObjectsPass: one pass of each LightMode it draws (first_of_light_mode)
               first_pass_per_light_mode=True)


def read_text(text: str, path: Path, pipeline: Pipeline = BUILTIN) -> M.UnityShader:
    """A whole shader: a ShaderLab file, bare CGPROGRAM text, or a port-unity port."""
    text = text.removeprefix("\ufeff")
    masked = blank_comments(text)
    # ShaderLab's keywords are case-insensitive: Unity reads ``shader "name" {`` too
    if not re.search(r"^\s*Shader\s*\"", masked, re.M | re.I):
        if not masked.strip():
            raise UnityShaderError(f"{path}:1: the file is empty (no Shader \"name\" {{ ... }} block, no program)")
        shader = parse_program(text, path, 1)
        if text.startswith(PORT_MARKER):
            shader.language = "glsl"
            for number, line in enumerate(text.splitlines(), start=1):
                where = f"{path}:{number}"
                if line.startswith("//@property "):
                    shader.properties.update(_properties_in(line[len("//@property "):], number, path,
                                                            shader.warnings))
                elif line.startswith("//@state "):
                    word, _, args = line[len("//@state "):].partition(" ")
                    apply_state([shaderlab.StateCommand(word, args, number)], shader.state,
                                shader.properties, path, shader.warnings, surface=True)
        _implicit_texture_properties(shader.program + "\n" + included_text(shader.program, path.parent),
                                     shader.properties)
        return M.UnityShader(path, shader.name, [shader], shader.properties, shader.warnings)
    try:
        layout = shaderlab.read_layout(text, path)
    except shaderlab.ShaderLabError as exc:
        raise UnityShaderError(str(exc)) from None
    warnings: list = []
    props = {}
    if layout.properties_span:
        a, b = layout.properties_span
        props = _properties_in(masked[a:b], line_of(text, a), path, warnings)
    reasons = []
    for index, sub in enumerate(layout.subshaders):
        notes: list = []
        tagged = sub.tags.get("RenderPipeline", "")
        if pipeline.tags and tagged and tagged not in pipeline.tags:
            reasons.append(f"SubShader {index + 1} (line {sub.line}): "
                           + _other_pipelines(path, index, sub, tagged, pipeline))
            continue
        try:
            passes = _subshader_passes(layout, sub, props, warnings, notes, pipeline)
        except UnityIncludeRefusal:
            raise
        except UnityShaderError as exc:
            reasons.append(f"SubShader {index + 1} (line {sub.line}): {exc}")
            continue
        if draws_nothing_alone([p.state for p in passes if p.kind != "grab"]):
            notes.append(f"{path}:{sub.line}: SubShader {NO_COLOUR_BY_STENCIL}: every pass that writes colour "
                         "tests for a stencil value that another object's mask writes (the frame's stencil is "
                         "cleared to 0), drawn as Unity draws it")
        if len(layout.subshaders) > 1:
            notes.insert(0, f"{path}:{sub.line}: SubShader {index + 1} of {len(layout.subshaders)} runs"
                         + (f" (earlier: {'; '.join(reasons)})" if reasons else ""))
        for p in passes:
            if p.kind != "grab":
                # samplers its includes declare too (TerrainSplatmapCommon.cginc's _Control, ...)
                _implicit_texture_properties(p.program + "\n" + included_text(p.program, path.parent), props)
                p.properties = props
        return M.UnityShader(path, layout.name, passes, props, warnings, notes)
    return _fallback(layout, reasons, path, pipeline)


def _other_pipelines(path: Path, index: int, sub, tagged: str, pipeline: Pipeline) -> str:
    """Why SubShader ``index`` (tagged RenderPipeline = ``tagged``) does not run under ``pipeline``:
    Unity runs a SubShader whose RenderPipeline tag is set only where the value matches the active
    pipeline's name (Shader.globalRenderPipeline, "matches the value completely": Unity's scripting
    reference), so a misspelt value ("UniversalPipelien") skips it in Unity too; the hint names the
    value it was likely meant to be."""
    line = sub.tag_lines.get("RenderPipeline", sub.line)
    names = " or ".join(f'"{name}"' for name in pipeline.tags)
    close = difflib.get_close_matches(tagged, pipeline.tags, n=1, cutoff=0.75)
    hint = (f'; "{tagged}" looks like a misspelling of "{close[0]}", which Unity would not correct either'
            if close else "")
    return (f'{path}:{line}: SubShader {index + 1} is tagged "RenderPipeline" = "{tagged}", and {pipeline.name} '
            f"runs only a SubShader tagged {names} or untagged (Unity matches the tag against the active "
            f"pipeline's name exactly, so it skips this SubShader too){hint}")


# The shaders Unity ships with the editor, not with a project (its built-in shaders: the legacy
# families by their short and "Legacy Shaders/" names, Standard, and the Unlit, Mobile, Particles,
# Skybox, Sprites, UI, GUI and Nature shaders by their whole names, since a project's own shaders
# often take those first names, "Unlit/NewUnlitShader"; the SRPs' packages): a Fallback names one by
# its name, and no folder of the project holds it.
_SHIPPED_WITH_UNITY = re.compile(
    r"(?:Legacy Shaders|Universal Render Pipeline|HDRP)/.*"
    r"|(?:Bumped )?(?:Diffuse|Specular)(?: Detail| Fast)?|VertexLit|Parallax (?:Diffuse|Specular)|Decal"
    r"|(?:Transparent|Self-Illumin|Reflective)/.*|Standard(?: \(Specular setup\))?|Autodesk Interactive"
    r"|Unlit/(?:Color|Texture|Transparent|Transparent Cutout)"
    r"|Mobile/(?:Diffuse|Bumped Diffuse|Bumped Specular.*|VertexLit.*|Unlit \(Supports Lightmap\)|Skybox|Particles/.*)"
    r"|Particles/Standard (?:Surface|Unlit)|Skybox/(?:6 Sided|Cubemap|Panoramic|Procedural)"
    r"|Sprites/(?:Default|Diffuse|Mask)|UI/(?:Default|Default Font|Unlit/.*|Lit/.*)|GUI/Text Shader"
    r"|Nature/(?:Terrain/.*|Tree Soft Occlusion.*|SpeedTree.*|Tree Creator.*)", re.I)
_ERROR_SHADER = "hidden/internalerrorshader"
# pbrlab's own stand-ins for a few of those (written from Unity's manual), found last
SHIPPED_STAND_INS = Path(__file__).parent / "shipped_shaders"
# the reason of a SubShader all of whose passes the pipeline's path skips (_subshader_passes)
_SKIPPED_ALL = "nothing here draws (every pass skipped"


def _missing_fallback(name: str) -> tuple:
    """(what, what to do) of a Fallback pbrlab did not find: a shader the project should hold, one
    of the shaders Unity ships (which no project holds), or Unity's error shader."""
    if name.lower() == _ERROR_SHADER:
        return "is Unity's error shader", (": Unity draws the object in its flat magenta, which pbrlab does "
                                           "not imitate")
    if _SHIPPED_WITH_UNITY.fullmatch(name):
        return ("is one of the shaders Unity ships with the editor (no file of the project)",
                ": pbrlab has no stand-in for it, and Unity would draw the object with it")
    return ("is a shader pbrlab does not have", ": put its .shader file in this shader's folder (or below it) or "
            "its Unity project's Assets, or name its folder in $PBRLAB_UNITY_SHADERS")


def _fallback(layout, reasons: list, path: Path, pipeline: Pipeline = BUILTIN) -> M.UnityShader:
    why = "; ".join(reasons) if reasons else "it has no SubShader"
    if layout.fallback in (None, "off"):
        if len(reasons) == 1:
            raise UnityShaderError(reasons[0].split(": ", 1)[1])
        raise UnityShaderError(f"{path}: no SubShader can run here ({why}), and there is no Fallback")
    found = find_shader(layout.fallback, path)
    if found is not None and found.parent == SHIPPED_STAND_INS and not all(_SKIPPED_ALL in r for r in reasons):
        # pbrlab's stand-in of a shader Unity ships is drawn only where Unity draws the Fallback:
        # every SubShader's passes are of another path (a Deferred-only one in the forward path);
        # a SubShader pbrlab cannot read (a mistake, a feature it lacks) is Unity's to draw or
        # reject, not the stand-in's, so that reason stays the refusal
        found = None
    what, how = _missing_fallback(layout.fallback)
    if found is None and len(reasons) == 1:  # this shader's one SubShader's reason first
        raise UnityShaderError(
            f"{reasons[0].split(': ', 1)[1]} (its one SubShader cannot run, and its Fallback "
            f'"{layout.fallback}" {what} (line {layout.fallback_line}){how})')
    if found is None:
        raise UnityShaderError(f"{path}:{layout.fallback_line}: no SubShader can run here ({why}); its Fallback "
                               f'"{layout.fallback}" {what}{how}')
    try:
        shader = read_shader(found, pipeline)
    except UnityShaderError as exc:  # the Fallback cannot run either: both reasons, this shader's first
        raise UnityShaderError(f'{path}:{layout.fallback_line}: no SubShader can run here ({why}); its Fallback '
                               f'"{layout.fallback}" ({found.name}) cannot run either: {exc}') from None
    shader.notes.insert(0, f'{path}:{layout.fallback_line}: no SubShader runs ({why}); Fallback '
                        f'"{layout.fallback}" ({found}) is drawn instead')
    return shader


def unity_project_folders(near: Path) -> list:
    """The folders of the Unity project ``near`` lies in, where Unity finds a shader by its
    name wherever it is (UsePass, Fallback, Shader.Find): ``Assets`` and ``Packages`` of the
    nearest folder above ``near`` that holds an ``Assets`` folder with ``near`` inside it; none
    for a file outside a Unity project."""
    resolved = near.resolve()
    for ancestor in resolved.parents:
        assets = ancestor / "Assets"
        if assets.is_dir() and assets in resolved.parents:
            return [folder for folder in (assets, ancestor / "Packages") if folder.is_dir()]
    return []


def find_shader(name: str, near: Path):
    """The ``.shader`` file whose ``Shader "name"`` is ``name`` (or ``Legacy Shaders/name``,
    Unity's old built-in names), in the folder of ``near`` and below, then anywhere in its Unity
    project (``unity_project_folders``), then the folders of $PBRLAB_UNITY_SHADERS."""
    wanted = {name, f"Legacy Shaders/{name}"}
    return next((candidate for candidate, found in shader_names(near) if found in wanted), None)


def shader_names(near: Path):
    """(file, its Shader "name") of every other ``.shader`` file ``find_shader`` searches, in its order."""
    import os
    roots = ([near.parent] + unity_project_folders(near)
             + [Path(p) for p in os.environ.get("PBRLAB_UNITY_SHADERS", "").split(os.pathsep) if p]
             + [SHIPPED_STAND_INS])
    seen = set()
    for root in roots:
        for candidate in sorted(root.rglob("*.shader")):
            if candidate in seen:
                continue
            seen.add(candidate)
            try:
                head = candidate.read_text(encoding="utf-8", errors="replace")[:4000]
            except OSError:
                continue
            m = re.search(r'\bShader\s*"([^"]*)"', blank_comments(head), re.I)
            if m and candidate.resolve() != near.resolve():
                yield candidate, m.group(1)


def _named_alike(name: str, near: Path) -> str:
    """A hint naming the shaders whose name ends as ``name``'s does (a UsePass or Fallback that
    names a shader by another path: Unity finds a shader by its whole name only)."""
    last = name.rpartition("/")[2].lower()
    alike = [f'"{found}" ({candidate.name})' for candidate, found in shader_names(near)
             if found.rpartition("/")[2].lower() == last]
    return (f"; the project has {', '.join(alike[:3])}: Unity finds a shader by its whole name, so the "
            "name written must be that one") if alike else ""


def _subshader_passes(layout, sub, props: dict, warnings: list, notes: list, pipeline: Pipeline = BUILTIN) -> list:
    path = layout.path
    passes = []
    first_note = len(notes)
    forward = any(item[0] == "pass" and item[1].light_mode.lower() == "forwardbase" for item in sub.items)
    for item in sub.items:
        kind = item[0]
        if kind == "program":
            block = item[1]
            if block.language != "CG":
                raise UnityShaderError(f"{path}:{block.line}: {block.keyword} is not supported: pbrlab runs "
                                       "CGPROGRAM blocks (Unity's built-in render pipeline)")
            if pipeline.name != BUILTIN.name:  # (a lightmapped reading of it is BUILTIN too: lightmaps.py)
                raise UnityShaderError(f"{path}:{block.line}: a surface program (#pragma surface) belongs to Unity's "
                                       f"built-in render pipeline, not {pipeline.name}")
            program, first = layout.program_text(block, sub)
            shader = parse_program(program, path, first, name=layout.name)
            state = M.RenderState()
            apply_state(sub.state, state, props, path, shader.warnings, surface=True)
            shader.state = state
            warnings.extend(shader.warnings)
            shader.warnings = warnings
            passes.append(shader)
        elif kind == "pass" and forward and item[1].light_mode.lower() in ("vertex", "vertexlm", "vertexlmrgbm") \
                and item[1].light_mode.lower() in pipeline.drawn:  # a lightmapped object's VertexLM too (lightmaps.py)
            notes.append(f"{path}:{item[1].line}: Pass (LightMode {item[1].light_mode}) skipped: its SubShader has "
                         "ForwardBase passes, which Unity's forward path draws instead")
        elif kind == "pass" and not first_of_light_mode(item[1], passes, pipeline):
            notes.append(f"{path}:{item[1].line}: Pass{' ' + repr(item[1].name) if item[1].name else ''} "
                         f"(LightMode {item[1].light_mode or 'none: SRPDefaultUnlit'}) skipped: {pipeline.name} "
                         "draws the first pass of each LightMode of a SubShader, and an earlier pass has this one's")
        elif kind == "pass":
            vf = _pass(layout, sub, item[1], props, warnings, notes, pipeline)
            if vf is not None:
                passes.append(vf)
        elif kind == "usepass":
            _, name, line = item
            pass_name = name.rpartition("/")[2].lower()
            if pass_name in pipeline.skipped or pass_name in ("caster", "shadowcollector"):
                notes.append(f'{path}:{line}: UsePass "{name}" skipped: '
                             f"{pipeline.skipped.get(pass_name, 'no shadow maps here')}")
                continue
            used = _use_pass(name, line, path, props, warnings, notes, pipeline)
            if used is not None:
                passes.append(used)
        elif kind == "grabpass":
            _, name, line = item
            passes.append(M.GrabPass(name, line))
    if not any(p.kind != "grab" for p in passes) and render_objects.custom_tags(sub, pipeline):
        # passes of a custom LightMode: drawn as a Render Objects renderer feature would (render_objects.py)
        tags = render_objects.custom_tags(sub, pipeline)
        del notes[first_note:]
        warnings.append(render_objects.warning(path, sub, tags))
        return _subshader_passes(layout, sub, props, warnings, notes, render_objects.drawing(pipeline, tags))
    if not any(p.kind != "grab" for p in passes):
        skipped = "; ".join(n.split(": ", 1)[1] if n.startswith(f"{path}:") else n for n in notes[first_note:])
        raise UnityShaderError(f"{path}:{sub.line}: nothing here draws (every pass skipped"
                               + (f": {skipped})" if skipped else ")") + _camera_colour(notes[first_note:]))
    return passes


# What Unity's forward path shows in the camera's colour for an object whose passes are all of
# one skipped kind (the reason SKIPPED_LIGHT_MODES gives them): said beside the refusal, so that
# it says what the shader looks like in Unity, not only which passes were skipped.
_CAMERA_COLOUR_WHEN_SKIPPED = (
    ("no shadow maps", "its passes only cast shadows: in Unity the object itself is invisible and shows only "
                       "as the shadow it casts on other objects, which pbrlab does not draw"),
    ("no motion vectors", "its passes only write motion vectors: Unity draws them into the camera's "
                          "motion-vector texture (where a camera asks for one), never into its colour, so in "
                          "Unity the object is invisible in the camera's image"),
    ("forward rendering only", "its passes are the deferred path's (the G-buffer's): they draw the object only "
                               "in a camera that renders deferred; in the forward path, which pbrlab draws, "
                               "Unity draws no pass of this SubShader into the camera's colour"),
)


def _camera_colour(notes: list) -> str:
    """``; <what Unity shows>`` where every skipped pass is of one kind above, else ''."""
    for reason, shown in _CAMERA_COLOUR_WHEN_SKIPPED:
        if notes and all(reason in n for n in notes):
            return "; " + shown
    return ""


def _srp_light_mode(mode: str) -> str:
    """A LightMode as an SRP draws it: an untagged pass is SRPDefaultUnlit."""
    return mode.lower() if mode.lower() not in ("", "always") else "srpdefaultunlit"


def first_of_light_mode(p, drawn: list, pipeline: Pipeline) -> bool:
    """Whether Pass ``p`` is drawn by a pipeline that draws one pass per LightMode, given the
    passes ``drawn`` before it. URP's DrawObjectsPass asks DrawRenderers for its ShaderTagId list
    (SRPDefaultUnlit, UniversalForward, UniversalForwardOnly; an untagged pass counts as
    SRPDefaultUnlit, URP's ShaderLab Pass tags page), and DrawRenderers draws an object's first
    pass of each tag: a second untagged pass is not drawn (Unity's Frame Debugger shows it;
    public write-ups of URP multi-pass shaders report it)."""
    if not pipeline.first_pass_per_light_mode:
        return True
    mode = _srp_light_mode(p.light_mode)
    return not any(getattr(q, "light_mode", None) is not None and _srp_light_mode(q.light_mode) == mode
                   for q in drawn if q.kind != "grab")


def _pass(layout, sub, p, props: dict, warnings: list, notes: list, pipeline: Pipeline = BUILTIN):
    """The vertex/fragment pass of ``Pass { ... }`` in ``sub``, or None where the harness
    skips it (a LightMode it does not draw, a depth-only pass), with a note saying so."""
    path = layout.path
    mode = p.light_mode
    label = f"Pass{' ' + repr(p.name) if p.name else ''}"
    if mode.lower() in pipeline.skipped:
        notes.append(f"{path}:{p.line}: {label} (LightMode {mode}) skipped: {pipeline.skipped[mode.lower()]}")
        return None
    if mode.lower() not in pipeline.drawn:
        notes.append(f"{path}:{p.line}: {label} (LightMode {mode}) skipped: {render_objects.skip_reason(mode, pipeline)}")
        return None
    if p.fixed_function and p.program is not None:
        # a program draws the pass: Unity ignores its fixed-function commands (docs, "ShaderLab:
        # legacy lighting" / "legacy texture combining" apply to passes without one)
        words = ", ".join(dict.fromkeys(w for w, _ in p.fixed_function))
        notes.append(f"{path}:{p.fixed_function[0][1]}: {label}: {words} ignored: a program draws this pass")
    if p.program is None:
        state = M.RenderState()
        apply_state(sub.state + p.state, state, props, path, [], surface=False)
        # a depth/stencil mask (ColorMask 0, no fixed-function command): Unity draws it in every
        # pipeline (an untagged pass is URP's SRPDefaultUnlit); its generated program's colour never
        # reaches the target, so it draws as written: depth (where ZWrite is on) and no colour
        writes_no_colour = not p.fixed_function and state.color_mask == "0"
        if writes_no_colour:
            notes.append(no_colour_note(path, p, label, state, sub.state + p.state))
        # Unity generates a program for a fixed-function pass (a pass with no command at all
        # draws white); so does pbrlab (fixed_function.py), which the front end then reads
        outer = [c for c in sub.state if c.word.lower() in shaderlab.FIXED_FUNCTION]
        lit = fixed_function.lit_command(outer + p.fixed_commands)
        if pipeline.name != BUILTIN.name and lit is not None:  # (a lightmapped reading is BUILTIN too)
            # Unity's manual ("Writing shaders", "ShaderLab: legacy fixed-function"): a fixed-function
            # pass is converted to a vertex and fragment program at import, so URP draws an untagged
            # one as it does any program (SRPDefaultUnlit); but its Lighting On reads the built-in
            # pipeline's per-vertex lights (unity_LightPosition[i] ...), which URP does not fill
            raise UnityShaderError(f"{path}:{lit.line}: a fixed-function Pass with Lighting On: its per-vertex "
                                   "lighting reads the built-in pipeline's vertex lights (unity_LightPosition, "
                                   "unity_LightColor), which pbrlab sets for the built-in pipeline's passes only, "
                                   f"not in {pipeline.name}; an unlit (Lighting Off) fixed-function pass is drawn")
        vf = parse_pass(fixed_function.translate(outer + p.fixed_commands, props, path), path, p.line, p)
        apply_state(sub.state + p.state, vf.state, props, path, warnings, surface=False)
        return vf
    if p.program.language == "GLSL":  # a GLSL snippet, in either pipeline (glslprogram.py)
        from .glslprogram import glsl_pass, implicit_samplers, note
        text, first = layout.program_text(p.program, sub)
        vf = glsl_pass(text, path, first, p)
        notes.append(note(path, first, text))
        for kind, name in implicit_samplers(text):  # a texture Unity binds by default, as for Cg
            props.setdefault(name, M.Property(name, name, kind, "white", ("implicit",)))
        apply_state(sub.state + p.state, vf.state, props, path, warnings, surface=False)
        return vf
    if p.program.language not in pipeline.languages:
        raise UnityShaderError(f"{path}:{p.program.line}: {p.program.keyword} is not supported: "
                               + ("pbrlab runs CGPROGRAM blocks (Unity's built-in render pipeline)"
                                  if pipeline.name == BUILTIN.name
                                  else f"{pipeline.name} runs CGPROGRAM and HLSLPROGRAM blocks"))
    program, first = layout.program_text(p.program, sub)
    for pattern, replacement in pipeline.spellings:
        program = pattern.sub(replacement, program)
    for rewrite in pipeline.rewrites:
        program = rewrite(program)
    program = respell_package_includes(forward_slashed_includes(program), path, first, warnings)
    vf = parse_pass(program, path, first, p, pipeline.spellings, pipeline.keywords, warnings, srp=pipeline.srp)
    vf.srp = pipeline.srp
    apply_state(sub.state + p.state, vf.state, props, path, warnings, surface=False)
    if vf.geometry is None and colour_output(vf, f"{path}:{p.line}") is None:
        # a fragment that writes SV_Depth and no SV_Target (Unity's Internal-DebugPattern's depth-only
        # pass): D3D leaves the colour target unwritten, so it draws as ColorMask 0 does
        vf.state.color_mask = "0"
        notes.append(f"{path}:{p.line}: {label} {NO_COLOUR_BY_FRAGMENT} ({vf.fragment}() returns no SV_Target): "
                     "drawn for its depth, rasterised (pbrlab does not write a fragment's SV_Depth)")
    return vf


# What a corpus summary lists a shader by when it renders but writes no colour by its own
# ColorMask (checking/unity_corpus.no_colour_reason reads it from the note).
NO_COLOUR_BY_COLOR_MASK = "draws no colour by its ColorMask"
# ... or by its fragment function, which writes no SV_Target (a depth-only pass).
NO_COLOUR_BY_FRAGMENT = "draws no colour by its fragment function"
# ... or draws nothing when its object is drawn alone, by its Stencil test (stencil_block.draws_nothing_alone).
NO_COLOUR_BY_STENCIL = "draws nothing alone by its Stencil test"


def no_colour_note(path: Path, p, label: str, state: M.RenderState, commands: list) -> str:
    """The note of a program-less ``ColorMask 0`` pass drawn as written: what it writes instead."""
    writes = ["depth"] if state.zwrite is not False else []
    if state.stencil is not None and state.stencil.write_mask and any(
            op != "keep" for face in (state.stencil.front, state.stencil.back)
            for op in (face.pass_op, face.fail_op, face.depth_fail_op)):
        writes.append("stencil")
    return (f"{path}:{p.line}: {label} {NO_COLOUR_BY_COLOR_MASK} (ColorMask 0): drawn as written, writing "
            f"{' and '.join(writes) or 'nothing the image shows (ZWrite Off)'}")


def _use_pass(name: str, line: int, path: Path, props: dict, warnings: list, notes: list,
              pipeline: Pipeline = BUILTIN):
    """``UsePass "Shader/NAME"``: the pass named NAME (Unity upper-cases pass names) of that
    shader's first SubShader that has one, drawn with this material's properties; None
    where the harness skips that pass (noted)."""
    shader_name, _, pass_name = name.rpartition("/")
    found = find_shader(shader_name, path) if shader_name else None
    if found is None:
        raise UnityShaderError(f'{path}:{line}: UsePass "{name}": no shader "{shader_name}" here (put its '
                               ".shader file in this shader's folder or its Unity project's Assets, or name "
                               f"its folder in $PBRLAB_UNITY_SHADERS){_named_alike(shader_name, path)}")
    try:
        layout = shaderlab.read_layout(read_source(found), found)
    except (OSError, UnicodeDecodeError, shaderlab.ShaderLabError) as exc:
        raise UnityShaderError(f'{path}:{line}: UsePass "{name}": {exc}') from None
    for sub in layout.subshaders:
        for item in sub.items:
            if item[0] == "pass" and (item[1].name or "").upper() == pass_name.upper():
                before = len(notes)
                vf = _pass(layout, sub, item[1], props, warnings, notes, pipeline)
                if vf is None:
                    notes[before:] = [f'{path}:{line}: UsePass "{name}": ' + n for n in notes[before:]]
                return vf
    raise UnityShaderError(f'{path}:{line}: UsePass "{name}": {found} has no Pass named {pass_name!r} '
                           "(a surface program's generated passes cannot be used)")


def read_shader(path: Path, pipeline: Pipeline = BUILTIN) -> M.UnityShader:
    try:
        text = read_source(Path(path))
    except OSError as exc:
        raise UnityShaderError(f"{path}: cannot read: {exc}") from None
    return read_text(text, Path(path), pipeline)


def is_unity_surface(path: Path) -> bool:
    """A ``.shader`` file, or text with a ``#pragma surface`` line."""
    if path.suffix == ".shader":
        return True
    try:
        text = path.read_text(encoding="utf-8", errors="replace")
    except OSError:
        return False
    return re.search(r"^[ \t]*#[ \t]*pragma[ \t]+surface\b", blank_comments(text), re.M) is not None


def parse_file(path: Path) -> M.SurfaceShader:
    """The surface program of a shader file (``read_shader`` gives every pass)."""
    shader = read_shader(path)
    if shader.surface is None:
        raise UnityShaderError(f"{path}: no surface program (#pragma surface) in the SubShader that runs")
    return shader.surface
