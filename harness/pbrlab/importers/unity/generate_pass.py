"""Write the two stages that run a vertex/fragment pass (``model.VertexFragmentPass``) in
the harness, in HLSL (the program as written) or GLSL (its ``port-unity`` port).

    vertex_text = stage_source(vf, "hlsl", "vertex", program_text, display, defines)

Each stage is the Unity prelude (``generate.prelude``), a ``#line`` to the shader file, the
program, then an entry point of this module's: the vertex entry builds the vertex function's
input from the mesh's attributes by Unity's semantics (POSITION, NORMAL, TANGENT, TEXCOORD0/1 (and 2 for
an object given a realtime GI lightmap: dynamic_lightmaps.py),
COLOR; what a mesh here lacks is 0, and w of POSITION 1), calls it and passes its outputs on
by semantic; the fragment entry rebuilds the fragment function's input from them (SV_POSITION
and VPOS the fragment's window position, VFACE / SV_IsFrontFace its facing) and writes what it
returns to the float target. Outputs are linked to inputs by semantic, as in Unity. The main
light (ForwardBase: the first directional light; none: black; ForwardAdd: the one light the
program draws, its falloff folded in) is in ``_LightColor0`` and ``_WorldSpaceLightPos0`` in
both stages.
"""

from __future__ import annotations

import re

from . import deferred
from . import model as M
from .cg_types import RENAME_PREFIX, is_reserved, ported_function_name
from .engine_inputs import fill_statements
from .written_globals import copy_statements
from .port import port_code_types
from .source_text import UnityShaderError, component_count

# Unity's vertex structs of UnityCG.cginc, by member and semantic (the harness's
# unity_surface.inc declares appdata_full; UnityCG's others are subsets of it here).
UNITY_STRUCTS = {
    "appdata_full": [("float4", "vertex", "POSITION"), ("float4", "tangent", "TANGENT"),
                     ("float3", "normal", "NORMAL"), ("float4", "texcoord", "TEXCOORD0"),
                     ("float4", "texcoord1", "TEXCOORD1"), ("float4", "texcoord2", "TEXCOORD2"),
                     ("float4", "texcoord3", "TEXCOORD3"), ("float4", "color", "COLOR")],
}
UNITY_STRUCTS["appdata_base"] = UNITY_STRUCTS["appdata_full"]
UNITY_STRUCTS["appdata_tan"] = UNITY_STRUCTS["appdata_full"]
# Mesh attributes by semantic: (expression in both languages, components, pad for w). A vertex
# input wider than its stream is filled (0, 0, 0, 1) by the input assembler (Direct3D 11's
# "missing components default to 0, w to 1"; OpenGL 3.3 core 2.8 likewise): a float4 TEXCOORD0
# of Unity's 2-component UVs reads (u, v, 0, 1), a float4 NORMAL (x, y, z, 1).
_VERTEX_FETCH_W = 1.0
_ATTRIBUTES = {
    "POSITION": ("in_position", 3, _VERTEX_FETCH_W), "SV_POSITION": ("in_position", 3, _VERTEX_FETCH_W),
    "NORMAL": ("in_normal", 3, _VERTEX_FETCH_W), "TANGENT": ("in_tangent", 4, 0.0),
    "TEXCOORD0": ("in_uv", 2, _VERTEX_FETCH_W), "TEXCOORD1": ("in_uv1", 2, _VERTEX_FETCH_W),
    "COLOR0": ("in_color", 4, 0.0),
}
_POSITION = ("SV_POSITION", "POSITION")
# TEXCOORD2 (Mesh.uv3; no mesh here has one: 0), or for an object given a realtime GI lightmap
# the realtime lightmap UVs: Unity packs them from uv3, else from uv2 (TEXCOORD1), the lightmap
# UVs here (importers/unity/dynamic_lightmaps.py, which defines PBRLAB_REALTIME_LIGHTMAP_UV).
_REALTIME_LIGHTMAP_UV = "pbrlab_texcoord2"


def _realtime_lightmap_uv(language: str) -> list[str]:
    zero = "float2(0.0, 0.0)" if language == "hlsl" else "vec2(0.0)"
    return ["#ifdef PBRLAB_REALTIME_LIGHTMAP_UV", f"#define {_REALTIME_LIGHTMAP_UV} in_uv1", "#else",
            f"#define {_REALTIME_LIGHTMAP_UV} {zero}", "#endif"]
