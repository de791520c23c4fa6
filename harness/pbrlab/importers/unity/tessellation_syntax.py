"""HLSL's tessellation syntax as a Unity program writes it (``#pragma hull H`` /
``#pragma domain D``), read without compiling:

    t = parse_tessellation(text, "Hull", "Domain", where, hull_offset)  # parse_pass: vf.tessellation
    text = spell_for_glsl(text)                                        # the syntax in Cg the port reads

The hull function carries its attributes (Microsoft's HLSL reference, "Hull Shader Stage" /
"Tessellator Stage"): ``[domain("tri"|"quad")]``, ``[outputcontrolpoints(N)]``,
``[outputtopology("triangle_cw"|"triangle_ccw")]``, ``[partitioning("integer"|"fractional_odd"|
"fractional_even"|"pow2")]``, ``[patchconstantfunc("PC")]``; it takes ``InputPatch<T, N>`` and
``uint : SV_OutputControlPointID`` (and ``uint : SV_PrimitiveID``), the patch-constant function
the input patch (and the primitive id) and returns a struct whose ``SV_TessFactor`` /
``SV_InsideTessFactor`` members are the tessellation levels; the domain function takes that
struct, ``OutputPatch<T, N>`` and ``float3 (tri) / float2 (quad) : SV_DomainLocation``.

``spell_for_glsl`` blanks the attributes and spells ``InputPatch<T, N> p`` / ``OutputPatch<T, N>
p`` as the array ``T p[N]`` (line for line). What the stages do with them: tessellation_stage.py.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from .geometry_syntax import _split_params  # (a parameter list split at its top-level commas)
from .source_text import IDENT, UnityShaderError

# D3D11's partitioning modes and the GLSL spacing each one is (GLSL 4.00 section 4.3.8.1 /
# OpenGL 4.0 section 2.12.2: equal_spacing rounds a level up to an integer, as D3D's integer
# partitioning; the fractional modes are defined alike in both). pow2 has no GL spacing.
SPACINGS = {"integer": "equal_spacing", "fractional_odd": "fractional_odd_spacing",
            "fractional_even": "fractional_even_spacing"}
# [domain(...)] -> (GLSL primitive mode, outer level count, inner level count, domain location size)
DOMAINS = {"tri": ("triangles", 3, 1, 3), "quad": ("quads", 4, 2, 2)}
# [outputtopology(...)] -> GLSL vertex order. Unity's tessellation shaders write triangle_cw with
# Cull Back and the barycentric domain p = u p0 + v p1 + w p2, and draw their meshes' front faces:
# triangle_cw keeps a patch's winding (D3D's front faces are clockwise). pbrlab draws Unity's
# meshes with GL's counter-clockwise front faces, so triangle_cw is GL's ccw (which keeps the
# patch's winding here; measured: a level-1 patch under Cull Back covers what the untessellated
# triangle does, tests/importers/unity/test_tessellation_stages.py) and triangle_ccw is cw.
# (glslang writes SPIR-V's VertexOrderCw for triangle_cw, but spirv-cross drops the order with
# the spacing: the evaluation stage's layout is written here in both languages.)
ORDERS = {"triangle_cw": "ccw", "triangle_ccw": "cw"}

# (UNITY_domain etc.: Unity's HLSLSupport.cginc names for the same attributes, written by shaders
# that define them as the plain ones)
_ATTRIBUTE = re.compile(r"\[\s*(?:UNITY_)?(domain|outputcontrolpoints|outputtopology|partitioning|patchconstantfunc|"
                        r"maxtessfactor)\s*\(\s*([^()\]]*?)\s*\)\s*\]")
_PATCH = re.compile(r"\b(?:const\s+)?(InputPatch|OutputPatch)\s*<\s*(" + IDENT + r")\s*,\s*(\w+)\s*>\s*(" + IDENT + r")")


@dataclass
class Tessellation:
    hull: str                   # the hull function
    domain_function: str        # the domain function
    control_type: str           # the input patch's struct (the vertex stage's output)
    patch_size: int             # N of InputPatch<T, N>: GL_PATCH_VERTICES
    output_type: str            # the hull's return struct (a control point)
    output_points: int          # [outputcontrolpoints(N)]
    domain: str                 # tri, quad
    spacing: str                # GLSL spacing
    order: str                  # cw, ccw
    constant: str               # the patch-constant function
    factors_type: str           # its return struct
    outer: list                 # [(member, index or None)] -> gl_TessLevelOuter[i]
    inner: list                 # -> gl_TessLevelInner[i]
    hull_params: list           # [(role, type)]: patch, control_point_id, primitive_id
    constant_params: list       # [(role, type)]: patch, primitive_id
    domain_params: list         # [(role, type)]: factors, patch, location
    partitioning: str           # as written (integer, fractional_odd, fractional_even)
    topology: str               # as written (triangle_cw, triangle_ccw)
    domain_return: str          # the domain function's output struct
    where: str
    dimension: int = 3          # the domain location's components (DOMAINS)


def _blank(text: str) -> str:
    return re.sub(r"[^\n]", " ", text)


def spell_for_glsl(text: str) -> str:
    """The tessellation syntax of HLSL in ``text`` spelled in Cg for the GLSL port (module
    docstring), line for line; a text without it unchanged."""
    if "Patch" not in text and "outputcontrolpoints" not in text:
        return text
    text = _ATTRIBUTE.sub(lambda m: _blank(m.group(0)), text)
    return _PATCH.sub(lambda m: f"{m.group(2)} {m.group(4)}[{m.group(3)}]", text)


def _expanded(value: str, before: str) -> str:
    """An attribute's argument with the object-like macros the text ``before`` the hull function
    defines expanded (``#define PARTITION_METHOD "fractional_odd"`` then
    ``[partitioning(PARTITION_METHOD)]``: FXC and glslang preprocess the attribute's argument as
    any other tokens, the Catlike Coding tessellation tutorial's spelling); its last definition
    before the function wins, as the preprocessor's would (its ``#undef`` is not followed)."""
    for _ in range(8):  # (a macro naming another)
        if not re.fullmatch(IDENT, value):
            break
        found = re.findall(r"^[ \t]*#[ \t]*define[ \t]+" + re.escape(value) + r"[ \t]+([^\n]*?)[ \t]*$", before, re.M)
        if not found or not found[-1]:
            break
        value = found[-1]
    return value


def _function(masked: str, name: str, where: str, pragma: str):
    """(return type, [parameter texts], offset of the attributes' start) of ``name``."""
    m = re.search(r"\b(" + IDENT + r")\s+" + re.escape(name) + r"\s*\(", masked)
    if m is None:
        raise UnityShaderError(f"{where}: #pragma {pragma} {name}: no function {name}(...) is defined")
    depth, i = 1, m.end()
    while i < len(masked) and depth:
        depth += {"(": 1, ")": -1}.get(masked[i], 0)
        i += 1
    return m.group(1), _split_params(masked[m.end():i - 1]), m.start()


def _roles(name: str, params: list, allowed: dict, where: str) -> tuple[list, dict]:
    roles, found = [], {}
    for text in params:
        patch = _PATCH.search(text)
        semantic = re.search(r":\s*(\w+)\s*$", text)
        role = None
        if patch and patch.group(1) in allowed:
            role = allowed[patch.group(1)]
            found[role] = patch.groups()
        elif semantic and semantic.group(1).upper() in allowed:
            role = allowed[semantic.group(1).upper()]
        elif "struct" in allowed and re.fullmatch(r"(?:in\s+)?" + IDENT + r"\s+" + IDENT, text):
            role = allowed["struct"]
            found[role] = text.split()[-2]
        if role is None:
            raise UnityShaderError(f"{where}: {name}(): the parameter {text!r} is not one pbrlab runs "
                                   f"(it takes {', '.join(k for k in allowed if k != 'struct')})")
        roles.append((role, re.match(r"(?:(?:in|const)\s+)*(\w+)", text).group(1)))
    return roles, found


def _levels(factors: list, semantic: str) -> list:
    """[(member, index)] of the struct members carrying ``semantic`` (an array: one per element)."""
    out = []
    for kind, member, sem in factors:
        if sem.upper().rstrip("0123456789") != semantic:
            continue
        array = re.fullmatch(r"(\w+)\[(\d+)\]", member)
        if array:  # (parse_pass._structs expands a semantic'd array into its elements)
            out.append((array.group(1), int(array.group(2))))
        else:
            n = {"float": 1, "half": 1, "float2": 2, "float3": 3, "float4": 4}.get(kind, 1)
            out += [(member, None)] if n == 1 else [(member, "xyzw"[k]) for k in range(n)]
    return out


def parse_tessellation(masked: str, hull: str, domain: str, structs: dict, where_of, offsets) -> Tessellation:
    """The hull and domain functions of ``masked`` (the program and its includes, comments
    blanked, the drawn variant's branches); ``structs``: parse_pass._structs of it;
    ``offsets``: the two pragmas' offsets in the program."""
    where = where_of(offsets[0])
    out_type, params, start = _function(masked, hull, where, "hull")
    where = where_of(start)  # (the hull function's line: its attributes and parameters)
    head = masked[:start]
    attrs = {}
    # the attributes written before the function (after the previous declaration's end)
    prefix = head[max(head.rfind(";"), head.rfind("}")) + 1:]
    for m in _ATTRIBUTE.finditer(prefix):
        attrs[m.group(1)] = _expanded(m.group(2).strip(), head).strip('"')
    for needed in ("domain", "outputcontrolpoints", "partitioning", "outputtopology", "patchconstantfunc"):
        if needed not in attrs:
            raise UnityShaderError(f"{where}: #pragma hull {hull}: {hull}() has no [{needed}(...)] attribute "
                                   "(HLSL requires it on a hull function)")
    if attrs["domain"] not in DOMAINS:
        raise UnityShaderError(f"{where}: {hull}(): [domain(\"{attrs['domain']}\")]: pbrlab tessellates "
                               "tri and quad domains (an isoline domain draws lines)")
    if attrs["partitioning"] not in SPACINGS:
        raise UnityShaderError(f"{where}: {hull}(): [partitioning(\"{attrs['partitioning']}\")]: pbrlab runs "
                               "integer, fractional_odd and fractional_even partitioning (GL has no pow2)")
    if attrs["outputtopology"] not in ORDERS:
        raise UnityShaderError(f"{where}: {hull}(): [outputtopology(\"{attrs['outputtopology']}\")]: pbrlab "
                               "draws triangle_cw and triangle_ccw output")
    hull_roles, found = _roles(hull, params, {"InputPatch": "patch", "SV_OUTPUTCONTROLPOINTID": "control_point_id",
                                              "SV_PRIMITIVEID": "primitive_id"}, where)
    if "patch" not in found:
        raise UnityShaderError(f"{where}: {hull}() takes no InputPatch<T, N>")
    control_type, size = found["patch"][1], found["patch"][2]
    points = attrs["outputcontrolpoints"]
    if not (size.isdigit() and points.isdigit()) or not 1 <= int(size) <= 32:
        raise UnityShaderError(f"{where}: {hull}(): InputPatch<{control_type}, {size}> / "
                               f"[outputcontrolpoints({points})]: pbrlab needs literal counts of 1 to 32")
    if int(size) != 3:  # the harness draws triangle meshes: each patch is one triangle
        raise UnityShaderError(f"{where}: {hull}(): InputPatch<{control_type}, {size}>: pbrlab draws triangle "
                               "meshes, so each patch is a triangle's 3 vertices")
    if int(points) != int(size):
        raise UnityShaderError(f"{where}: {hull}(): [outputcontrolpoints({points})] differs from its "
                               f"InputPatch<{control_type}, {size}>: pbrlab runs hull functions that give one "
                               "control point per input vertex")
    constant = attrs["patchconstantfunc"]
    factors_type, cparams, _ = _function(masked, constant, where, f"hull {hull}: [patchconstantfunc]")
    constant_roles, _ = _roles(constant, cparams, {"InputPatch": "patch", "SV_PRIMITIVEID": "primitive_id"}, where)
    if factors_type not in structs:
        raise UnityShaderError(f"{where}: {constant}() returns {factors_type}, not a struct of "
                               "SV_TessFactor / SV_InsideTessFactor members")
    members = structs[factors_type].members
    outer, inner = _levels(members, "SV_TESSFACTOR"), _levels(members, "SV_INSIDETESSFACTOR")
    _, n_outer, n_inner, _ = DOMAINS[attrs["domain"]]
    if len(outer) != n_outer or len(inner) != n_inner:
        raise UnityShaderError(f"{where}: {factors_type}: a {attrs['domain']} domain takes {n_outer} SV_TessFactor "
                               f"and {n_inner} SV_InsideTessFactor values ({len(outer)} and {len(inner)} here)")
    dwhere = where_of(offsets[1])
    domain_return, dparams, _ = _function(masked, domain, dwhere, "domain")
    domain_roles, _ = _roles(domain, dparams, {"OutputPatch": "patch", "SV_DOMAINLOCATION": "location",
                                               "struct": "factors"}, dwhere)
    if domain_return not in structs:
        raise UnityShaderError(f"{dwhere}: {domain}() returns {domain_return}: pbrlab runs a domain function "
                               "returning a struct with an SV_POSITION member")
    return Tessellation(hull=hull, domain_function=domain, control_type=control_type, patch_size=int(size),
                        output_type=out_type, output_points=int(points), domain=attrs["domain"],
                        spacing=SPACINGS[attrs["partitioning"]], order=ORDERS[attrs["outputtopology"]],
                        partitioning=attrs["partitioning"], topology=attrs["outputtopology"],
                        constant=constant, factors_type=factors_type, outer=outer, inner=inner,
                        hull_params=hull_roles, constant_params=constant_roles, domain_params=domain_roles,
                        domain_return=domain_return, where=where,
                        dimension=DOMAINS[attrs["domain"]][3])
