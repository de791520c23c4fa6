"""A vertex/fragment pass's geometry stage (``#pragma geometry geom``): Unity's

    [maxvertexcount(N)]
    void geom(triangle v2g IN[3], inout TriangleStream<g2f> stream) { ... stream.Append(o); ... }

run between the pass's vertex and fragment stages, in both languages.

    g = parse_geometry(text, "geom", where, offset)      # parse_pass: vf.geometry (geometry_syntax.py)
    source = geometry_source(vf, "hlsl", defines, text)  # program_pass: the stage's GLSL

HLSL: the program as written plus an entry of ours (``pbrlab_geometry_main``: the user's
parameter list, the pass's light as the other stages set it, then a call of ``geom``), through
glslang (``-S geom``) and spirv-cross, which write a GLSL 330 geometry shader. spirv-cross names
the stage's inputs ``<param>_<member>`` and its outputs ``<stream>_<member>``; they are renamed
here to the names the other stages use: the vertex stage's outputs ``pbrlab_vary_<SEMANTIC>``
(of the geometry input struct's members), the fragment stage's inputs
``pbrlab_gvary_<SEMANTIC>`` (of the output struct's members; ``fragment_pass`` is the pass as
the fragment entry sees it: its varyings are the geometry output struct's).

GLSL: the port of the program, in which ``spell_for_glsl`` (geometry_syntax.py, run by
port.port_text) has spelled the geometry syntax in Cg the type pass reads: the ``[maxvertexcount]`` attribute and the primitive
word (``triangle``) dropped, the stream parameter dropped, ``stream.Append(x)`` ->
``PBRLAB_GEOMETRY_APPEND(x)`` and ``stream.RestartStrip()`` -> ``PBRLAB_GEOMETRY_RESTART()``.
The geometry entry defines those two as writing the output struct's members to the stage's
outputs, its SV_POSITION to ``gl_Position``, then ``EmitVertex()`` / ``EndPrimitive()``
(the GLSL 3.30 specification, section 8.12, "Geometry Shader Functions"); the vertex and
fragment stages define them as nothing (the geometry function is dead code there). Its
``main`` fills the input array from ``gl_in[k].gl_Position`` and the vertex stage's outputs
and ``SV_PrimitiveID`` from ``gl_PrimitiveIDIn``, and calls the function.

A geometry function taking ``point`` input (``void geom(point v2g IN[1], ...)``: billboards,
grass) runs once per mesh triangle, given the triangle's first vertex as its point. Unity draws
a mesh with its submesh's own topology (MeshTopology; points only for a mesh built with
MeshTopology.Points), so on D3D11 a point-input geometry shader meets a triangle list, a
mismatch that "(sort of) works in D3D11 on some drivers" (vkd3d-proton pull request 2361,
"Validate GS input topology", 2025, on the Unity game Clanfolk, whose point geometry shader is
drawn with triangles; D3D12 validation and Vulkan reject it). DXVK's workaround for that game
(dxvk pull request 4716, commit b41253e1, DxvkShader::patchInputTopology) compiles the geometry
shader for the draw's topology, the input array's element 0 being each primitive's first
vertex: pbrlab does the same in both languages, the stage declaring ``layout(triangles) in``
(``POINT_INPUT_LAYOUT``) and handing the function ``gl_in[0]``'s vertex. A vertex is a point of
each triangle it starts; one that starts none draws nothing.

A function of the program that takes the stream (``void emit(inout TriangleStream<T> s, ...)``)
loses that parameter too, and a call handing the stream on (``emit(stream, ...)``) that argument.
"""

from __future__ import annotations

import dataclasses
import re

from .cg_types import RENAME_PREFIX, is_reserved
from .geometry_syntax import PRIMITIVES, STREAMS, _POSITION
from .source_text import UnityShaderError, component_count


def port_code_types(kind: str) -> str:
    from .port import port_code_types as rename  # (imported where used: start-up stays lean)
    return rename(kind)


def _members(vf, kind: str, where: str, semantic: str = "") -> list:
    """[(type, member, semantic)] of the struct ``kind``; a bare value per vertex (``triangle
    float4 IN[3] : SV_POSITION``, ``semantic`` the array's) is one member, named "" (the value
    itself), carrying the array's semantic, as FXC reads it (HLSL's semantics apply to a
    parameter as to a struct member: Microsoft's "Semantics" page, geometry-shader inputs)."""
    members = vf.structs.get(kind)
    if members is None and component_count(kind):
        if not semantic:
            raise UnityShaderError(f"{where}: the geometry stage takes an array of {kind} without a semantic "
                                   "(HLSL needs one on a bare value per vertex: triangle float4 IN[3] : SV_POSITION)")
        return [(kind, "", semantic)]
    if members is None:
        raise UnityShaderError(f"{where}: the geometry stage's struct {kind} is not defined")
    return members.members


