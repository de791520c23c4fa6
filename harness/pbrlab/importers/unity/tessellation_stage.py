"""A vertex/fragment pass's tessellation stages (``#pragma hull H`` / ``#pragma domain D``) run
between its vertex and fragment stages, in both languages; each mesh triangle is one patch
(drawn as GL_PATCHES of 3 vertices: ``PATCH_VERTICES``).

    t = parse_tessellation(...)                                  # parse_pass: vf.tessellation
    control, evaluation, read = build_tessellation_stages(...)  # program_pass: the two stages' GLSL

HLSL: the program as written plus entries of ours: ``pbrlab_hull_main`` (the hull function's
attributes, its patch-constant function ``pbrlab_patch_constant``; both set the pass's light as
the other stages do, then call the user's functions) and ``pbrlab_domain_main``, through glslang
(``-S tesc`` / ``-S tese``) and spirv-cross. spirv-cross names the stages' inputs
``pbrlab_patch_<member>`` and outputs ``_entryPointOutput_<member>``: renamed to the vertex
stage's outputs ``pbrlab_vary_<SEMANTIC>``, the control points ``pbrlab_tvary_<SEMANTIC>`` and
the fragment stage's inputs ``pbrlab_gvary_<SEMANTIC>`` (as behind a geometry stage). spirv-cross
writes no spacing or vertex order on the evaluation stage (SPIR-V holds them on the control
stage, GLSL on the evaluation stage: GLSL 4.00 section 4.3.8.1), so they are written there from
the hull's attributes (tessellation_syntax: SPACINGS, ORDERS).

GLSL: the port of the program (tessellation_syntax.spell_for_glsl has spelled the patches as
arrays and blanked the attributes) and mains of ours: the control stage fills the patch from
the vertex stage's outputs, calls the hull function for its control point (gl_InvocationID) and,
in invocation 0, the patch-constant function, whose SV_TessFactor / SV_InsideTessFactor members
are gl_TessLevelOuter / gl_TessLevelInner in order (D3D11's edge i and GL's outer level i are
both the edge opposite the domain's corner i: u = 0, v = 0, w = 0); its other members pass as
``patch out`` variables. The evaluation stage calls the domain function with gl_TessCoord as
SV_DomainLocation.
"""

from __future__ import annotations

import dataclasses
import re

from .geometry_stage import (_canonical, _fit, _glsl_name, _members, glsl_stage_macros, port_code_types,
                             positional_add)
from .engine_inputs import fill_statements
from .geometry_syntax import _POSITION
from .written_globals import copy_statements
from .source_text import UnityShaderError, component_count

PATCH_VERTICES = 3  # each mesh triangle is one patch (tessellation_syntax refuses other sizes)
_EXTENSION = "#extension GL_ARB_tessellation_shader : require"


def fragment_pass(vf):
    """The pass as the stage after the domain stage sees it (the fragment entry, or a geometry
    stage's, geometry_stage.py): its varyings are the domain output struct's."""
    t = vf.tessellation
    return dataclasses.replace(vf, vertex_return=t.domain_return, vertex_return_semantic="", vertex_params=[],
                               tessellation=None)


def _domain_prefix(vf) -> str:
    """The domain stage's outputs: the fragment stage's inputs, or a geometry stage's (which
    reads the vertices it is given as ``pbrlab_vary_<SEMANTIC>``)."""
    return "pbrlab_vary_" if vf.geometry is not None else "pbrlab_gvary_"


def _flat(kind: str) -> str:
    return "flat " if kind.startswith(("int", "uint", "bool")) else ""


def _varying_members(vf, kind: str, where: str) -> list:
    """[(type, member, SEMANTIC)] of ``kind`` that pass between stages (not the position)."""
    return [(t, m, _canonical(s)) for t, m, s in _members(vf, kind, where) if s and _canonical(s) not in _POSITION]


