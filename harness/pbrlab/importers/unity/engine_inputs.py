"""Globals a Unity shader declares itself but only one of Unity's engine subsystems sets (the
previous frame's matrices of motion vectors, the terrain's tree-imposter lights): where the
harness has nothing to fill one from, it would stay zero and draw a picture Unity never shows.
A vertex/fragment pass whose drawn variant reads one
is refused naming it, at its line, before anything is compiled (a compiler would accept the
shader's own declaration).

    check_engine_inputs(active_program, path, first_line)   # raises UnityShaderError

Some of them the harness's scene fills as Unity's engine would (FILLED: the terrain
imposter's tree lights from the scene's directional lights; motion vectors' matrices of a
still camera and still objects, the previous frame's equal to this one's). A vertex/fragment
program that declares one of those itself, with Unity's type, has its declaration made a
``static`` global (line kept), which the entry points of both stages fill before the
program's functions run:

    program, filled = fill_declared(program, active_program)   # parse_pass
    fill_statements(filled, language)                          # generate_pass's entry points
"""

from __future__ import annotations

import re
from pathlib import Path

from . import light_space, multisampled_textures
from .source_text import UnityShaderError, line_of

_MOTION = ("motion vectors: the previous frame's camera and object matrices, which pbrlab fills (a still "
           "frame's) only where the program itself declares them as Unity does (float4x4, at global scope)")
_STEREO_MOTION = ("motion vectors of a stereo render: each eye's previous-frame matrices (pbrlab renders "
                  "one eye)")
_TREE_IMPOSTER = ("the lights Unity's terrain sets when it renders a tree into its billboard imposter "
                  "texture, which pbrlab fills from the scene's directional lights only where the program "
                  "itself declares them as Unity does (float3[4] directions, float4[4] colours, at global scope)")

# name -> the engine feature that sets it (docs/unity.md, "Unity names set by an engine subsystem";
# the ones FILLED below are refused only where not declared as Unity declares them).
ENGINE_FED = {
    "_NonJitteredVP": _MOTION, "_PreviousVP": _MOTION, "_PreviousM": _MOTION,
    "_StereoNonJitteredVP": _STEREO_MOTION, "_StereoPreviousVP": _STEREO_MOTION,
    "_TerrainTreeLightDirections": _TREE_IMPOSTER, "_TerrainTreeLightColors": _TREE_IMPOSTER,
}
_NAME = re.compile(r"\b(" + "|".join(sorted(ENGINE_FED, key=len, reverse=True)) + r")\b")
# a declaration's own line does not read it: ``float4x4 _PreviousVP;`` alone draws nothing
_DECLARATION = re.compile(r"^\s*(?:uniform\s+)?\w+\s+\w+\s*(?:\[[^\]]*\])?\s*;\s*$")


def engine_input_read(active_program: str, filled=()):
    """(name, offset) of the first use of an ENGINE_FED name in ``active_program`` (comments
    blanked, branches not drawn blanked) other than a declaration, leaving out ``filled`` (the
    names fill_declared found filled); None when there is none."""
    for m in _NAME.finditer(active_program):
        if m.group(1) in filled:
            continue
        start = active_program.rfind("\n", 0, m.start()) + 1
        end = active_program.find("\n", m.end())
        line = active_program[start:end if end >= 0 else len(active_program)]
        if not _DECLARATION.match(line):
            return m.group(1), m.start()
    return None


# Direct3D 10's multisampled texture objects declared outright (``Texture2DMSArray<float> t;``):
# a declaration alone is kept (GLSL's sampler2DMS / sampler2DMSArray: multisampled_textures.py);
# a read of one in the drawn variant needs a multisampled texture bound, which a material cannot
# give (its textures are single-sampled 2D).
MULTISAMPLED_FEATURE = ("multisampled textures (Direct3D's Texture2DMS objects): reading one needs a "
                        "multisampled texture, which a material cannot bind (its textures are single-sampled 2D)")


def check_engine_inputs(active_program: str, path: Path, first_line: int, filled=()) -> None:
    """Refuse a program whose drawn variant reads a global only an engine subsystem sets (other
    than ``filled``: fill_declared's), or reads a multisampled texture object."""
    found = engine_input_read(active_program, filled)
    feature = ENGINE_FED[found[0]] if found else None
    read = multisampled_textures.first_read(active_program)
    if read and (found is None or read[1] < found[1]):
        found, feature = read, MULTISAMPLED_FEATURE
    if found is None:
        return
    name, offset = found
    line = first_line - 1 + line_of(active_program, offset)
    raise UnityShaderError(f"{path}:{line}: uses {name}, part of {feature}; pbrlab does not provide it")