# System values a vertex function may take (Unity's procedural draws index a buffer by them):
# the index the mesh's index buffer gives the vertex, and the instance's (0: one instance).
_SYSTEM_VALUES = {"SV_VERTEXID": ("pbrlab_vertex_id", "gl_VertexID"),
                  "SV_INSTANCEID": ("pbrlab_instance_id", "gl_InstanceID")}


def canonical(semantic: str) -> str:
    """TEXCOORD -> TEXCOORD0, COLOR -> COLOR0, upper case (Unity's semantics are); POSITION0 ->
    POSITION and SV_POSITION0 -> SV_POSITION: a semantic without an index is index 0 (HLSL's
    semantics documentation), so ``float4 vertex : POSITION0;`` in a v2f is the clip-space
    position, as FXC takes it, and POSITION1 beside it an ordinary interpolator."""
    s = semantic.upper()
    if s in ("TEXCOORD", "COLOR", "SV_TARGET"):
        return s + "0"
    if s in ("POSITION0", "SV_POSITION0"):
        return s[:-1]
    return s


def _vec(n: int, language: str) -> str:
    if n == 1:
        return "float"
    return f"float{n}" if language == "hlsl" else f"vec{n}"


def fit(expr: str, have: int, want: int, language: str, w: float = 0.0) -> str:
    """``expr`` of ``have`` components as ``want`` components: truncated, or padded with 0
    (the last with ``w``: Unity's vertex fetch gives (x, y, 0, 1) for a 2-component UV)."""
    if have == want:
        return expr
    if want < have:
        return f"({expr}).{'xyzw'[:want]}"
    pads = ["0.0"] * (want - have)
    if want == 4:
        pads[-1] = f"{w:.1f}"
    return f"{_vec(want, language)}({expr}, {', '.join(pads)})"


def _struct(vf: M.VertexFragmentPass, name: str):
    if name in vf.structs:
        return vf.structs[name].members
    return UNITY_STRUCTS.get(name)


def colour_output(vf: M.VertexFragmentPass, where: str):
    """The fragment function's SV_Target0 (COLOR0) colour as (its expression in fragment_entry's
    main, its component count): the value it returns, the SV_Target0 member of the struct it
    returns, or its ``out`` SV_Target0 parameter; None where it gives none (a fragment that writes
    only SV_Depth: D3D leaves a render target the pixel shader does not write unchanged)."""
    if vf.fragment_return != "void":
        members = _struct(vf, vf.fragment_return)
        if members is None:
            return ("pbrlab_result", _size(vf.fragment_return, where))
        target = [(t, n) for t, n, s in members if canonical(s) in ("SV_TARGET0", "COLOR0")]
        return (f"pbrlab_result.{target[0][1]}", _size(target[0][0], where)) if target else None
    for qual, kind, name, semantic in vf.fragment_params:
        if qual == "out" and canonical(semantic) in ("SV_TARGET0", "COLOR0"):
            return (f"pbrlab_arg_{name}", _size(kind, where))
    return None


def _size(kind: str, where: str) -> int:
    n = component_count(kind)
    if not n:
        raise UnityShaderError(f"{where}: {kind} cannot pass between the stages here (scalars and "
                               "vectors only)")
    return n


def _zero(kind: str, language: str) -> str:
    n = component_count(kind)
    if n == 1:
        if kind == "bool":
            return "false"  # (GLSL converts no number to a bool)
        return "0" if kind.startswith(("int", "uint")) else "0.0"
    if n:
        return f"{_vec(n, language)}(0.0)" if language == "glsl" else f"({kind})0"
    return None


def _type(kind: str, language: str) -> str:
    """``kind`` as the language names it: the port's GLSL type, a struct of a name GLSL reserves
    renamed as the port renames it (``struct output``: cg_types.is_reserved)."""
    if language == "hlsl":
        return kind
    return RENAME_PREFIX + kind if is_reserved(kind) else port_code_types(kind)


def _declare(kind: str, name: str, language: str) -> list[str]:
    """A local of ``kind``, zeroed."""
    if language == "hlsl":
        return [f"    {kind} {name} = ({kind})0;"]
    return [f"    {_type(kind, language)} {name};"]  # _fill_struct writes every member


def _fill_struct(vf, kind: str, var: str, language: str, value_of) -> list[str]:
    """Assignments of every member of struct ``kind`` in ``var`` from ``value_of(semantic, n)``."""
    members = _struct(vf, kind)
    out = []
    for mtype, mname, semantic in members:
        n = component_count(mtype)
        value = value_of(canonical(semantic), n, mtype) if semantic else None
        if value is None:
            value = _zero(mtype, language)
        if value is not None:
            out.append(f"    {var}.{mname} = {value};")
    return out