def _position_member(vf, kind: str, where: str):
    return next(((t, m) for t, m, s in _members(vf, kind, where) if s and _canonical(s) in _POSITION), None)


def _extras(vf) -> list:
    """[(type, member, GLSL variable)] of the patch-constant struct besides its levels."""
    t = vf.tessellation
    levels = {name for name, _ in t.outer + t.inner}
    out = []
    for kind, member, _ in _members(vf, t.factors_type, t.where):
        if re.sub(r"\[\d+\]$", "", member) not in levels:
            out.append((kind, member, "pbrlab_patch_" + re.sub(r"\W", "_", member)))
    return out


def _level(member: str, index) -> str:
    if index is None:
        return member
    return f"{member}[{index}]" if isinstance(index, int) else f"{member}.{index}"


# -- HLSL ---------------------------------------------------------------------------------------

def _args(params: list, values: dict) -> str:
    return ", ".join(values[role] for role, _ in params)


def hlsl_entries(vf, main_light: str) -> str:
    """The HLSL hull (with its patch-constant function) and domain entries (module docstring)."""
    t = vf.tessellation
    patch = f"InputPatch<{t.control_type}, {t.patch_size}> pbrlab_patch"
    ids = {"patch": "pbrlab_patch", "control_point_id": "pbrlab_id", "primitive_id": "pbrlab_primitive"}
    domain_values = {"patch": "pbrlab_patch", "factors": "pbrlab_factors", "location": "pbrlab_location"}
    location = "float3" if t.dimension == 3 else "float2"
    return (f"{t.factors_type} pbrlab_patch_constant({patch}, uint pbrlab_primitive : SV_PrimitiveID) {{\n"
            f"{main_light}    return {t.constant}({_args(t.constant_params, ids)});\n}}\n"
            f"[domain(\"{t.domain}\")]\n[outputcontrolpoints({t.output_points})]\n"
            f"[outputtopology(\"{t.topology}\")]\n[partitioning(\"{t.partitioning}\")]\n"
            f"[patchconstantfunc(\"pbrlab_patch_constant\")]\n"
            f"{t.output_type} pbrlab_hull_main({patch}, uint pbrlab_id : SV_OutputControlPointID, "
            f"uint pbrlab_primitive : SV_PrimitiveID) {{\n"
            f"{main_light}    return {t.hull}({_args(t.hull_params, ids)});\n}}\n"
            f"[domain(\"{t.domain}\")]\n"
            f"{t.domain_return} pbrlab_domain_main({t.factors_type} pbrlab_factors, "
            f"const OutputPatch<{t.output_type}, {t.output_points}> pbrlab_patch, "
            f"{location} pbrlab_location : SV_DomainLocation) {{\n"
            f"{main_light}    return {t.domain_function}({_args(t.domain_params, domain_values)});\n}}\n")


def _renamed(glsl: str, pairs, stage: str, where: str) -> str:
    """spirv-cross's ``<prefix><member>`` varyings -> ours; ``_Global`` and its instance named
    per stage (as the vertex stage's: program.rename_vertex_globals)."""
    for old, new in pairs:
        glsl = re.sub(r"\b" + re.escape(old) + r"\b", new, glsl)
    unlinked = [m.group(1) for m in re.finditer(r"^(?:flat\s+)?(?:patch\s+)?(?:in|out)\s+\w+\s+(\w+)", glsl, re.M)
                if not m.group(1).startswith(("pbrlab_vary_", "pbrlab_tvary_", "pbrlab_gvary_", "pbrlab_patch_",
                                              "gl_"))]
    if unlinked:
        raise UnityShaderError(f"{where}: pbrlab cannot link the {stage} stage's {', '.join(unlinked)} to the "
                               "stages around it")
    instance = re.search(r"uniform _Global (\w+);", glsl)
    if instance:
        glsl = re.sub(r"\b_Global\b", f"_Global{stage.title()}", glsl)
        glsl = re.sub(r"\b" + instance.group(1) + r"\b", f"pbrlab_{stage}_globals", glsl)
    return glsl