# The engine-set globals the harness's scene fills, as Unity's engine fills them: name ->
# (Unity's declared type, its array length or None, what it holds here). The statements that
# fill them are fill_statements'; docs/unity.md, "Engine-set inputs filled from the scene".
#
# The terrain imposter's tree lights (UnityTerrainImposter: float3[4] directions, float4[4]
# colours, read by Nature/TreeCreator/*Rendertex and by UnityBuiltin2xTreeLibrary under
# USE_CUSTOM_LIGHT_DIR): Unity renders a tree into its billboard texture lit by the scene's
# directional lights. The shaders use a direction as the unit vector towards the light in the
# tree's object space (dot with the object-space v.normal, and half-way with
# ObjSpaceViewDir), a colour's rgb as the light's colour (times N.L, added): so slot i holds
# the scene's i-th directional light (scene order; at most 4, the array's length; the TreeCreator
# Rendertex shaders read 3, the soft-occlusion ones through UnityBuiltin2xTreeLibrary.cginc 4): direction normalize(unity_WorldToObject (-light direction, 0)), colour
# (color x intensity, 1), the harness's _LightColor0 convention. A slot without a light is no
# light: colour 0 and direction 0 (a zero direction keeps the shader's normalize(L + V)
# finite; times colour 0 it adds nothing). Positional lights have no direction to give: a
# billboard's lights are directions.
#
# Motion vectors (Internal-MotionVectors and the shaders written after it): the harness renders
# one frame from a still camera of objects that do not move, so the previous frame's
# view-projection and object matrices are this frame's (_PreviousVP = unity_MatrixVP,
# _PreviousM = unity_ObjectToWorld), and its camera has no jitter (_NonJitteredVP =
# unity_MatrixVP, its projection unjittered): the motion each pixel holds is 0. The stereo
# arrays (_Stereo*) stay refused: the harness renders one eye (USING_STEREO_MATRICES is off).
TREE_LIGHTS = 4
FILLED = {
    "_TerrainTreeLightDirections": ("float3", TREE_LIGHTS, "the scene's directional lights, towards each in object space"),
    "_TerrainTreeLightColors": ("float4", TREE_LIGHTS, "the scene's directional lights' colour x intensity"),
    "_NonJitteredVP": ("float4x4", None, "unity_MatrixVP (the harness's camera has no jitter)"),
    "_PreviousVP": ("float4x4", None, "unity_MatrixVP (a still camera)"),
    "_PreviousM": ("float4x4", None, "unity_ObjectToWorld (a still object)"),
    # the forward pass's light (AutoLight.cginc declares it; Unity 5.3's name the program's own)
    "unity_WorldToLight": ("float4x4", None, "the pass's light: world to light space (light_space.py)"),
    "_LightMatrix0": ("float4x4", None, "the pass's light: world to light space (light_space.py)"),
    # URP's additional lights (its Input.hlsl's arrays, the uniform-array path; URP_LIGHTS entries,
    # MAX_VISIBLE_LIGHTS on OpenGL Core): the scene's lights after the main one, in the stand-in
    # Input.hlsl's order, each entry the value of that file's function of the same part
    "_AdditionalLightsPosition": ("float4", 32, "the additional lights' positions (a directional's direction, w 0)"),
    "_AdditionalLightsColor": ("float4", 32, "the additional lights' colours"),
    "_AdditionalLightsAttenuation": ("float4", 32, "the additional lights' range and cone factors"),
    "_AdditionalLightsSpotDir": ("float4", 32, "the additional lights' spot directions (towards the light)"),
}
# each URP additional-light array and the stand-in function (Input.hlsl) that gives its entry i
URP_LIGHTS = {"_AdditionalLightsPosition": "pbrlab_urp_additional_light_position",
              "_AdditionalLightsColor": "pbrlab_urp_additional_light_color",
              "_AdditionalLightsAttenuation": "pbrlab_urp_additional_light_attenuation",
              "_AdditionalLightsSpotDir": "pbrlab_urp_additional_light_spot_direction"}
# a global's declaration: its `uniform` (1), base (2: float|half|fixed), dimensions (3), name (4), length (5)
_DECLARED = re.compile(r"^[ \t]*(uniform[ \t]+)?(float|half|fixed)([34](?:x4)?)[ \t]+(\w+)[ \t]*"
                       r"(?:\[[ \t]*(\d+)[ \t]*\])?[ \t]*;", re.M)
# the same groups of a `static` one (a stand-in's own global, filled as it stands)
_STATIC_DECLARED = re.compile(r"^[ \t]*(static[ \t]+)(float|half|fixed)([34](?:x4)?)[ \t]+(\w+)[ \t]*"
                              r"(?:\[[ \t]*(\d+)[ \t]*\])?[ \t]*;", re.M)


