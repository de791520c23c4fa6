"""Write the programs that run a parsed surface shader (``model.SurfaceShader``) in the
harness, in HLSL (the CGPROGRAM text exactly as written) or GLSL (its ``port-unity`` port).

    text = fragment_source(shader, "hlsl", "sphere", program_text)

The fragment program is, in order: the harness's defines and scene shading
(``scene_shading.hlsl``/``.glsl``), ``templates/unity_surface.inc`` (Unity's generated-code
names: INTERNAL_DATA, appdata_full, the environment hooks), the library's ``pbr/unity/``
includes, a ``#line`` to the shader file and the program text, then this module's glue:
the ``_ST`` uniforms Unity declares for each ``uv_<Tex>``, the Input filled by Unity's naming
rules, the lighting model's call in its form (``templates/unity_shading.inc`` sums the
lights), the pixel function (surface function, alpha test, tangent-space normal to world,
lighting, final colour) and the entry point.
"""

from __future__ import annotations

import re

from ...gpu.hlsl import line_directive
from ...gpu.programs import SAMPLES_DEFINE
from ...scene.surface_layers import FIELD_SIZES
from . import model as M
from .generate_pass import _ATTRIBUTES, UNITY_STRUCTS, _attribute, _zero, canonical, fit
from .output_struct import layered_struct, vector_type
from .port import port_code_types
from .source_text import component_count
from .user_definitions import prelude_renames
from .written_globals import copy_statements

LIBRARY_INCLUDES = ("unity_compat/shader_variables", "pbr/unity/unity_cg", "pbr/unity/lighting_legacy",
                    "pbr/unity/global_illumination")
SUFFIX = {"glsl": ".glsl", "hlsl": ".hlsl"}


def _input_fill(shader: M.SurfaceShader, language: str) -> str:
    """``Input pbrlab_unity_input(PbrlabFragment f)``: every member by Unity's rules."""
    lines = ["Input pbrlab_unity_input(PbrlabFragment f) {", "    Input IN;"]
    if language == "hlsl":
        lines.append("    IN = (Input)0;")
    lines += ["    vec3 t = pbrlab_unity_tangent(f);", "    vec3 b = pbrlab_unity_bitangent(f, t);"]
    uv_members = {m: tex for m, _, tex in shader.uv_members()}
    for kind, name in shader.input_members:
        if name in uv_members:
            tex = uv_members[name]
            lines.append(f"    IN.{name} = f.uv * {tex}_ST.xy + {tex}_ST.zw;")
        elif name == "viewDir":
            if shader.writes_normal:  # tangent space, as Unity when the surface writes o.Normal
                lines.append("    IN.viewDir = vec3(dot(t, f.view), dot(b, f.view), dot(f.normal, f.view));")
            else:
                lines.append("    IN.viewDir = f.view;")
        elif name == "worldPos":
            lines.append("    IN.worldPos = f.position;")
        elif name == "worldNormal":
            lines.append("    IN.worldNormal = f.normal;")
        elif name == "worldRefl":
            if shader.writes_normal and shader.internal_data:
                # Unity: the incident direction, for WorldReflectionVector(IN, o.Normal) to reflect
                lines.append("    IN.worldRefl = -f.view;")
            else:
                lines.append("    IN.worldRefl = reflect(-f.view, f.normal);")
        elif name == "screenPos":
            lines.append("    IN.screenPos = ComputeScreenPos(" + _mul(language, "unity_MatrixVP", "vec4(f.position, 1.0)") + ");")
        elif shader.is_color(name):  # the vertex colour: white on meshes here, unless vertex: sets it
            source = f"pbrlab_custom_{name}" if shader.vertex else fit("f.color", 4, component_count(kind) or 4, language)
            lines.append(f"    IN.{name} = {source};")
        else:  # written by the vertex: function, interpolated (mesh entry: pbrlab_custom_*)
            lines.append(f"    IN.{name} = pbrlab_custom_{name};")
    for name in shader.facing_members:  # VFACE: 1 seen from the front, -1 from the back
        lines.append(f"    IN.{name} = f.facing;")
    if shader.internal_data:
        lines += ["    IN.internalSurfaceTtoW0 = vec3(t.x, b.x, f.normal.x);",
                  "    IN.internalSurfaceTtoW1 = vec3(t.y, b.y, f.normal.y);",
                  "    IN.internalSurfaceTtoW2 = vec3(t.z, b.z, f.normal.z);"]
    lines += ["    return IN;", "}"]
    return "\n".join(lines)