def _canonical(semantic: str) -> str:
    from .generate_pass import canonical
    return canonical(semantic)


def _flat(vf, mtype: str, semantic: str) -> str:
    """"flat " where the vertex stage's output and the fragment stage's input of this semantic are
    flat (generate_pass._flat: an integer, or a member some struct declares ``nointerpolation``):
    GLSL links a stage pair only where both sides qualify a varying alike (GLSL 4.30 section 4.3.4),
    so the geometry stage's input and output of that semantic are flat too."""
    from .generate_pass import _flat as stage_flat
    return stage_flat(mtype, semantic, vf)


def _fit(expr: str, have: int, want: int, w: float = 0.0) -> str:
    from .generate_pass import fit
    return fit(expr, have, want, "glsl", w)


def fragment_pass(vf):
    """The pass as the fragment entry sees it: its vertex stage outputs the geometry output
    struct (the varyings the fragment reads are that struct's members)."""
    g = vf.geometry
    return dataclasses.replace(vf, vertex_return=g.output_type, vertex_return_semantic="", vertex_params=[],
                               geometry=None)


def fragment_inputs_renamed(text: str) -> str:
    """The fragment stage's inputs named as the geometry stage writes them."""
    return re.sub(r"\bpbrlab_vary_", "pbrlab_gvary_", text)


def _glsl_name(name: str) -> str:
    """A member or variable name as the GLSL port spells it (cg_types renames reserved words)."""
    return RENAME_PREFIX + name if is_reserved(name) else name


# A ForwardAdd pass of a point or spot light folds the light's falloff into _LightColor0 at the
# surface point (generate_pass._main_light). Behind a geometry stage the fragment's point is
# that of the emitted vertices, which the stage writes from each one's clip position: clip =
# P (e, 1) for the eye point e, of whose four rows three are solved for e (x, y and, for a
# perspective P, whose last row is (0, 0, -1, 0), w; for an orthographic one, z): the depth row
# of a perspective P is left out, where float32 loses (far/near) times its precision (measured
# 2e-3 relative through the inverse of P at near 1e-4); then world = V^-1 (e, 1). The geometry
# function's own _LightColor0 is the light at its triangle's first vertex (the point the vertex
# stage gives).
POSITIONAL_ADD = "defined(PBRLAB_UNITY_ADD_POINT) || defined(PBRLAB_UNITY_ADD_SPOT)"
_WORLD_OF_CLIP = """vec3 pbrlab_world_of_clip(vec4 clip_position) {
    mat4 p = glstate_matrix_projection;
    int r = p[3][3] == 0.0 ? 3 : 2;
    mat3 rows = transpose(mat3(vec3(p[0][0], p[1][0], p[2][0]), vec3(p[0][1], p[1][1], p[2][1]),
                               vec3(p[0][r], p[1][r], p[2][r])));
    vec3 eye = inverse(rows) * (vec3(clip_position.x, clip_position.y, clip_position[r]) - vec3(p[3][0], p[3][1], p[3][r]));
    return (unity_MatrixInvV * vec4(eye, 1.0)).xyz;
}
"""


# the input layout a geometry stage declares for the draw's primitive: the mesh's triangles also
# for a point-input function (module docstring)
POINT_INPUT_LAYOUT = "triangles"


def _input_layout(g) -> str:
    return POINT_INPUT_LAYOUT if g.primitive == "point" else PRIMITIVES[g.primitive][0]


def point_input_on_triangles(vf, glsl: str) -> str:
    """spirv-cross's point-input geometry stage reading the draw's triangles (module docstring):
    ``layout(points) in`` -> ``layout(triangles) in``, its input arrays of 1 unsized (element 0,
    the triangle's first vertex, is the one read)."""
    if vf.geometry.primitive != "point":
        return glsl
    glsl = re.sub(r"^layout\(points\) in;", f"layout({POINT_INPUT_LAYOUT}) in;", glsl, flags=re.M)
    return re.sub(r"^((?:layout\([^)]*\)\s*)?(?:flat\s+)?in\s+\w+\s+\w+)\[1\];", r"\1[];", glsl, flags=re.M)