def _outside_braces(text: str) -> str:
    """``text`` with what lies inside braces blanked (newlines kept): the same offsets."""
    out, depth = [], 0
    for ch in text:
        depth += ch == "{"
        out.append(ch if depth == 0 or ch == "\n" else " ")
        depth -= ch == "}"
    return "".join(out)


def _unitys(m) -> bool:
    """Whether declaration ``m`` (_DECLARED) is of a FILLED name with Unity's type and length."""
    if m.group(4) not in FILLED:
        return False
    kind, count, _ = FILLED[m.group(4)]
    return f"float{m.group(3)}" == kind and (int(m.group(5)) if m.group(5) else None) == count


def fill_declared(program: str, active_program: str, active_included: str = "") -> tuple[str, tuple]:
    """(``program`` with its own declarations of FILLED names made ``static``: a global of
    the stage's own, which its entry point fills (the GLSL port drops the word: a plain
    global), the names so filled). ``active_program``: ``program`` with comments and the
    branches not drawn blanked (the same offsets); ``active_included``: the same of the files
    it includes, where a ``static`` declaration (a stand-in's: UnityBuiltin2xTreeLibrary.cginc)
    is filled as it stands. Only a declaration at brace depth 0 with Unity's type and array
    length (float, half or fixed alike) is taken; any other keeps its name refused
    (check_engine_inputs)."""
    taken = [m for m in _DECLARED.finditer(_outside_braces(active_program)) if _unitys(m)]
    text = program
    for m in reversed(taken):  # `uniform float4x4 X;` -> `static float4x4 X;`; `float3 X[4];` -> `static float3 X[4];`
        start = m.start(1) if m.group(1) else m.start(2)
        text = text[:start] + "static " + text[m.start(2):]
    static = [m for m in _STATIC_DECLARED.finditer(_outside_braces(active_included)) if _unitys(m)]
    # URP's additional-light arrays (Input.hlsl, in every URP program): filled only where something
    # reads one, past its declaration (the stand-ins read the functions that give them instead)
    everything = active_program + "\n" + active_included
    static = [m for m in static if m.group(4) not in URP_LIGHTS
              or len(re.findall(rf"\b{m.group(4)}\b", everything)) > 1]
    return text, tuple(dict.fromkeys(m.group(4) for m in taken + static))


def fill_statements(filled, language: str) -> str:
    """Statements (an entry point's, before it calls the program) that fill the ``filled`` names
    from the scene (FILLED's comment: the mapping)."""
    vec3, vec4 = ("float3", "float4") if language == "hlsl" else ("vec3", "vec4")
    to_object = ("mul(unity_WorldToObject, {v})" if language == "hlsl" else "(unity_WorldToObject * {v})")
    out = []
    if "_TerrainTreeLightDirections" in filled or "_TerrainTreeLightColors" in filled:
        direction = "_TerrainTreeLightDirections" in filled
        colour = "_TerrainTreeLightColors" in filled
        out.append(f"    for (int pbrlab_t = 0; pbrlab_t < {TREE_LIGHTS}; pbrlab_t++) {{")
        if direction:
            out.append(f"        _TerrainTreeLightDirections[pbrlab_t] = {vec3}(0.0, 0.0, 0.0);")
        if colour:
            out.append(f"        _TerrainTreeLightColors[pbrlab_t] = {vec4}(0.0, 0.0, 0.0, 0.0);")
        out += ["    }", "#if PBRLAB_DIRECTIONAL_COUNT > 0",
                f"    for (int pbrlab_d = 0; pbrlab_d < PBRLAB_DIRECTIONAL_COUNT && pbrlab_d < {TREE_LIGHTS}; pbrlab_d++) {{"]
        if direction:
            towards = to_object.format(v=f"{vec4}(-u_directional_direction[pbrlab_d], 0.0)")
            out.append(f"        _TerrainTreeLightDirections[pbrlab_d] = normalize({towards}.xyz);")
        if colour:
            out.append(f"        _TerrainTreeLightColors[pbrlab_d] = {vec4}(u_directional_radiance[pbrlab_d], 1.0);")
        out += ["    }", "#endif"]
    for name in ("unity_WorldToLight", "_LightMatrix0"):
        if name in filled:
            out += light_space.statements(name, language)
    for name, source in (("_NonJitteredVP", "unity_MatrixVP"), ("_PreviousVP", "unity_MatrixVP"),
                         ("_PreviousM", "unity_ObjectToWorld")):
        if name in filled:
            out.append(f"    {name} = {source};")
    urp = [name for name in URP_LIGHTS if name in filled]
    if urp:
        out.append(f"    for (int pbrlab_l = 0; pbrlab_l < {FILLED[urp[0]][1]}; pbrlab_l++) {{")
        out += [f"        {name}[pbrlab_l] = {URP_LIGHTS[name]}(pbrlab_l);" for name in urp]
        out.append("    }")
    return "".join(line + "\n" for line in out)