def _attribute(semantic: str, n: int, language: str, kind: str = "uint", realtime_uv: bool = False):
    """The mesh attribute of ``semantic`` as ``n`` components, or None (0); ``realtime_uv``: TEXCOORD2
    may be the realtime lightmap UVs (this module's vertex entry defines them)."""
    if semantic in _SYSTEM_VALUES:
        hlsl, glsl = _SYSTEM_VALUES[semantic]
        return f"({kind}){hlsl}" if language == "hlsl" else f"{_type(kind, language)}({glsl})"
    if semantic in _ATTRIBUTES:
        expr, have, w = _ATTRIBUTES[semantic]
        return fit(expr, have, n, language, w)
    if semantic == "TEXCOORD2" and realtime_uv and not kind.removeprefix("min16").startswith(("int", "uint", "bool")):
        # the realtime lightmap UVs where a realtime lightmap is supplied (an integer member: 0; a
        # surface program's vertex input, generate.py, keeps 0: a surface shader takes no realtime
        # lightmap, dynamic_lightmaps.check_reads)
        return fit(_REALTIME_LIGHTMAP_UV, 2, n, language, _VERTEX_FETCH_W)
    return None  # TEXCOORD3..7 and others: no such attribute on meshes here: 0


def _outputs(vf, where: str) -> list[tuple]:
    """[(semantic, type, access)] the vertex stage passes on: members of its output struct,
    out parameters with semantics, or its return value."""
    out = []
    if vf.vertex_return != "void":
        if _struct(vf, vf.vertex_return) is not None:
            out += [(canonical(s), t, f"pbrlab_out.{n}") for t, n, s in _struct(vf, vf.vertex_return) if s]
        elif vf.vertex_return_semantic:
            out.append((canonical(vf.vertex_return_semantic), vf.vertex_return, "pbrlab_out"))
        else:
            raise UnityShaderError(f"{where}: {vf.vertex}() returns {vf.vertex_return} without a semantic")
    for qual, kind, name, semantic in vf.vertex_params:
        if qual == "in":
            continue
        if _struct(vf, kind) is not None:
            out += [(canonical(s), t, f"{name}.{n}") for t, n, s in _struct(vf, kind) if s]
        elif semantic:
            out.append((canonical(semantic), kind, name))
    if not any(s in _POSITION for s, _, _ in out) and vf.geometry is None and vf.tessellation is None:
        # (a geometry or domain stage may place them)
        empty = "" if out or vf.vertex_return != "void" or any(q != "in" for q, *_ in vf.vertex_params) else (
            f" ({vf.vertex}() returns void and has no out parameter: it writes nothing, so no vertex is "
            "placed and the pass draws nothing)")
        raise UnityShaderError(f"{where}: {vf.vertex}() writes no SV_POSITION: the vertex stage must "
                               "give the clip-space position" + empty)
    return out


def _main_light(language: str) -> str:
    """The pass's light in _LightColor0 / _WorldSpaceLightPos0: a ForwardAdd program's one
    light (PBRLAB_UNITY_ADD_DIRECTIONAL / _POINT / _SPOT: its index; a positional light's
    falloff, and a spot's cone, at the point pbrlab_world_position, folded into the colour as
    for surface programs, so LIGHT_ATTENUATION is 1), else the first directional light."""
    return """    #if defined(PBRLAB_UNITY_ADD_POINT)
    UnityLight pbrlab_light = pbrlab_positional_light(u_point_position[PBRLAB_UNITY_ADD_POINT],
        u_point_radiance[PBRLAB_UNITY_ADD_POINT], u_point_range[PBRLAB_UNITY_ADD_POINT], pbrlab_world_position);
    _LightColor0 = vec4(pbrlab_light.color, 1.0);
    _WorldSpaceLightPos0 = vec4(u_point_position[PBRLAB_UNITY_ADD_POINT], 1.0);
    #elif defined(PBRLAB_UNITY_ADD_SPOT)
    UnityLight pbrlab_light = pbrlab_positional_light(u_spot_position[PBRLAB_UNITY_ADD_SPOT],
        u_spot_radiance[PBRLAB_UNITY_ADD_SPOT], u_spot_range[PBRLAB_UNITY_ADD_SPOT], pbrlab_world_position);
    pbrlab_light.color *= pbr_spot_attenuation(pbrlab_light.dir, u_spot_direction[PBRLAB_UNITY_ADD_SPOT],
        u_spot_cone[PBRLAB_UNITY_ADD_SPOT].x, u_spot_cone[PBRLAB_UNITY_ADD_SPOT].y);
    _LightColor0 = vec4(pbrlab_light.color, 1.0);
    _WorldSpaceLightPos0 = vec4(u_spot_position[PBRLAB_UNITY_ADD_SPOT], 1.0);
    #elif defined(PBRLAB_UNITY_ADD_DIRECTIONAL)
    _LightColor0 = vec4(u_directional_radiance[PBRLAB_UNITY_ADD_DIRECTIONAL], 1.0);
    _WorldSpaceLightPos0 = vec4(-u_directional_direction[PBRLAB_UNITY_ADD_DIRECTIONAL], 0.0);
    #elif PBRLAB_DIRECTIONAL_COUNT > 0
    _LightColor0 = vec4(u_directional_radiance[0], 1.0);
    _WorldSpaceLightPos0 = vec4(-u_directional_direction[0], 0.0);
    #else
    _LightColor0 = vec4(0.0, 0.0, 0.0, 0.0);
    _WorldSpaceLightPos0 = vec4(0.0, 0.0, 1.0, 0.0);
    #endif
""".replace("vec4", "float4" if language == "hlsl" else "vec4")