def hlsl_renamed(vf, control: str, evaluation: str) -> tuple[str, str]:
    t = vf.tessellation
    cps = _varying_members(vf, t.control_type, t.where)
    outs = _varying_members(vf, t.output_type, t.where)
    finals = _varying_members(vf, t.domain_return, t.where)
    # the patch-constant struct's other members: spirv-cross's _patchConstantOutput_<member> (an
    # array's element <member>_<i>_) in the control stage, pbrlab_factors_<member> in the evaluation
    # stage -> pbrlab_patch_<member> (glsl_control / glsl_evaluation spell them so)
    extras = [(f"_patchConstantOutput_{v[len('pbrlab_patch_'):]}", v) for _, _, v in _extras(vf)]
    factors = [(f"pbrlab_factors_{v[len('pbrlab_patch_'):]}", v) for _, _, v in _extras(vf)]
    # (a struct member's leaf, inner.uv, is spirv-cross's <prefix>inner_uv)
    cps, outs, finals = ([(k, m.replace(".", "_"), s) for k, m, s in group] for group in (cps, outs, finals))
    control = _renamed(control, [(f"pbrlab_patch_{m}", f"pbrlab_vary_{s}") for _, m, s in cps]
                       + [(f"_entryPointOutput_{m}", f"pbrlab_tvary_{s}") for _, m, s in outs] + extras,
                       "hull", t.where)
    # glslang writes a control point's nested struct member (CP.inner.uv) at a constant index of
    # the output array (``pbrlab_tvary_TEXCOORD0[1] = flattenTemp.inner.uv``), which GLSL refuses
    # ("outputs can only be indexed by gl_InvocationID") and which is not this invocation's
    # point: each invocation writes its own control point, gl_InvocationID (as for the others)
    control = re.sub(r"^(\s*pbrlab_tvary_\w+)\[\d+\](\s*=\s*flattenTemp\.\w+\.)", r"\1[gl_InvocationID]\2",
                     control, flags=re.M)
    evaluation = _renamed(evaluation, [(f"pbrlab_patch_{m}", f"pbrlab_tvary_{s}") for _, m, s in outs]
                          + [(f"_entryPointOutput_{m}", _domain_prefix(vf) + s) for _, m, s in finals] + factors,
                          "domain", t.where)
    primitive = {"tri": "triangles", "quad": "quads"}[t.domain]
    evaluation = re.sub(r"^layout\(" + primitive + r"\) in;", f"layout({primitive}, {t.spacing}, {t.order}) in;",
                        evaluation, count=1, flags=re.M)
    return control, evaluation


# -- GLSL ---------------------------------------------------------------------------------------

def _fill(vf, kind: str, target: str, sources: dict, k: int) -> list:
    """Statements filling ``target`` (a struct ``kind``) from the previous stage's k-th vertex."""
    lines = []
    for mtype, member, semantic in _members(vf, kind, vf.tessellation.where):
        s = _canonical(semantic) if semantic else ""
        n = component_count(mtype)
        to = f"    {target}.{_glsl_name(member)} = "
        if s in _POSITION:
            lines.append(to + _fit(f"gl_in[{k}].gl_Position", 4, n) + ";")
        elif s in sources:
            lines.append(to + f"{sources[s]}[{k}];")
        elif n:  # not written by the stage before: 0, as an unwritten HLSL input
            lines.append(to + f"{port_code_types(mtype)}(0);")
    return lines


def _write(vf, kind: str, value: str, prefix: str, position: str, index: str = "") -> list:
    lines = []
    for mtype, member, semantic in _members(vf, kind, vf.tessellation.where):
        if not semantic:
            continue
        s = _canonical(semantic)
        if s in _POSITION:
            lines.append(f"    {position} = {_fit(f'{value}.{_glsl_name(member)}', component_count(mtype), 4, 1.0)};")
        else:
            lines.append(f"    {prefix}{s}{index} = {value}.{_glsl_name(member)};")
    return lines