def _mul(language: str, m: str, v: str) -> str:
    return f"mul({m}, {v})" if language == "hlsl" else f"({m} * {v})"


def _light_call(shader: M.SurfaceShader) -> str:
    name = "Lighting" + shader.lighting.name
    return {
        M.FORM_GI_VIEW: f"{name}(o, v, gi)",
        M.FORM_GI: f"{name}(o, gi)",
        M.FORM_LIGHT_DIR: f"{name}(o, gi.light.dir, 1.0)",
        M.FORM_LIGHT_VIEW_DIR: f"{name}(o, gi.light.dir, v, 1.0)",
    }[shader.lighting.form]


def _zero_output(shader: M.SurfaceShader, language: str) -> list[str]:
    t = shader.output_type
    lines = [f"    {t} o;"]
    if language == "hlsl":
        lines.append(f"    o = ({t})0;")
    else:
        for name, n in shader.output_fields.items():
            if n:
                zero = "0.0" if n == 1 else f"{vector_type(n)}({', '.join(['0.0'] * n)})"
                lines.append(f"    o.{name} = {zero};")
    if "Occlusion" in shader.output_fields:
        lines.append("    o.Occlusion = 1.0;")
    if shader.layers:  # the layers' fields start from the harness's defaults (no coat, ...)
        lines.append("    SurfaceOutputStandardLayers pbrlabLayerDefaults = pbrlab_default_layers();")
        lines += [f"    o.{name} = pbrlabLayerDefaults.{name};" for name in FIELD_SIZES]
    return lines


def _layered_shading(shader: M.SurfaceShader) -> list[str]:
    """A layered model's output shaded as the harness shades a JSON material with the same
    layers (scene_lighting.inc pbrlab_shade_surface): the Standard struct and the layers'
    struct filled from it, tangent-space layer directions to the world as o.Normal. (The
    specular model's material has the specular workflow, scene.py: PbrlabSurfaceOutput is
    SurfaceOutputStandardSpecular there.)"""
    base = M.LAYERED_MODELS[shader.pragma.model]
    lines = [f"    {base} pbrlabBase;"]
    lines += [f"    pbrlabBase.{name} = o.{name};" for name in M.OUTPUT_FIELDS[base]]
    if shader.layers:
        lines.append("    SurfaceOutputStandardLayers layers;")
        lines += [f"    layers.{name} = o.{name};" for name in FIELD_SIZES]
        for layer, direction in (("clearcoat", "ClearCoatNormal"), ("anisotropy", "AnisotropyDirection")):
            if layer in shader.layers:
                lines.append(f"    layers.{direction} = pbrlab_tangent_to_world_normal(layers.{direction}, "
                             "f.normal, f.tangent);")
    lines.append("    vec4 c = pbrlab_shade_surface(pbrlabBase, f.position, f.view, f.normal PBRLAB_LAYERS_ARG);")
    return lines