def positional_add(defines: dict) -> bool:
    return any(k in defines for k in ("PBRLAB_UNITY_ADD_POINT", "PBRLAB_UNITY_ADD_SPOT"))


def hlsl_entry(vf, main_light: str, world_register: int) -> str:
    """The HLSL geometry entry: the user's parameters (and, for a positional ForwardAdd light,
    the vertex stage's world points, its TEXCOORD ``world_register``), the pass's light, a
    call of geom."""
    g = vf.geometry
    count = PRIMITIVES[g.primitive][1]
    params = ", ".join(text for _, text, _ in g.params)
    args = ", ".join(name for _, _, name in g.params)
    return (f"[maxvertexcount({g.max_vertices})]\nvoid pbrlab_geometry_main({params}\n#if {POSITIONAL_ADD}\n"
            f", {g.primitive} float3 pbrlab_vary_world_position[{count}] : TEXCOORD{world_register}\n#endif\n) {{\n"
            f"#if {POSITIONAL_ADD}\n    float3 pbrlab_world_position = pbrlab_vary_world_position[0];\n#endif\n"
            f"{main_light}    {g.name}({args});\n}}\n")


def hlsl_world_written(glsl: str) -> str:
    """The spirv-cross geometry stage of a positional ForwardAdd light writing each emitted
    vertex's world point for the fragment (POSITIONAL_ADD)."""
    declarations = ("uniform mat4 unity_MatrixInvV;\nuniform mat4 glstate_matrix_projection;\n"
                    "out vec3 pbrlab_gvary_world_position;\n" + _WORLD_OF_CLIP)
    glsl = re.sub(r"^(layout\([^)]*max_vertices[^)]*\) out;\n)", lambda m: m.group(1) + declarations, glsl,
                  count=1, flags=re.M)
    return glsl.replace("EmitVertex();", "pbrlab_gvary_world_position = pbrlab_world_of_clip(gl_Position); EmitVertex();")


def hlsl_renamed(vf, glsl: str) -> str:
    """spirv-cross's names for the geometry stage's inputs and outputs -> the other stages'
    (module docstring); its ``_Global`` struct and instance renamed as the vertex stage's."""
    g = vf.geometry
    for kind, param, prefix, own in ((g.input_type, g.input_name, "pbrlab_vary_", g.input_semantic),
                                     (g.output_type, g.stream_name, "pbrlab_gvary_", "")):
        for _, member, semantic in _members(vf, kind, g.where, own):
            if semantic and _canonical(semantic) not in _POSITION:
                # (a bare value: the parameter's name; a struct member's leaf, inner.uv: IN_inner_uv)
                spirv_name = f"{param}_{member.replace('.', '_')}" if member else param
                glsl = re.sub(r"\b" + re.escape(spirv_name) + r"\b", prefix + _canonical(semantic), glsl)
    unlinked = [m.group(1) for m in re.finditer(r"^(?:flat\s+)?(?:in|out)\s+\w+\s+(\w+)", glsl, re.M)
                if not m.group(1).startswith(("pbrlab_vary_", "pbrlab_gvary_", "gl_"))
                and m.group(1) != "pbrlab_vary_world_position"]
    if unlinked:  # spirv-cross named a varying otherwise than <param>_<member>: say so, not a link error
        raise UnityShaderError(f"{g.where}: {g.name}(): pbrlab cannot link the geometry stage's "
                               f"{', '.join(unlinked)} to the vertex or fragment stage")
    # an input or output flat where the vertex and fragment stages' varying of its semantic is
    # (_flat: an integer, or a member declared ``nointerpolation``): SPIR-V asks Flat of a fragment
    # input only, so spirv-cross writes the geometry stage's varyings plain, and GLSL 3.30 links a
    # stage pair only with the same interpolation qualifiers (section 4.3.4)
    flat_semantics = {_canonical(semantic) for kind, own in ((g.input_type, g.input_semantic), (g.output_type, ""))
                      for mtype, _, semantic in _members(vf, kind, g.where, own)
                      if semantic and _flat(vf, mtype, _canonical(semantic))}
    for s in sorted(flat_semantics):
        glsl = re.sub(r"^((?:layout\([^)]*\)\s*)?)((?:in|out)\s+\w+\s+pbrlab_g?vary_" + re.escape(s) + r"\b)",
                      r"\1flat \2", glsl, flags=re.M)
    instance = re.search(r"uniform _Global (\w+);", glsl)
    if instance:
        glsl = re.sub(r"\b_Global\b", "_GlobalGeometry", glsl)
        glsl = re.sub(r"\b" + instance.group(1) + r"\b", "pbrlab_geometry_globals", glsl)
    return glsl