def _declare(vf, kind: str, qualifier: str, prefix: str, array: str) -> list:
    return [f"{_flat(t)}{qualifier} {port_code_types(t)} {prefix}{s}{array};"
            for t, _, s in _varying_members(vf, kind, vf.tessellation.where)]


def glsl_control(vf, main_light: str, vertex_outputs: dict) -> tuple[str, str]:
    """(declarations, main) of the GLSL control stage."""
    t = vf.tessellation
    decl = [f"layout(vertices = {t.output_points}) out;"]
    decl += [f"{_flat(kind)}in {port_code_types(kind)} pbrlab_vary_{s}[];" for s, kind in vertex_outputs.items()]
    decl += _declare(vf, t.output_type, "out", "pbrlab_tvary_", "[]")
    decl += [f"patch out {port_code_types(kind)} {var};" for kind, _, var in _extras(vf)]
    body = [main_light, f"    {t.control_type} pbrlab_patch[{t.patch_size}];"]
    for k in range(t.patch_size):
        body += _fill(vf, t.control_type, f"pbrlab_patch[{k}]", {s: f"pbrlab_vary_{s}" for s in vertex_outputs}, k)
    ids = {"control_point_id": "gl_InvocationID", "primitive_id": "gl_PrimitiveID"}
    # (an id as the parameter declares it: int or uint)
    call = lambda params: ", ".join("pbrlab_patch" if r == "patch" else f"{k}({ids[r]})" for r, k in params)
    body.append(f"    {t.output_type} pbrlab_point = {t.hull}({call(t.hull_params)});")
    body += _write(vf, t.output_type, "pbrlab_point", "pbrlab_tvary_", "gl_out[gl_InvocationID].gl_Position",
                   "[gl_InvocationID]")
    body += ["    if (gl_InvocationID == 0) {",
             f"    {t.factors_type} pbrlab_factors = {t.constant}({call(t.constant_params)});"]
    body += [f"    gl_TessLevelOuter[{i}] = pbrlab_factors.{_level(m, x)};" for i, (m, x) in enumerate(t.outer)]
    body += [f"    gl_TessLevelInner[{i}] = pbrlab_factors.{_level(m, x)};" for i, (m, x) in enumerate(t.inner)]
    body += [f"    {var} = pbrlab_factors.{_glsl_name(member)};" for _, member, var in _extras(vf)]
    body.append("    }")
    return "\n".join(decl) + "\n", "\n".join(["void main() {"] + body + ["}"]) + "\n"


def glsl_evaluation(vf, main_light: str) -> tuple[str, str]:
    """(declarations, main) of the GLSL evaluation stage."""
    t = vf.tessellation
    primitive = {"tri": "triangles", "quad": "quads"}[t.domain]
    decl = [f"layout({primitive}, {t.spacing}, {t.order}) in;"]
    decl += _declare(vf, t.output_type, "in", "pbrlab_tvary_", "[]")
    decl += [f"patch in {port_code_types(kind)} {var};" for kind, _, var in _extras(vf)]
    decl += _declare(vf, t.domain_return, "out", _domain_prefix(vf), "")
    body = [main_light, f"    {t.output_type} pbrlab_patch[{t.output_points}];"]
    sources = {s: f"pbrlab_tvary_{s}" for _, _, s in _varying_members(vf, t.output_type, t.where)}
    for k in range(t.output_points):
        body += _fill(vf, t.output_type, f"pbrlab_patch[{k}]", sources, k)
    body.append(f"    {t.factors_type} pbrlab_factors;")
    body += [f"    pbrlab_factors.{_level(m, x)} = gl_TessLevelOuter[{i}];" for i, (m, x) in enumerate(t.outer)]
    body += [f"    pbrlab_factors.{_level(m, x)} = gl_TessLevelInner[{i}];" for i, (m, x) in enumerate(t.inner)]
    body += [f"    pbrlab_factors.{_glsl_name(member)} = {var};" for _, member, var in _extras(vf)]
    values = {"patch": "pbrlab_patch", "factors": "pbrlab_factors",
              "location": "gl_TessCoord" if t.dimension == 3 else "gl_TessCoord.xy"}
    body.append(f"    {t.domain_return} pbrlab_out = {t.domain_function}("
                f"{', '.join(values[r] for r, _ in t.domain_params)});")
    body += _write(vf, t.domain_return, "pbrlab_out", _domain_prefix(vf), "gl_Position")
    return "\n".join(decl) + "\n", "\n".join(["void main() {"] + body + ["}"]) + "\n"