def glue(shader: M.SurfaceShader, language: str) -> str:
    """What follows the shader's text: uniforms Unity declares, Input, lighting, pixel."""
    out = []
    for tex in sorted({tex for _, _, tex in shader.uv_members()}):
        if f"{tex}_ST" not in shader.declared:
            out.append(f"uniform vec4 {tex}_ST;  // Unity declares it for uv_{tex}: (tiling, offset)")
    cutoff = shader.pragma.cutoff_property
    if cutoff and cutoff not in shader.declared:
        out.append(f"uniform float {cutoff};  // #pragma surface alphatest:{cutoff}")
    for kind, name in custom_varyings(shader, language):
        if language == "hlsl":
            out.append(f"static {kind} pbrlab_custom_{name};  // set by main from v_custom_{name}")
        else:
            out.append(f"in {kind} v_custom_{name};\n#define pbrlab_custom_{name} v_custom_{name}")
    out.append(_input_fill(shader, language))
    layered = shader.pragma.model in M.LAYERED_MODELS
    if not layered:  # Unity's forward path over Lighting<Name> (a layered model: _layered_shading)
        out.append(f"#define PBRLAB_UNITY_OUTPUT {shader.output_type}")
        out.append(f"#define PBRLAB_UNITY_LIGHT(o, v, gi) {_light_call(shader)}")
        if shader.lighting.form in (M.FORM_GI_VIEW, M.FORM_GI):
            out.append(f"#define PBRLAB_UNITY_GI(o, data, gi) Lighting{shader.lighting.name}_GI(o, data, gi)")
        if "Emission" in shader.output_fields:
            out.append("#define PBRLAB_UNITY_EMISSION")
        out.append('#include "unity_shading.inc"')
    body = ["vec4 pbrlab_unity_pixel(PbrlabFragment f) {"]
    if shader.written_globals:  # each copy from its uniform, before the program runs
        body.append(copy_statements(shader.written_globals).rstrip("\n"))
    body.append("    Input IN = pbrlab_unity_input(f);")
    body += _zero_output(shader, language)
    body.append("    o.Normal = vec3(0.0, 0.0, 1.0);" if shader.writes_normal else "    o.Normal = f.normal;")
    body.append(f"    {shader.pragma.function}(IN, o);")
    if cutoff:
        body.append(f"    if (o.Alpha - {cutoff} < 0.0) discard;  // Unity: clip(o.Alpha - {cutoff})")
    if shader.writes_normal:
        body += ["    vec3 t = pbrlab_unity_tangent(f);",
                 "    vec3 b = pbrlab_unity_bitangent(f, t);",
                 "    o.Normal = normalize(vec3(dot(vec3(t.x, b.x, f.normal.x), o.Normal),",
                 "                              dot(vec3(t.y, b.y, f.normal.y), o.Normal),",
                 "                              dot(vec3(t.z, b.z, f.normal.z), o.Normal)));"]
    body += _layered_shading(shader) if layered else ["    vec4 c = pbrlab_unity_shade(o, f.position, f.view);"]
    if shader.pragma.finalcolor:
        body.append(f"    {shader.pragma.finalcolor}(IN, o, c);")
    body.append("    return vec4(pbrlab_target_radiance(c.rgb), pbrlab_output_alpha(c));")
    body.append("}")
    out.append("\n".join(body))
    return "\n".join(out) + "\n"