# Unity's vertex lights (a Vertex pass: legacy vertex-lit rendering, and fixed-function passes,
# fixed_function.py): up to 8, directional first, in view space as Unity sets them
# (unity_LightPosition: the direction to a directional light, w 0; a positional light's
# position, w 1). A positional light's falloff (and a spot's cone) is the harness's, at the mesh
# vertex, folded into unity_LightColor as for ForwardAdd programs (_main_light): its
# unity_LightAtten is then (-1, 1, 0, 3e38), no further falloff, cone or range. Other passes
# see 8 black lights (Unity: "Always: no lighting is applied").
VERTEX_LIGHTS = 8


def _vertex_lights(language: str) -> str:
    def view(v: str) -> str:
        return f"mul(unity_MatrixV, {v}).xyz" if language == "hlsl" else f"(unity_MatrixV * {v}).xyz"
    lines = ["    for (int pbrlab_i = 0; pbrlab_i < 8; pbrlab_i++) {",
             "        unity_LightColor[pbrlab_i] = vec4(0.0, 0.0, 0.0, 0.0);",
             "        unity_LightPosition[pbrlab_i] = vec4(0.0, 0.0, 1.0, 0.0);",
             "        unity_LightAtten[pbrlab_i] = vec4(-1.0, 1.0, 0.0, 3.0e38);",
             "        unity_SpotDirection[pbrlab_i] = vec4(0.0, 0.0, 1.0, 0.0);",
             "    }",
             "#if defined(PBRLAB_UNITY_VERTEX_LIGHTS)",
             f"    vec3 pbrlab_vl_world = {_world_position(language)};",
             "    int pbrlab_n = 0;",
             "#if PBRLAB_DIRECTIONAL_COUNT > 0",
             "    for (int pbrlab_d = 0; pbrlab_d < PBRLAB_DIRECTIONAL_COUNT && pbrlab_n < 8; pbrlab_d++, pbrlab_n++) {",
             "        unity_LightColor[pbrlab_n] = vec4(u_directional_radiance[pbrlab_d], 1.0);",
             f"        unity_LightPosition[pbrlab_n] = vec4({view('vec4(-u_directional_direction[pbrlab_d], 0.0)')}, 0.0);",
             "    }",
             "#endif"]
    for kind in ("point", "spot"):
        upper = kind.upper()
        lines += [f"#if PBRLAB_{upper}_COUNT > 0",
                  f"    for (int pbrlab_p = 0; pbrlab_p < PBRLAB_{upper}_COUNT && pbrlab_n < 8; pbrlab_p++, pbrlab_n++) {{",
                  f"        UnityLight pbrlab_vl = pbrlab_positional_light(u_{kind}_position[pbrlab_p], "
                  f"u_{kind}_radiance[pbrlab_p], u_{kind}_range[pbrlab_p], pbrlab_vl_world);"]
        if kind == "spot":
            lines.append("        pbrlab_vl.color *= pbr_spot_attenuation(pbrlab_vl.dir, u_spot_direction[pbrlab_p], "
                         "u_spot_cone[pbrlab_p].x, u_spot_cone[pbrlab_p].y);")
        lines += ["        unity_LightColor[pbrlab_n] = vec4(pbrlab_vl.color, 1.0);",
                  f"        unity_LightPosition[pbrlab_n] = vec4({view(f'vec4(u_{kind}_position[pbrlab_p], 1.0)')}, 1.0);",
                  "    }", "#endif"]
    lines.append("#endif")
    return _statements(lines, language)