def _entry_start(vf, language: str) -> str:
    """What each entry does before the program runs, as the vertex and fragment entries do: the
    pass's light, the engine-filled globals, the written globals' copies (written_globals.py)."""
    from .generate_pass import _main_light
    return _main_light(language) + fill_statements(vf.engine_filled, language) + copy_statements(vf.written_globals)


def build_tessellation_stages(vf, language: str, defines: dict, dirs, program_text: str, display: str,
                              virtual=None):
    """(control stage, evaluation stage, the files they read), as ``shaders.Source``s.
    ``program_text``: the program as written (HLSL) or the line that includes its port (GLSL,
    ``virtual`` its files)."""
    from ...foundation.file_identity import include_closure
    from ...gpu import hlsl, shaders
    from . import generate
    from .generate_pass import varyings
    t = vf.tessellation
    if positional_add(defines):  # the light's falloff at each generated point: not wired here
        raise UnityShaderError(f"{t.where}: a ForwardAdd pass of a point or spot light with tessellation "
                               "stages: pbrlab lights tessellated passes by directional lights only")
    head = "\n".join(generate.prelude(language, defines, vertex_stage=True))
    names = {kind: f"{vf.path.name} (generated {language} {kind} stage)" for kind in ("hull", "domain")}
    if language == "hlsl":
        text = (head + "\n#define POSITION SV_Position\n" + hlsl.line_directive(vf.program_line, display) + "\n"
                + program_text + "\n" + hlsl_entries(vf, _entry_start(vf, "hlsl")))
        from .program import hlsl_includes  # (program imports the stages' modules)
        replaced = hlsl_includes(vf)  # the shader's own includes as the other stages compile them
        control = hlsl.cross_to_glsl(hlsl.compile_spirv(text, names["hull"], dirs, stage="tesc", entry="pbrlab_hull_main",
                                                        replaced=replaced), version=400, plain_uniforms=True)
        evaluation = hlsl.cross_to_glsl(hlsl.compile_spirv(text, names["domain"], dirs, stage="tese",
                                                           entry="pbrlab_domain_main", replaced=replaced),
                                        version=400, plain_uniforms=True)
        control, evaluation = hlsl_renamed(vf, control, evaluation)
        return (shaders.Source(control, [f"{names['hull']} (GLSL from spirv-cross)"]),
                shaders.Source(evaluation, [f"{names['domain']} (GLSL from spirv-cross)"]),
                include_closure(text, [*dirs, hlsl.HLSL_ROOT]))
    head = head.replace("#version 330 core", "#version 330 core\n" + _EXTENSION, 1)
    stages = []
    for kind, (decl, main) in (("hull", glsl_control(vf, _entry_start(vf, "glsl"), dict(varyings(vf, t.where)))),
                               ("domain", glsl_evaluation(vf, _entry_start(vf, "glsl")))):
        # (a geometry function of the program is dead code here: its stream macros are nothing)
        text = head + "\n" + decl + glsl_stage_macros(vf, False) + "#line 1\n" + program_text + "\n" + main
        stages.append(shaders.expand(text, names[kind], include_dirs=dirs, virtual=virtual or {}))
    return stages[0], stages[1], [*stages[0].paths, *stages[1].paths]