_ENTRY = {
    ("hlsl", "sphere"): """
uniform float4x4 u_view_proj;

void pbrlab_unity_sphere_pixel(float2 at, out float4 radiance, out float depth) {
    PbrlabFragment f;
    float3 d;
    f.position = pbrlab_sphere_hit(at, d, f.normal);
    f.view = -d;
    f.uv = pbr_equirect_uv(f.normal);
    f.tangent = pbrlab_sphere_tangent(f.uv);
    f.color = float4(1.0, 1.0, 1.0, 1.0);
    f.facing = 1.0;
    radiance = pbrlab_unity_pixel(f);
    float4 clip = mul(u_view_proj, float4(f.position, 1.0));
    depth = clamp(clip.z / clip.w * 0.5 + 0.5, 0.0, 1.0);
}

#ifdef PBRLAB_SAMPLES
void main(float4 position : SV_Position, out float4 radiance : SV_Target0, out float depth : SV_Depth,
          out uint coverage : SV_Coverage) {
    float2 at;
    coverage = uint(pbrlab_sphere_coverage(position.xy, at));
    pbrlab_unity_sphere_pixel(at, radiance, depth);
}
#else
void main(float4 position : SV_Position, out float4 radiance : SV_Target0, out float depth : SV_Depth) {
    pbrlab_unity_sphere_pixel(position.xy, radiance, depth);
}
#endif
""",
    ("glsl", "sphere"): """
uniform mat4 u_view_proj;
out vec4 out_radiance;

void main() {
    vec2 at = gl_FragCoord.xy;
#ifdef PBRLAB_SAMPLES
    gl_SampleMask[0] = pbrlab_sphere_coverage(gl_FragCoord.xy, at);
#endif
    PbrlabFragment f;
    vec3 d;
    f.position = pbrlab_sphere_hit(at, d, f.normal);
    f.view = -d;
    f.uv = pbr_equirect_uv(f.normal);
    f.tangent = pbrlab_sphere_tangent(f.uv);
    f.color = vec4(1.0, 1.0, 1.0, 1.0);
    f.facing = 1.0;
    out_radiance = pbrlab_unity_pixel(f);
    vec4 clipPos = u_view_proj * vec4(f.position, 1.0);
    gl_FragDepth = clamp(clipPos.z / clipPos.w * 0.5 + 0.5, 0.0, 1.0);
}
""",
    ("hlsl", "mesh"): """
float4 main(float4 position : SV_Position, bool front_facing : SV_IsFrontFace,
            float3 v_position : TEXCOORD0, float3 v_normal : TEXCOORD1,
            float2 v_uv : TEXCOORD2, float4 v_tangent : TEXCOORD3) : SV_Target0 {
    PbrlabFragment f;
    f.facing = front_facing ? 1.0 : -1.0;
    f.position = v_position;
    f.normal = normalize(v_normal);
    f.view = normalize(u_camera_position - v_position);
    f.uv = v_uv;
    f.tangent = v_tangent;
    f.color = float4(1.0, 1.0, 1.0, 1.0);
    return pbrlab_unity_pixel(f);
}
""",
    ("glsl", "mesh"): """
in vec3 v_position;
in vec3 v_normal;
in vec2 v_uv;
in vec4 v_tangent;
out vec4 out_radiance;

void main() {
    PbrlabFragment f;
    f.facing = gl_FrontFacing ? 1.0 : -1.0;
    f.position = v_position;
    f.normal = normalize(v_normal);
    f.view = normalize(u_camera_position - v_position);
    f.uv = v_uv;
    f.tangent = v_tangent;
    f.color = vec4(1.0, 1.0, 1.0, 1.0);
    out_radiance = pbrlab_unity_pixel(f);
}
""",
}


def _defines(defines: dict) -> str:
    return "\n".join(f"#define {k} {v}".rstrip() for k, v in sorted(defines.items()))


# The library's configuration for a Unity program: UnityLight (pbr_Light) with Unity's deprecated
# member ndotl, which older shaders assign and read (pbr/surface/lighting_standard.glsl); and
# UnpackNormal / UnpackScaleNormal as Unity compiles them for desktop, where UNITY_NO_DXT5nm is
# undefined (UnityCG.cginc's UnpackNormalmapRGorAG: x = r * a, y = g, z rebuilt), the branch that
# reads a normal map as the editor stores it there (pbr/unity/surface_standard.glsl,
# PBR_UNITY_NORMAL_MAP_ENCODING_DXT5NM; importers/unity/normal_maps.py uploads a map in that layout).
UNITY_LIBRARY_DEFINES = {"PBR_LIGHT_NDOTL": 1, "PBR_UNITY_NORMAL_MAP_ENCODING": 2}

# HLSL's arrays of arrays (``float w[2][3]``; the type pass keeps them, cg_types.array_suffix):
# GLSL 4.30's, which GLSL 3.30 takes with this extension (every Mesa driver has it).
ARRAYS_OF_ARRAYS = "#extension GL_ARB_arrays_of_arrays : enable"