# The forward path's four per-vertex point lights (UnityShaderVariables.cginc's unity_4LightPosX0 /
# Y0 / Z0, unity_4LightAtten0 and unity_LightColor[0..3], read by Shade4PointLights), set in both
# stages of a ForwardBase program. Unity's forward path ("Per-pixel and per-vertex lights"): the
# brightest directional light is the base pass's pixel light; other lights are per-pixel, drawn
# by the ForwardAdd pass, up to the Pixel Light Count, and the next four point lights are vertex
# lights. pbrlab draws a ForwardAdd pass once for every other light (material.light_programs), so
# where the shader has one no point light is left to the vertex lights (all zero); where it has
# none (PBRLAB_UNITY_FOUR_LIGHTS), Unity cannot draw its point lights per pixel and gives the base
# pass the first four: pbrlab's point lights, then its spot lights (as points: Shade4PointLights
# has no cone), in the scene's order (Unity's ranks them by their brightness at the object).
# Colour: the light's colour times intensity (pbrlab's radiance), as Unity's unity_LightColor;
# attenuation: Unity's 25 / range^2 (the quadratic term of its vertex-light falloff, so that a
# light at its range is 1/26 of its colour); a light without a range (range +inf) gets 1, so
# 1 / (1 + d^2): the inverse square of pbrlab's unbounded lights, kept finite at the light.
FOUR_LIGHTS = 4


def _four_lights(language: str) -> str:
    lines = ["    unity_4LightPosX0 = vec4(0.0, 0.0, 0.0, 0.0);",
             "    unity_4LightPosY0 = vec4(0.0, 0.0, 0.0, 0.0);",
             "    unity_4LightPosZ0 = vec4(0.0, 0.0, 0.0, 0.0);",
             "    unity_4LightAtten0 = vec4(0.0, 0.0, 0.0, 0.0);",
             "#if !defined(PBRLAB_UNITY_VERTEX_LIGHTS)",  # (a Vertex pass's vertex stage has set its own)
             f"    for (int pbrlab_c = 0; pbrlab_c < {FOUR_LIGHTS}; pbrlab_c++) {{ unity_LightColor[pbrlab_c] = vec4(0.0, 0.0, 0.0, 0.0); }}",
             "#endif",
             "#if defined(PBRLAB_UNITY_FOUR_LIGHTS)",
             "    int pbrlab_f = 0;"]
    for kind in ("point", "spot"):
        lines += [f"#if PBRLAB_{kind.upper()}_COUNT > 0",
                  f"    for (int pbrlab_q = 0; pbrlab_q < PBRLAB_{kind.upper()}_COUNT && pbrlab_f < {FOUR_LIGHTS}; pbrlab_q++, pbrlab_f++) {{",
                  f"        vec3 pbrlab_at = u_{kind}_position[pbrlab_q];",
                  f"        float pbrlab_r = u_{kind}_range[pbrlab_q];",
                  "        unity_4LightPosX0[pbrlab_f] = pbrlab_at.x;",
                  "        unity_4LightPosY0[pbrlab_f] = pbrlab_at.y;",
                  "        unity_4LightPosZ0[pbrlab_f] = pbrlab_at.z;",
                  "        unity_4LightAtten0[pbrlab_f] = pbrlab_r > 0.0 && pbrlab_r < 3.0e38 ? 25.0 / (pbrlab_r * pbrlab_r) : 1.0;",
                  f"        unity_LightColor[pbrlab_f] = vec4(u_{kind}_radiance[pbrlab_q], 1.0);",
                  "    }", "#endif"]
    lines.append("#endif")
    return _statements(lines, language)


def _statements(lines: list, language: str) -> str:
    """Lines written with GLSL's vector names, in ``language``."""
    text = "\n".join(lines) + "\n"
    return re.sub(r"\bvec([234])\b", r"float\1", text) if language == "hlsl" else text


# A positional ForwardAdd light is evaluated at the surface point: the vertex stage hands the
# mesh vertex's world position (before the pass's vertex function moves it) to the fragment.
_POSITIONAL_ADD = "#if defined(PBRLAB_UNITY_ADD_POINT) || defined(PBRLAB_UNITY_ADD_SPOT)"