def glsl_stage_macros(vf, in_geometry: bool) -> str:
    """PBRLAB_GEOMETRY_APPEND / _RESTART: the geometry stage's (an emitted vertex, the end of a
    strip) or, in the vertex and fragment stages, nothing."""
    if not in_geometry:  # (vf may have no geometry stage: a geometry function no pragma names)
        return "#define PBRLAB_GEOMETRY_APPEND(v)\n#define PBRLAB_GEOMETRY_RESTART()\n"
    g = vf.geometry
    writes = []
    for mtype, member, semantic in _members(vf, g.output_type, g.where):
        if not semantic:
            continue
        s, name = _canonical(semantic), f"pbrlab_emitted.{_glsl_name(member)}"
        if s in _POSITION:
            writes.append(f"gl_Position = {_fit(name, component_count(mtype), 4, 1.0)};")
        else:
            writes.append(f"pbrlab_gvary_{s} = {name};")
    body = " ".join([f"{g.output_type} pbrlab_emitted = (v);", *writes, "PBRLAB_GEOMETRY_WORLD(); EmitVertex();"])
    return (f"#if {POSITIONAL_ADD}\nin vec3 pbrlab_vary_world_position[];\nout vec3 pbrlab_gvary_world_position;\n"
            + _WORLD_OF_CLIP + "#define PBRLAB_GEOMETRY_WORLD() pbrlab_gvary_world_position = "
            "pbrlab_world_of_clip(gl_Position)\n#else\n#define PBRLAB_GEOMETRY_WORLD()\n#endif\n"
            f"#define PBRLAB_GEOMETRY_APPEND(v) {{ {body} }}\n"
            "#define PBRLAB_GEOMETRY_RESTART() EndPrimitive()\n")


def glsl_declarations(vf, vertex_outputs: dict) -> str:
    """The GLSL geometry stage's layouts, inputs and outputs (before the program: the stream's
    macros write the outputs); ``vertex_outputs``: {semantic: type} the vertex stage passes on
    (its pbrlab_vary_<SEMANTIC> outputs)."""
    g = vf.geometry
    lines = [f"layout({_input_layout(g)}) in;"]
    lines += [f"{_flat(vf, t, s)}in {port_code_types(t)} pbrlab_vary_{s}[];" for s, t in vertex_outputs.items()]
    for mtype, member, semantic in _members(vf, g.output_type, g.where):
        if semantic and _canonical(semantic) not in _POSITION:
            s = _canonical(semantic)
            lines.append(f"{_flat(vf, mtype, s)}out {port_code_types(mtype)} pbrlab_gvary_{s};")
    return "\n".join(lines) + "\n"


def glsl_entry(vf, main_light: str, vertex_outputs: dict) -> str:
    """The GLSL geometry stage's main (module docstring)."""
    g = vf.geometry
    count = PRIMITIVES[g.primitive][1]
    body = [f"#if {POSITIONAL_ADD}", "    vec3 pbrlab_world_position = pbrlab_vary_world_position[0];", "#endif",
            main_light, f"    {port_code_types(g.input_type)} pbrlab_in[{count}];"]
    for k in range(count):
        for mtype, member, semantic in _members(vf, g.input_type, g.where, g.input_semantic):
            s = _canonical(semantic) if semantic else ""
            target = f"    pbrlab_in[{k}]{'.' + _glsl_name(member) if member else ''} = "
            n = component_count(mtype)
            if s in _POSITION:
                body.append(target + _fit(f"gl_in[{k}].gl_Position", 4, n) + ";")
            elif s in vertex_outputs:
                body.append(target + f"pbrlab_vary_{s}[{k}];")
            elif n:  # a member the vertex stage does not write: 0, as an unwritten HLSL input
                body.append(target + f"{port_code_types(mtype)}(0);")
    args = []
    for role, text, name in g.params:
        if role == "input":
            args.append("pbrlab_in")
        elif role == "primitive_id":  # int or uint, as the parameter is declared
            args.append(re.match(r"(?:in\s+)?(\w+)", text).group(1) + "(gl_PrimitiveIDIn)")
    body.append(f"    {g.name}({', '.join(args)});")
    # after the program, whose macros [maxvertexcount(...)] may name (an expression: a constant
    # expression in a layout qualifier is GLSL 4.40's, or GL_ARB_enhanced_layouts')
    layout = f"layout({STREAMS[g.stream]}, max_vertices = {g.max_vertices}) out;"
    return "\n".join([layout, "void main() {"] + body + ["}"]) + "\n"