def prelude(language: str, defines: dict, vertex_stage: bool) -> list[str]:
    """What comes before a Unity program in either stage: the harness's defines and scene
    shading, Unity's generated-code names, the Cg intrinsics (GLSL) and the pbr/unity/ library."""
    suffix = SUFFIX[language]
    head = ["#version 330 core", ARRAYS_OF_ARRAYS] if language == "glsl" else []
    stage = {"PBRLAB_UNITY_VERTEX_STAGE": 1, "PBR_UNITY_VERTEX_STAGE": 1} if vertex_stage else {}
    head += [_defines({**defines, "PBRLAB_UNITY_SURFACE": 1, **UNITY_LIBRARY_DEFINES, **stage})]
    if language == "glsl" and SAMPLES_DEFINE in defines:  # an antialiased sphere writes gl_SampleMask
        head.append("#extension GL_ARB_sample_shading : require")
    renamed, restored = _renamed_globals(defines)
    head += renamed
    head += [f'#include "scene_shading{suffix}"', '#include "unity_surface.inc"']
    head.append('#include "unity_compat/cg_compat.glsl"' if language == "glsl" else '#include "unity_hlsl_support.hlsl"')
    head += [f'#include "{name}{suffix}"' for name in LIBRARY_INCLUDES]
    return head + restored


def _renamed_globals(defines: dict) -> tuple:
    """(lines before the prelude's includes, lines after them): a prelude global the program
    declares with a type of its own is the prelude's under its own name there, and the
    program's is the only one of the name (user_definitions.prelude_renames)."""
    renames = prelude_renames(defines)
    return ([f"#define {name} {own}" for name, own in sorted(renames.items())],
            [f"#undef {name}" for name in sorted(renames)])


def fragment_source(shader: M.SurfaceShader, language: str, stem: str, program: str,
                    display: str, defines: dict) -> str:
    """The whole fragment program; ``program`` is the shader's text in ``language``
    (the CGPROGRAM for HLSL, its port for GLSL), ``display`` its file name in messages."""
    suffix = SUFFIX[language]
    head = ["#version 330 core", ARRAYS_OF_ARRAYS] if language == "glsl" else []
    renamed, restored = _renamed_globals(defines)
    head += [_defines({**defines, "PBRLAB_UNITY_SURFACE": 1, **UNITY_LIBRARY_DEFINES}), *renamed,
             f'#include "scene_shading{suffix}"',
             '#include "unity_surface.inc"']
    if language == "glsl":
        head.append('#include "unity_compat/cg_compat.glsl"')
    else:
        head.append('#include "unity_hlsl_support.hlsl"')
    head += [f'#include "{name}{suffix}"' for name in LIBRARY_INCLUDES] + restored
    head += layered_struct(shader)
    first = shader.program_line if language == "hlsl" else 1
    line = line_directive(first, display) if language == "hlsl" else f"#line {first}"
    entry = _ENTRY[(language, stem)]
    custom = custom_varyings(shader, language)
    if custom and language == "hlsl":  # the vertex stage's custom Input members
        params = "".join(f", {t} v_custom_{n} : TEXCOORD{4 + i}" for i, (t, n) in enumerate(custom))
        sets = "".join(f"    pbrlab_custom_{n} = v_custom_{n};\n" for _, n in custom)
        entry = entry.replace("float4 v_tangent : TEXCOORD3) : SV_Target0 {\n",
                              f"float4 v_tangent : TEXCOORD3{params}) : SV_Target0 {{\n{sets}")
    tail = glue(shader, language) + entry
    return "\n".join(head) + "\n" + line + "\n" + program + "\n" + tail


def custom_varyings(shader: M.SurfaceShader, language: str):
    """[(type in ``language``, member)] of the Input members a vertex: function writes."""
    if shader.vertex is None:
        return []
    members = list(shader.custom_members())
    members += [(t, n) for t, n in shader.input_members if shader.is_color(n)]  # from v.color
    return [(t if language == "hlsl" else port_code_types(t), n) for t, n in members]