def _world_position(language: str) -> str:
    if language == "hlsl":
        return "mul(unity_ObjectToWorld, float4(in_position, 1.0)).xyz"
    return "(unity_ObjectToWorld * vec4(in_position, 1.0)).xyz"


def varyings(vf, where: str) -> list[tuple]:
    """[(semantic, type)] passed from the vertex to the fragment stage (not the position)."""
    return [(s, t) for s, t, _ in _outputs(vf, where) if s not in _POSITION]


_MATRIX = re.compile(r"(?:float|half|fixed|min16float|real)([234])x([234])")


def _slots(vf, where: str, language: str) -> list[tuple]:
    """[(semantic, slot name, slot type, part)]: the varyings as the stages pass them, one
    location each. A matrix (``float3x3 tbn : TEXCOORD4``) passes as its vectors, as Unity's
    compilers do (a floatRxC takes R registers): in HLSL its R rows, in GLSL (which indexes
    columns: the port's matCxR) its C columns; ``part`` is the vector's index, None for a
    scalar or vector varying, which passes whole. Interpolating each vector interpolates each
    element, so either split gives the fragment the same matrix."""
    out = []
    for s, kind in varyings(vf, where):
        m = _MATRIX.fullmatch(kind)
        if m is None:
            out.append((s, f"pbrlab_vary_{s}", kind, None))
            continue
        rows, cols = int(m.group(1)), int(m.group(2))
        count, size = (rows, cols) if language == "hlsl" else (cols, rows)
        out += [(s, f"pbrlab_vary_{s}_{k}", f"float{size}", k) for k in range(count)]
    return out


def _matrix_varying(slots, semantic: str, kind: str, language: str) -> str:
    """The fragment's matrix rebuilt from its vectors (_slots): HLSL's constructor takes rows,
    GLSL's columns, as each language passed them."""
    parts = ", ".join(name for s, name, _, part in slots if s == semantic)
    return f"{_type(kind, language)}({parts})"


def vertex_entry(vf: M.VertexFragmentPass, language: str, where: str) -> str:
    outs = _outputs(vf, where)
    vec3 = "float3" if language == "hlsl" else "vec3"
    body = [_POSITIONAL_ADD, f"    {vec3} pbrlab_world_position = {_world_position(language)};",
            "    pbrlab_vary_world_position = pbrlab_world_position;", "#endif", _main_light(language),
            _vertex_lights(language), _four_lights(language), fill_statements(vf.engine_filled, language),
            copy_statements(vf.written_globals)]
    args = []
    for qual, kind, name, semantic in vf.vertex_params:
        local = f"pbrlab_arg_{name}"
        if _struct(vf, kind) is not None:
            body += _declare(kind, local, language)
            if qual != "out":
                body += _fill_struct(vf, kind, local, language, lambda s, n, t: _attribute(s, n, language, t, True))
        else:
            n = _size(kind, where)
            body.append(f"    {_type(kind, language)} {local} = "
                        f"{(_attribute(canonical(semantic), n, language, kind, True) if qual != 'out' else None) or _zero(kind, language)};")
        args.append(local)
    call = f"{ported_function_name(vf.vertex, language)}({', '.join(args)})"
    if vf.vertex_return != "void":
        body.append(f"    {_type(vf.vertex_return, language)} pbrlab_out = {call};")
    else:
        body.append(f"    {call};")
    access = {}
    for semantic, kind, expr in outs:
        expr = re.sub(r"^(\w+)\.", lambda m: f"pbrlab_arg_{m.group(1)}." if m.group(1) != "pbrlab_out" else m.group(0), expr)
        if "." not in expr and expr != "pbrlab_out":
            expr = f"pbrlab_arg_{expr}"
        access[semantic] = (kind, expr)
    pos_kind, pos_expr = next((access[s] for s in _POSITION if s in access), ("float4", None))
    position = fit(pos_expr, _size(pos_kind, where), 4, language, 1.0) if pos_expr else f"{_vec(4, language)}(0.0, 0.0, 0.0, 1.0)"
    lines = []
    slots = _slots(vf, where, language)
    if language == "hlsl":
        params = ["float3 in_position : POSITION", "float3 in_normal : NORMAL", "float2 in_uv : TEXCOORD0",
                  "float4 in_tangent : TANGENT", "float2 in_uv1 : TEXCOORD1", "float4 in_color : COLOR0",
                  "uint pbrlab_vertex_id : SV_VertexID", "uint pbrlab_instance_id : SV_InstanceID",
                  "out float4 pbrlab_clip : SV_Position"]
        # an integer varying is flat on both sides (HLSL's nointerpolation; the fragment side's
        # integer input is flat already, and a linker refuses a mismatch)
        params += [f"{'nointerpolation ' if _flat(kind, s, vf) else ''}out {kind} {name} : TEXCOORD{i}"
                   for i, (s, name, kind, _) in enumerate(slots)]
        lines += _realtime_lightmap_uv(language)
        lines += ["void main(" + ", ".join(params), _POSITIONAL_ADD,
                  f", out float3 pbrlab_vary_world_position : TEXCOORD{len(slots)}", "#endif", ") {"]
        body.append(f"    pbrlab_clip = {position};")
    else:
        lines += ["in vec3 in_position;", "in vec3 in_normal;", "in vec2 in_uv;", "in vec4 in_tangent;",
                  "in vec2 in_uv1;", "in vec4 in_color;"] + _realtime_lightmap_uv(language)
        lines += [f"{_flat(kind, s, vf)}out {_type(kind, language)} {name};" for s, name, kind, _ in slots]
        lines += [_POSITIONAL_ADD, "out vec3 pbrlab_vary_world_position;", "#endif", "void main() {"]
        body.append(f"    gl_Position = {position};")
    for s, name, kind, part in slots:
        body.append(f"    {name} = {access[s][1]}{'' if part is None else f'[{part}]'};")
    return "\n".join(lines + body + ["}"]) + "\n" if language == "hlsl" else _members_as_ported(
        "\n".join(lines + body + ["}"]) + "\n")