def build_geometry_stage(vf, language: str, defines: dict, dirs, program_text: str, display: str,
                         virtual=None):
    """(the geometry stage as a ``shaders.Source``, the files it read). ``program_text``: the
    program as written (HLSL) or the line that includes its port (GLSL, ``virtual`` its files)."""
    from ...foundation.file_identity import include_closure
    from ...gpu import hlsl, shaders
    from . import generate
    from .generate_pass import _main_light, varyings
    from .written_globals import copy_statements
    # the copies of the globals the program writes, from their uniforms, as the other stages'
    # entries set them (written_globals.py: FXC's backwards-compatible writable globals)
    copies = copy_statements(vf.written_globals)
    head = "\n".join(generate.prelude(language, defines, vertex_stage=True))
    name = f"{vf.path.name} (generated {language} geometry stage)"
    if language == "hlsl":
        # POSITION passes as SV_Position between Unity's stages (as the vertex entry treats it); in
        # glslang's geometry stage only SV_Position is gl_in[k].gl_Position / gl_Position
        text = (head + "\n#define POSITION SV_Position\n" + hlsl.line_directive(vf.program_line, display) + "\n"
                + program_text + "\n"
                + hlsl_entry(vf, _main_light("hlsl") + copies, len(varyings(vf, vf.geometry.where))))
        from .program import hlsl_includes  # (program imports the stages' modules)
        spirv = hlsl.compile_spirv(text, name, dirs, stage="geom", entry="pbrlab_geometry_main",
                                   replaced=hlsl_includes(vf))  # the shader's own includes as the other stages
        glsl = point_input_on_triangles(vf, hlsl_renamed(vf, hlsl.cross_to_glsl(spirv, plain_uniforms=True)))
        if positional_add(defines):
            glsl = hlsl_world_written(glsl)
        return (shaders.Source(glsl, [f"{name} (GLSL from spirv-cross)"]),
                include_closure(text, [*dirs, hlsl.HLSL_ROOT]))
    outputs = dict(varyings(vf, vf.geometry.where))
    if not re.fullmatch(r"\d+", vf.geometry.max_vertices):
        head = head.replace("#version 330 core", "#version 330 core\n#extension GL_ARB_enhanced_layouts : require", 1)
    text = (head + "\n" + glsl_declarations(vf, outputs) + glsl_stage_macros(vf, True) + "#line 1\n" + program_text + "\n"
            + glsl_entry(vf, _main_light("glsl") + copies, outputs))
    source = shaders.expand(text, name, include_dirs=dirs, virtual=virtual or {})
    return source, list(source.paths)


def link(ctx, vertex, geometry, fragment):
    """``shaders.build_program`` with a geometry stage (link_stages)."""
    return link_stages(ctx, {"vertex": vertex, "geometry": geometry, "fragment": fragment})


def link_stages(ctx, stages: dict):
    """``shaders.build_program`` with a geometry stage or tessellation stages (``stages``:
    moderngl's shader keywords without ``_shader``): the same limits and compile guards, errors
    at the original file and line of the stage that failed."""
    import warnings

    import moderngl

    from ...foundation.errors import LoopLimitWarning, ShaderCompileError
    from ...gpu import shaders
    from ...gpu.cancellation import dies_on_signal
    from ...gpu.compile_messages import compile_failure
    from ...gpu.driver_time_limit import within_time_limit
    for stage in stages.values():
        shaders.check_limits(stage)
    if "llvmpipe" in str(ctx.info.get("GL_RENDERER", "")).lower():
        for stage in stages.values():
            for message in shaders.loop_limit_warnings(stage):
                warnings.warn(message, LoopLimitWarning, stacklevel=2)
    try:
        label = shaders.program_label(stages["vertex"], stages["fragment"])
        with dies_on_signal(), within_time_limit(f"compiling {label}"):
            return ctx.program(**{f"{name}_shader": source.text for name, source in stages.items()})
    except moderngl.Error as exc:
        log = str(exc)
        name = next((n for n in stages if n != "vertex" and f"{n}_shader" in log), "vertex")
        messages = "\n".join(line for line in stages[name].map_messages(log).splitlines()
                              if line.strip() not in {f"{n}_shader" for n in stages})
        raise ShaderCompileError(compile_failure(f"{name} shader failed to compile", messages)) from None