def _vertex_value(shader: M.SurfaceShader, member: str) -> str:
    """What the vertex stage passes for an Input member: what vertex: wrote, or for `color`
    (unless written) the vertex colour v.color."""
    if shader.is_color(member) and member not in shader.vertex.writes_input:
        kind = next(t for t, n in shader.input_members if n == member)
        colour = _appdata_member(shader, "COLOR0")
        return fit(f"v.{colour}" if colour else "vec4(1.0, 1.0, 1.0, 1.0)", 4, component_count(kind) or 4, "glsl")
    return f"o.{member}"


def _appdata_member(shader: M.SurfaceShader, semantic: str):
    """The member of the vertex function's input struct with ``semantic`` (appdata_full's
    names when it takes one of Unity's structs), or None."""
    members = shader.vertex.appdata_members or UNITY_STRUCTS["appdata_full"]
    return next((n for t, n, s in members if canonical(s) == semantic), None)


def _appdata_lines(shader: M.SurfaceShader, language: str) -> list[str]:
    """Declare and fill the vertex function's input from the mesh, member by semantic."""
    v = shader.vertex
    kind = v.appdata if v.appdata_members else "appdata_full"
    members = v.appdata_members or UNITY_STRUCTS["appdata_full"]
    lines = [f"    {kind} v = ({kind})0;" if language == "hlsl" else f"    {kind} v;"]
    for mtype, name, semantic in members:
        n = component_count(mtype)
        value = _attribute(canonical(semantic), n, language) if semantic else None
        if value is None:
            value = _zero(mtype, language)
        if canonical(semantic) == "COLOR0":  # meshes here are white unless they carry colours
            value = "float4(1.0, 1.0, 1.0, 1.0)" if language == "hlsl" else "vec4(1.0, 1.0, 1.0, 1.0)"
            value = fit(value, 4, n, language)
        if value is not None:
            lines.append(f"    v.{name} = {value};")
    return lines


def _appdata_read(shader: M.SurfaceShader, language: str) -> dict:
    """Expressions of the moved vertex: position (float4), normal, tangent (float4), uv."""
    if not shader.vertex.appdata_members:
        return {"position": "v.vertex", "normal": "v.normal", "tangent": "v.tangent", "uv": "v.texcoord.xy"}
    found = {canonical(s): (t, n) for t, n, s in shader.vertex.appdata_members}
    out = {}
    for key, semantic, want in (("position", "POSITION", 4), ("normal", "NORMAL", 3), ("tangent", "TANGENT", 4),
                                ("uv", "TEXCOORD0", 2)):
        if semantic in found:
            t, n = found[semantic]
            out[key] = fit(f"v.{n}", component_count(t), want, language, 1.0 if key == "position" else 0.0)
        else:
            expr, have, w = _ATTRIBUTES[semantic]
            out[key] = fit(expr, have, want, language, w)
    return out


# The vertex function's ``out Input o``: Unity's UNITY_INITIALIZE_OUTPUT(Input, o) zero-fills it
# wherever Unity compiles through HLSL (every platform since Unity 5's HLSLcc), and the HLSL
# path starts it at (Input)0. GLSL leaves an ``out`` parameter undefined at entry and the macro
# is empty in GLSL (Unity's old GLSL targets), so a vertex function that reads a member before
# writing it (Tilt Brush's NeonPulse: o.color = TbVertToSrgb(o.color)) read garbage: in GLSL
# the parameter is ``inout`` and the caller zeroes every member first (_zero_input_lines).
_OUT_INPUT = re.compile(r"\bout(\s+Input\s+\w+\s*[,)])")


def input_starts_zero(program: str) -> str:
    """The GLSL port's text with ``out Input o`` parameters made ``inout`` (see above); the
    vertex stage (program._vertex_stage) applies it to the ported program it includes."""
    return _OUT_INPUT.sub(r"inout\1", program)


def _zero_input_lines(shader: M.SurfaceShader) -> str:
    lines = []
    for kind, name in shader.input_members:
        glsl_type = port_code_types(kind).strip()
        if re.fullmatch(r"(float|int|uint|bool|[biu]?vec[234]|mat[234](x[234])?)", glsl_type):
            lines.append(f"    o.{name} = {glsl_type}(0);")
    return "\n".join(lines)