def _flat(kind: str, semantic: str = "", vf=None) -> str:
    """"flat " for an integer varying (flat in both languages), or one the program's struct
    declares ``nointerpolation`` (HLSL's flat: each triangle takes its provoking vertex's)."""
    if kind.startswith(("int", "uint", "bool")):
        return "flat "
    if vf is not None and semantic and any(
            canonical(sem) == semantic for struct in vf.structs.values() for _, name, sem in struct.members
            if name in struct.flat):
        return "flat "
    return ""


# A pixel shader's SV_Position.w is the clip-space w (the eye depth, in a perspective view) in
# Direct3D, Unity's default API; GLSL's gl_FragCoord.w, and glslang's SV_Position taken from it,
# is 1 / w (GLSL 4.60 7.1.2; DXC's -fvk-use-dx-position-w and glslang's --hlsl-dx-position-w
# exist for this difference). A program that reads i.pos.w in its fragment (ComputeScreenPos(i.pos),
# a depth fade's eye depth) reads w, as in Unity; x, y (the pixel centre) and z (window depth) as were.
_CLIP_W = "1.0 / pbrlab_frag_position.w"


def fragment_entry(vf: M.VertexFragmentPass, language: str, where: str, blended: bool) -> str:
    have = {s: t for s, t in varyings(vf, where)}
    slots = _slots(vf, where, language)

    def value(semantic: str, n: int, kind: str):
        if semantic in _POSITION or semantic == "VPOS":
            return fit("pbrlab_frag_position", 4, n, language)
        if semantic in ("VFACE", "SV_ISFRONTFACE"):
            if kind.startswith("bool"):
                return "pbrlab_front_facing"
            if kind.startswith(("uint", "int")):  # ``uint f : SV_IsFrontFace``: the bool converted
                # (HLSL's bool -> uint is 1 or 0, as glslang's HLSL path gives it)
                return f"{'int' if kind.startswith('int') else 'uint'}(pbrlab_front_facing)"
            return "(pbrlab_front_facing ? 1.0 : -1.0)"
        if semantic == "SV_PRIMITIVEID":  # the triangle's index in the draw (GLSL's gl_PrimitiveID)
            return f"{'int' if kind.startswith('int') else 'uint'}(pbrlab_primitive_id)"
        if semantic in have and _MATRIX.fullmatch(have[semantic]):
            if _MATRIX.fullmatch(kind) is None or _MATRIX.fullmatch(kind).groups() != _MATRIX.fullmatch(have[semantic]).groups():
                raise UnityShaderError(f"{where}: the fragment reads {semantic} as {kind}, the vertex stage "
                                       f"writes it as {have[semantic]}")
            return _matrix_varying(slots, semantic, kind, language)
        if semantic in have:
            return fit(f"pbrlab_vary_{semantic}", _size(have[semantic], where), n, language)
        return None

    vec3 = "float3" if language == "hlsl" else "vec3"
    body = [_POSITIONAL_ADD, f"    {vec3} pbrlab_world_position = pbrlab_vary_world_position;", "#endif",
            _main_light(language), _four_lights(language), deferred.light_assignments(language),
            fill_statements(vf.engine_filled, language),
            copy_statements(vf.written_globals)]
    args = []
    for qual, kind, name, semantic in vf.fragment_params:
        local = f"pbrlab_arg_{name}"
        if _struct(vf, kind) is not None:
            body += _declare(kind, local, language)
            body += _fill_struct(vf, kind, local, language, value)
        elif qual == "out":
            body.append(f"    {_type(kind, language)} {local};")
        else:
            filled = value(canonical(semantic), component_count(kind) or 4, kind) or _zero(kind, language)
            if filled is None:  # neither a struct nor a vector (a type no signature resolved): never "None"
                raise UnityShaderError(f"{where}: {vf.fragment}() takes {name} of type {kind}, which is neither "
                                       "a struct the program defines nor a scalar, vector or matrix")
            body.append(f"    {_type(kind, language)} {local} = {filled};")
        args.append(local)
    call = f"{ported_function_name(vf.fragment, language)}({', '.join(args)})"
    if vf.fragment_return != "void":
        body.append(f"    {_type(vf.fragment_return, language)} pbrlab_result = {call};")
    else:
        body.append(f"    {call};")
    colour = colour_output(vf, where)
    if colour is None and vf.state.color_mask.strip() == "0":
        colour = (_zero("float4", language), 4)   # a depth-only fragment: ColorMask 0 (parse.py) discards it
    if colour is None:
        raise UnityShaderError(f"{where}: {vf.fragment}() gives no SV_Target colour")
    c = fit(colour[0], colour[1], 4, language, 1.0)
    alpha = "pbrlab_c.a" if blended else "1.0"
    vec4 = "float4" if language == "hlsl" else "vec4"
    body += [f"    {vec4} pbrlab_c = {c};",
             f"    pbrlab_radiance = {vec4}(pbrlab_target_radiance(pbrlab_c.rgb), {alpha});"]
    lines = []
    reads_primitive_id = any(canonical(semantic) == "SV_PRIMITIVEID" for _, _, _, semantic in vf.fragment_params)
    if language == "hlsl":
        params = ["float4 pbrlab_frag_position : SV_Position", "bool pbrlab_front_facing : SV_IsFrontFace"]
        params += ["uint pbrlab_primitive_id : SV_PrimitiveID"] * reads_primitive_id
        params += [f"{'nointerpolation ' if _flat(kind, s, vf) and not _flat(kind) else ''}{kind} {name} : TEXCOORD{i}"
                   for i, (s, name, kind, _) in enumerate(slots)]
        params.append("out float4 pbrlab_radiance : SV_Target0")
        lines += _realtime_lightmap_uv(language)
        lines += ["void main(" + ", ".join(params), _POSITIONAL_ADD,
                  f", float3 pbrlab_vary_world_position : TEXCOORD{len(slots)}", "#endif", ") {",
                  f"    pbrlab_frag_position.w = {_CLIP_W};"]
    else:
        lines += [f"{_flat(kind, s, vf)}in {_type(kind, language)} {name};" for s, name, kind, _ in slots]
        lines += [_POSITIONAL_ADD, "in vec3 pbrlab_vary_world_position;", "#endif"]
        lines += ["out vec4 pbrlab_radiance;", "void main() {",
                  f"    vec4 pbrlab_frag_position = vec4(gl_FragCoord.xyz, {_CLIP_W.replace('pbrlab_frag_position', 'gl_FragCoord')});",
                  "    bool pbrlab_front_facing = gl_FrontFacing;"]
        lines += ["    int pbrlab_primitive_id = gl_PrimitiveID;"] * reads_primitive_id
        return _members_as_ported("\n".join(lines + body + ["}"]) + "\n")
    return "\n".join(lines + body + ["}"]) + "\n"


_MEMBER = re.compile(r"\.([A-Za-z_]\w*)\b")


def _members_as_ported(glsl: str) -> str:
    """The GLSL entry's reads and writes of the program's struct members, named as the port
    names them (cg_types.is_reserved: ``gl_Position``, ``sample`` -> pbr_unity_...)."""
    return _MEMBER.sub(lambda m: "." + (RENAME_PREFIX + m.group(1) if is_reserved(m.group(1)) else m.group(1)), glsl)