def vertex_source(shader: M.SurfaceShader, language: str, program: str, display: str, defines: dict) -> str:
    """The vertex stage of a shader with a vertex: function: Unity's appdata_full from the
    mesh, the user's function, then world position, normal, tangent, UV and the custom
    Input members it wrote, as the mesh fragment program reads them."""
    suffix = SUFFIX[language]
    v = shader.vertex
    head = ["#version 330 core", ARRAYS_OF_ARRAYS] if language == "glsl" else []
    renamed, restored = _renamed_globals(defines)
    head += [_defines({**defines, "PBRLAB_UNITY_SURFACE": 1, **UNITY_LIBRARY_DEFINES, "PBRLAB_UNITY_VERTEX_STAGE": 1,
                       "PBR_UNITY_VERTEX_STAGE": 1}), *renamed,
             f'#include "scene_shading{suffix}"', '#include "unity_surface.inc"']
    head.append('#include "unity_compat/cg_compat.glsl"' if language == "glsl" else '#include "unity_hlsl_support.hlsl"')
    head += [f'#include "{name}{suffix}"' for name in LIBRARY_INCLUDES] + restored
    head += layered_struct(shader)
    first = shader.program_line if language == "hlsl" else 1
    line = line_directive(first, display) if language == "hlsl" else f"#line {first}"
    custom = custom_varyings(shader, language)
    call = f"{v.name}(v, o);" if v.input_param else f"{v.name}(v);"
    fill = "\n".join(_appdata_lines(shader, language))
    read = _appdata_read(shader, language)
    if language == "hlsl":
        outs = "".join(f", out {t} v_custom_{n} : TEXCOORD{4 + i}" for i, (t, n) in enumerate(custom))
        body = f"""
void main(float3 in_position : POSITION, float3 in_normal : NORMAL, float2 in_uv : TEXCOORD0,
          float4 in_tangent : TANGENT, float2 in_uv1 : TEXCOORD1, out float4 position : SV_Position, out float3 v_position : TEXCOORD0,
          out float3 v_normal : TEXCOORD1, out float2 v_uv : TEXCOORD2, out float4 v_tangent : TEXCOORD3{outs}) {{
{fill}
{copy_statements(shader.written_globals)}    Input o = (Input)0;
    {call}
    float4 world = mul(unity_ObjectToWorld, {read["position"]});
    v_position = world.xyz;
    v_normal = mul({read["normal"]}, (float3x3)unity_WorldToObject);
    float4 moved_tangent = {read["tangent"]};
    v_tangent = float4(mul((float3x3)unity_ObjectToWorld, moved_tangent.xyz), moved_tangent.w);
    v_uv = {read["uv"]};
""" + "".join(f"    v_custom_{n} = {_vertex_value(shader, n)};\n" for _, n in custom) + """    position = mul(unity_MatrixVP, world);
}
"""
    else:
        decls = "".join(f"out {t} v_custom_{n};\n" for t, n in custom)
        body = f"""
in vec3 in_position;
in vec3 in_normal;
in vec2 in_uv;
in vec4 in_tangent;
in vec2 in_uv1;
out vec3 v_position;
out vec3 v_normal;
out vec2 v_uv;
out vec4 v_tangent;
{decls}
void main() {{
{fill}
{copy_statements(shader.written_globals)}    Input o;
{_zero_input_lines(shader)}
    {call}
    vec4 world = unity_ObjectToWorld * {read["position"]};
    v_position = world.xyz;
    v_normal = {read["normal"]} * mat3(unity_WorldToObject);
    vec4 moved_tangent = {read["tangent"]};
    v_tangent = vec4(mat3(unity_ObjectToWorld) * moved_tangent.xyz, moved_tangent.w);
    v_uv = {read["uv"]};
""" + "".join(f"    v_custom_{n} = {_vertex_value(shader, n)};\n" for _, n in custom) + """    gl_Position = unity_MatrixVP * world;
}
"""
    return "\n".join(head) + "\n" + line + "\n" + program + "\n" + body
